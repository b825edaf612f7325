#pragma once

/**
 * @file
 * Threads per MPI rank (issue 17). MUMPS's dense kernels run in OpenBLAS,
 * whose threads spin while they wait: two ranks with two BLAS threads
 * each on two cores spend their time yielding to each other. The BLAS
 * (and deal.II's TBB) thread count of each rank is therefore set so that
 * ranks per node x threads never exceed the cores the process may use,
 * unless OPENBLAS_NUM_THREADS or OMP_NUM_THREADS says otherwise.
 */

#include <mpi.h>

namespace pneuma
{
  /// Set the thread counts of this rank as above; returns the BLAS
  /// thread count in force (0 if the BLAS offers no control).
  unsigned int
  set_thread_counts(const MPI_Comm comm);
} // namespace pneuma
