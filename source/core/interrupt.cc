#include <deal.II/base/mpi.h>

#include <pneuma/core/interrupt.h>

#include <csignal>

namespace pneuma
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    record_signal(int signal)
    {
      received = signal;
    }
  } // namespace

  void
  install_interrupt_handlers()
  {
    std::signal(SIGINT, record_signal);
    std::signal(SIGTERM, record_signal);
  }

  int
  interrupt_signal(const MPI_Comm comm)
  {
    return dealii::Utilities::MPI::max(static_cast<int>(received), comm);
  }
} // namespace pneuma
