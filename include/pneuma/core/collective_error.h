#pragma once

/**
 * @file
 * Input errors on MPI ranks, agreed on by all of them: a check that fails
 * on one rank only (a mesh-dependent check, a file that one rank cannot
 * write) must not leave the others waiting in a collective operation.
 */

#include <deal.II/base/mpi.h>

#include <string>

namespace pneuma
{
  /**
   * Every rank calls this with its own error message (empty: none) at the
   * end of a phase. Returns, on every rank, the message of the lowest rank
   * that failed, or an empty string if none did. A rank that does not come
   * within @p timeout seconds is stuck elsewhere (in a collective operation
   * the failing rank left): the waiting rank then prints its message and
   * calls MPI_Abort with @p exit_code, so no rank hangs.
   */
  std::string
  agree_on_error(const MPI_Comm     comm,
                 const std::string &local_error,
                 const int          exit_code,
                 const double       timeout = 60.);

  /**
   * Collective check: every rank calls this with its own finding
   * ("parameter: what", or empty); if any rank found something, every rank
   * throws the same InputError (the lowest rank's message).
   */
  void
  throw_if_any(const MPI_Comm comm, const std::string &local_error);
} // namespace pneuma
