#pragma once

/**
 * @file
 * The linear solver of each Newton step: a parallel direct solver (MUMPS
 * through Trilinos Amesos, the default) or AMG-preconditioned GMRES
 * (Trilinos ML) for large meshes.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <pneuma/core/linear_algebra.h>

#include <string>
#include <vector>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    /// "Linear solver" subsection and the solve itself.
    class LinearSolver
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Near-null space for AMG: one entry per displacement component.
      void
      set_constant_modes(const std::vector<std::vector<bool>> &modes);

      /**
       * Solve A x = b; returns the number of Krylov iterations (0 for the
       * direct solver). Throws SolverControl::NoConvergence on failure.
       */
      unsigned int
      solve(const LA::SparseMatrix &A, LA::Vector &x, const LA::Vector &b);

      /// "direct" or "amg".
      const std::string &
      type() const
      {
        return solver_type;
      }

    private:
      std::string                    solver_type, direct_package;
      double                         relative_tolerance = 1e-10;
      unsigned int                   max_iterations     = 1000;
      std::vector<std::vector<bool>> constant_modes;
    };
  } // namespace solvers
} // namespace pneuma
