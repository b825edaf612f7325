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
 * (a bad-input run: 0.98 s -> 0.53 s on the development machine). Such
 * singletons share one session directory, so nothing that puts a file
 * there is loaded: no shared-memory transport, no `sm` shared file
 * pointer for MPI-IO (a checkpoint of two runs side by side failed with
 * it). Every
 * value is only a default: a variable the user set (`OMPI_MCA_*`) wins,
 * and nothing is changed when a launcher (mpirun, srun, a PMI) started the
 * process.
 */

namespace pneuma
{
  /// Call before MPI_Init (deal.II's MPI_InitFinalize).
  void
  prepare_mpi_start();
} // namespace pneuma
