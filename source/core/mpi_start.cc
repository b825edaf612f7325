#include <pneuma/core/mpi_start.h>

#include <cstdlib>
#include <initializer_list>

namespace pneuma
{
  void
  prepare_mpi_start()
  {
    // A launcher leaves one of these; a singleton has none.
    for (const char *launched : {"OMPI_COMM_WORLD_SIZE",
                                 "OMPI_UNIVERSE_SIZE",
                                 "PMIX_RANK",
                                 "PMI_RANK",
                                 "PMI_SIZE",
                                 "SLURM_PROCID"})
      if (std::getenv(launched) != nullptr)
        return;
    // setenv with overwrite = 0: the user's own settings stay.
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    // Isolated singletons share one session directory (job 0/1): the MPI-IO
    // shared file pointer's "sm" component, which puts a file there, failed
    // when two runs started and ended side by side (a checkpoint's mesh).
    setenv("OMPI_MCA_sharedfp", "^sm", 0);
  }
} // namespace pneuma
