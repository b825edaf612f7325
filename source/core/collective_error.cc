#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>

#include <chrono>
#include <climits>
#include <iostream>
#include <thread>
#include <vector>

namespace pneuma
{
  std::string
  agree_on_error(const MPI_Comm     comm,
                 const std::string &local_error,
                 const int          exit_code,
                 const double       timeout)
  {
    const int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    if (dealii::Utilities::MPI::n_mpi_processes(comm) == 1)
      return local_error;
    // The lowest failing rank, by a non-blocking reduction that the caller
    // can give up on.
    int         mine = local_error.empty() ? INT_MAX : rank, first = INT_MAX;
    MPI_Request request;
    MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm, &request);
    dealii::Timer clock;
    int           done = 0;
    while (true)
      {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done)
          break;
        if (clock.wall_time() > timeout)
          {
            std::cerr << "pneuma (rank " << rank << "): error in "
                      << (local_error.empty() ? "another rank" : local_error)
                      << "; the other ranks do not answer, aborting"
                      << std::endl;
            MPI_Abort(comm, exit_code);
          }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    if (first == INT_MAX)
      return "";
    // Every rank is here: the failing rank sends its message.
    int length = rank == first ? local_error.size() : 0;
    MPI_Bcast(&length, 1, MPI_INT, first, comm);
    std::vector<char> text(local_error.begin(), local_error.end());
    text.resize(length);
    MPI_Bcast(text.data(), length, MPI_CHAR, first, comm);
    return std::string(text.begin(), text.end());
  }

  void
  throw_if_any(const MPI_Comm comm, const std::string &local_error)
  {
    const std::string error = agree_on_error(comm, local_error, 1);
    if (!error.empty())
      throw InputError(error);
  }
} // namespace pneuma
