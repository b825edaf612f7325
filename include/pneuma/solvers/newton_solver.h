#pragma once

/**
 * @file
 * Newton-Raphson for one load step (step-44 style), with a backtracking
 * line search and a Levenberg-Marquardt safeguard.
 *
 * A step is accepted when it reduces the residual norm (Armijo). When the
 * full Newton step and its backtracking fail, the iteration matrix is
 * regularised, \f$(K + s\,L)\,\Delta u = -r\f$, with the vector surface
 * Laplacian \f$L_{ij} = \int \nabla_S N_i\cdot\nabla_S N_j\,dA\f$ (the
 * geometric stiffness of a unit isotropic prestress) scaled by
 * \f$\bar K/\bar L\f$; s grows by 4 after each rejected step and shrinks by
 * 10 after each accepted one, down to zero. Only the iteration matrix
 * changes, never the residual: the converged state is the exact
 * equilibrium and the final iterations are pure Newton, so the rate stays
 * quadratic. This lets a flat, unstressed membrane (no out-of-plane
 * stiffness) take its first steps.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/linear_algebra.h>

#include <vector>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    /// What Newton needs from the discrete problem.
    class NonlinearProblem
    {
    public:
      virtual ~NonlinearProblem() = default;
      /// Residual at @p u (owned vector), and the tangent it keeps.
      virtual void
      assemble(const LA::Vector &u, LA::Vector &residual) = 0;
      /// Solve (K + shift L) du = rhs with the last assembled tangent K.
      virtual void
      solve_linear(const double shift, const LA::Vector &rhs, LA::Vector &du) = 0;
      /// The scale mean(diag K)/mean(diag L) that makes the shift
      /// dimensionless.
      virtual double
      shift_scale() = 0;
      /// Norm of the external load vector, for the residual reference.
      virtual double
      load_norm() = 0;
    };

    /// Convergence history of one Newton solve.
    struct NewtonResult
    {
      bool                converged  = false;
      unsigned int        iterations = 0;
      std::vector<double> residual_history;
      std::string         failure_reason;
    };

    /// "Newton" subsection and the iteration.
    class NewtonSolver
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Iterate from @p u (owned) to equilibrium; @p u holds the result.
      NewtonResult
      solve(NonlinearProblem &       problem,
            LA::Vector &             u,
            const ConditionalOStream &out) const;

      unsigned int
      max_iterations() const
      {
        return max_iter;
      }

    private:
      unsigned int max_iter             = 25;
      double       residual_tolerance   = 1e-9;
      double       update_tolerance     = 1e-8;
      double       shift_factor         = 1e-2;
      unsigned int max_line_search      = 6;
      bool         line_search          = true;
      bool         print_table          = true;
    };
  } // namespace solvers
} // namespace pneuma
