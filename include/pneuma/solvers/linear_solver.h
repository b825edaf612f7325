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

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

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

      LinearSolver();
      ~LinearSolver();

      /// Forget the symbolic factorization (call after the sparsity changes).
      void
      reset();

      /**
       * Factorize @p A (direct: numeric factorization, reusing the symbolic
       * one while the matrix object is the same; amg: build the
       * preconditioner). Every solve() until the next call reuses it, so a
       * bordered system costs one factorization and a few substitutions.
       */
      void
      factorize(const LA::SparseMatrix &A);

      /**
       * Solve A x = b with the factorization of the last factorize(A);
       * returns the number of Krylov iterations (0 for the direct solver).
       * Throws SolverControl::NoConvergence on failure.
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
      std::string                    ordering;
      // Direct solver state: the symbolic factorization (fill-reducing
      // ordering) is computed once per matrix and reused by every Newton
      // iteration; only the numeric factorization is redone.
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    direct;
      const void                           *factored_matrix = nullptr;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    };
  } // namespace solvers
} // namespace pneuma
