#pragma once

/**
 * @file
 * A clean stop on SIGINT and SIGTERM (doc/user-guide.md "Exit codes"): the
 * handler only records the signal; the solution strategy asks at safe
 * points (each Newton iteration, each step), all ranks together, and then
 * stops with the last converged state written and the exit code
 * 128 + signal (130 for SIGINT, 143 for SIGTERM).
 */

#include <deal.II/base/mpi.h>

namespace pneuma
{
  /// Record SIGINT and SIGTERM from now on (the main program calls it).
  void
  install_interrupt_handlers();

  /// The signal received on any rank so far (0: none); collective.
  int
  interrupt_signal(const MPI_Comm comm);
} // namespace pneuma
