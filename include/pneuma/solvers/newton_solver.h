#pragma once

/**
 * @file
 * Newton-Raphson for one load step (step-44 style), with a backtracking
 * line search and a Levenberg-Marquardt safeguard.
 *
 * A step is accepted when it reduces the residual norm (Armijo). When pure
 * Newton fails (a flat, unstressed membrane has no out-of-plane stiffness),
 * the step continues in pseudo time: a sequence of implicit steps
 * \f$r(u_{k+1}) + s_k L\,(u_{k+1} - u_k) = 0\f$ with the vector surface
 * Laplacian \f$L_{ij} = \int \nabla_S N_i\cdot\nabla_S N_j\,dA\f$ (the
 * geometric stiffness of a unit isotropic prestress), scaled by
 * \f$\bar K/\bar L\f$. Each is well posed; s shrinks by 4 after each
 * success and grows by 4 after a failure. When |r| has dropped, pure Newton
 * finishes the step: the regularisation is gone at convergence, so the
 * converged state is the exact equilibrium and the final rate quadratic.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/solvers/bordered_vector.h>

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
      /// Residual at @p u (owned field, border of chamber unknowns), and
      /// the tangent it keeps.
      virtual void
      assemble(const BorderedVector &u, BorderedVector &residual) = 0;
      /// Solve J du = rhs with the last assembled Jacobian J, its field
      /// block shifted to K + shift L.
      virtual void
      solve_linear(const double          shift,
                   const BorderedVector &rhs,
                   BorderedVector       &du) = 0;
      /// The scale mean(diag K)/mean(diag L) that makes the shift
      /// dimensionless.
      virtual double
      shift_scale() = 0;
      /// y = L x with the regularisation matrix L (zero on the border).
      virtual void
      laplacian_vmult(const BorderedVector &x, BorderedVector &y) = 0;
      /// Norm of the external load vector, for the residual reference.
      virtual double
      load_norm() = 0;
      /// Forcing term of an inexact Newton step: the linear solve may stop
      /// at |J du - rhs| <= eta |rhs| (iterative solves only).
      virtual void
      set_linear_tolerance(const double eta)
      {
        (void)eta;
      }
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

      /**
       * Iterate from @p u (owned) to equilibrium; @p u holds the result.
       * The pseudo-time continuation is used only if
       * @p allow_continuation (the step starts from the unstressed state);
       * elsewhere a failed Newton step is left to the load-step cut-back, so
       * that no spurious branch (e.g. an everted sphere past a limit point)
       * is picked up.
       */
      NewtonResult
      solve(NonlinearProblem         &problem,
            BorderedVector           &u,
            const ConditionalOStream &out,
            const bool                allow_continuation) const;

      unsigned int
      max_iterations() const
      {
        return max_iter;
      }

      /// The first continuation shift relative to NonlinearProblem::
      /// shift_scale().
      double
      regularisation_factor() const
      {
        return shift_factor;
      }

    private:
      /// Newton on r(u) + shift L (u - u_anchor) = 0 to |r_s| <= tol r_ref.
      bool
      iterate(NonlinearProblem         &problem,
              BorderedVector           &u,
              const double              shift,
              const BorderedVector     &u_anchor,
              const unsigned int        max_iterations,
              const double              tolerance,
              const double              r_ref,
              const ConditionalOStream &out,
              NewtonResult             &result) const;

      unsigned int max_iter           = 25;
      double       residual_tolerance = 1e-8;
      double       update_tolerance   = 1e-8;
      double       shift_factor       = 1e-2;
      unsigned int max_line_search    = 6;
      unsigned int watchdog_steps     = 3;
      bool         line_search        = true;
      bool         print_table        = true;
    };
  } // namespace solvers
} // namespace pneuma
