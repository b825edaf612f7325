#pragma once

/**
 * @file
 * A lighter MPI start for a run of one rank started without a launcher.
 *
 * Open MPI 4 starts such a "singleton" by spawning a supporting daemon
 * (orted) and by loading every point-to-point transport it finds (the
 * matching-transport layer `cm` pulls in libfabric and PSM). A run of one
 * rank talks to no other process, so neither is needed: with the daemon
 * left out (`ess_singleton_isolated`), the `ob1` layer and the `self`
 * transport, MPI_Init of Debian 12's Open MPI 4.1 takes about 0.45 s less
 * (a bad-input run: 0.98 s -> 0.53 s on the development machine).
 *
 * Isolated singletons all name their session directory alike
 * (`ompi.<host>.<uid>/jf.0/1/0` under `orte_tmpdir_base`), and each removes
 * it at MPI_Finalize: a run that ended while another started removed the
 * directory the other had just made, whose MPI_Init then failed ("A call
 * to mkdir was unable to create the desired directory"; 3 of 600 runs of
 * six side by side, once in CI's fuzz test). So every singleton gets a
 * private base, a fresh `pneuma-mpi-XXXXXX` under `$TMPDIR` (or /tmp),
 * removed when the run ends (an MPI_Abort or a kill leaves it, as Open MPI
 * leaves its own session directory then). For the same reason nothing
 * that shares files across runs is loaded: no `sm` shared file pointer for
 * MPI-IO. Every value is only a default: a variable the user set
 * (`OMPI_MCA_*`) wins, and nothing is changed when a launcher (mpirun,
 * srun, a PMI) started the process.
 */

#include <string>

namespace pneuma
{
  /**
   * Prepares MPI_Init in its constructor and removes the private session
   * directory in its destructor. Construct it before deal.II's
   * MPI_InitFinalize, so that it is destroyed after MPI_Finalize.
   */
  class MpiStart
  {
  public:
    MpiStart();
    ~MpiStart();
    MpiStart(const MpiStart &) = delete;
    MpiStart &
    operator=(const MpiStart &) = delete;

  private:
    /// The private session directory base this process made, or empty.
    std::string session_base;
  };
} // namespace pneuma
