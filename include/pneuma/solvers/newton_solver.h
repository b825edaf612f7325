#pragma once

/**
 * @file
 * Newton-Raphson for one load step in the shape of step-44: one loop that
 * assembles, tests convergence, solves and updates, with three small
 * policies beside it (doc/theory.md "Newton"):
 *
 * - **LineSearch**: backtracking on the residual norm with the Armijo
 *   condition \f$|r(u+\alpha\,\delta u)| \le (1 - c\,\alpha)|r(u)|\f$,
 *   halving \f$\alpha\f$.
 * - **Watchdog** (non-monotone acceptance, Chamberlain et al. 1982): a
 *   full step that raises |r| is still taken from a saved state; if |r|
 *   has not dropped below the saved value within a few more iterations,
 *   the saved state is restored and the line search backtracks there.
 * - **Continuation** in pseudo time for a start without stiffness (a flat,
 *   unstressed membrane): implicit steps
 *   \f$r(u_{k+1}) + s_k L\,(u_{k+1} - u_k) = 0\f$ with the vector surface
 *   Laplacian \f$L\f$ (the geometric stiffness of a unit prestress), scaled
 *   by \f$\bar K/\bar L\f$. \f$s\f$ halves after each successful implicit
 *   step and triples after a failed one; once |r| has dropped by
 *   `switch_ratio`, pure Newton finishes the step. The regularisation is
 *   gone at convergence: the converged state is the exact equilibrium and
 *   the final rate is quadratic.
 *
 * - **Stiffened start** from an unstressed state: the first solve uses
 *   \f$K + s L\f$ with the mean membrane force \f$s\f$ that the virial of
 *   the loads predicts (NonlinearProblem::start_prestress), instead of
 *   the bare linear stiffness whose solution kinks the surface where a
 *   membrane meets a support (the nonlinear boundary layer is thinner
 *   than the cells). Newton goes on from there; the start is kept only if
 *   it lowers |r|.
 *
 * Convergence is declared by one of four named tests (NewtonResult::
 * convergence_test): "residual" (|r| <= tol |r_ref|), "update at the
 * round-off floor" (|du| <= tol_u |u| while |r| is within `floor_update`
 * of the tolerance), "update predicted below tolerance" (the same, with
 * the next update predicted from the last two full steps of a quadratic
 * iteration, |du_{k+1}| ~ |du_k|^3/|du_{k-1}|^2, so that no factorization
 * is spent to confirm it) or "no descent at the round-off floor" (no step
 * reduces |r| while it is within `floor_descent` of the tolerance). The
 * reference is \f$|r_{ref}| = \max(|r_0|, |f|)\f$ with the problem's force
 * scale |f|. The table prints, per iteration, the total residual and each block
 * (membrane, cables, chambers, ...) normalized by its value at the first
 * iteration.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/solvers/bordered_vector.h>

#include <functional>
#include <string>
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
      /// Residual at @p u (owned field, border unknowns), and the tangent
      /// it keeps for solve_linear().
      virtual void
      assemble(const BorderedVector &u, BorderedVector &residual) = 0;
      /// Solve J du = rhs with the last assembled Jacobian J, its field
      /// block shifted to K + shift L.
      virtual void
      solve_linear(const double          shift,
                   const BorderedVector &rhs,
                   BorderedVector       &du) = 0;
      /// The first continuation shift for a shift @p factor relative to
      /// the scale mean(diag K)/mean(diag L) of the last assembled K.
      virtual double
      initial_shift(const double factor) = 0;
      /// y = L x with the regularisation matrix L (zero on the border).
      virtual void
      laplacian_vmult(const BorderedVector &x, BorderedVector &y) = 0;
      /**
       * The isotropic membrane force s (N/m) of the stiffened start: the
       * first solve from an unstressed state uses K + s L. 0: none.
       */
      virtual double
      start_prestress()
      {
        return 0.;
      }
      /// Force scale of the loads, for the residual reference.
      virtual double
      load_norm() = 0;
      /// Forcing term of an inexact Newton step: the linear solve may stop
      /// at |J du - rhs| <= eta |rhs| (iterative solves only).
      virtual void
      set_linear_tolerance(const double eta)
      {
        (void)eta;
      }
      /// True if the run was asked to stop (a signal); all ranks agree.
      virtual bool
      interrupted()
      {
        return false;
      }
      /// Names of the residual blocks (membrane, cables, chambers, ...).
      virtual std::vector<std::string>
      block_names() const
      {
        return {};
      }
      /// The l2 norm of each block of @p r, in the order of block_names().
      virtual std::vector<double>
      block_norms(const BorderedVector &r) const
      {
        (void)r;
        return {};
      }
    };

    /// Why a Newton solve, or the step around it, failed.
    enum class NewtonFailure
    {
      none,
      /// The residual is NaN or inf.
      not_finite,
      /// SIGINT or SIGTERM.
      interrupted,
      /// The iteration limit.
      no_convergence,
      /// The factorization or the solve failed.
      linear_solver,
      /// No step length reduced the merit function.
      line_search,
      /// Converged, but a subsystem rejects the state (check_state()).
      state_rejected,
      /// Converged, but back along the path (arc length).
      turned_back,
      /// The step cannot begin (begin_step(): e.g. a chamber drained).
      impossible_step
    };

    /// Convergence history of one Newton solve.
    struct NewtonResult
    {
      bool         converged  = false;
      unsigned int iterations = 0;
      /// |r| after each accepted iteration of the final pure Newton phase.
      std::vector<double> residual_history;
      /// Why it failed (NewtonFailure::none if it did not), and the
      /// reason in words with its numbers, for the log.
      NewtonFailure failure = NewtonFailure::none;
      std::string   failure_reason;

      /// Record a failure.
      void
      fail(const NewtonFailure why, const std::string &reason)
      {
        failure        = why;
        failure_reason = reason;
      }
      /// The test that declared convergence (empty if none did).
      std::string convergence_test;
      /// |r_ref|, the scale of the residual tolerance.
      double reference = 0.;
    };

    /// "Newton" subsection and the iteration.
    class NewtonSolver
    {
    public:
      /// Declare the entries, bound to the members (their initial values
      /// are the defaults).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Iterate from @p u (owned) to equilibrium; @p u holds the result.
       * The continuation is used only if @p allow_continuation (the step
       * starts from the unstressed state); elsewhere a failed Newton step
       * is left to the load-step cut-back, so that no spurious branch (an
       * everted sphere past a limit point) is picked up.
       * @p reference: a lower bound of |r_ref| (a step that starts from a
       * predicted state measures its tolerance against the residual the
       * step's loads cause at the last converged state, not against the
       * predictor's smaller one).
       */
      NewtonResult
      solve(NonlinearProblem         &problem,
            BorderedVector           &u,
            const ConditionalOStream &out,
            const bool                allow_continuation,
            const double              reference = 0.) const;

      unsigned int
      max_iterations() const
      {
        return max_iter;
      }

      /// The forcing term eta of an inexact step at |r|/|r_ref| = @p ratio:
      /// eta = min(max_forcing, forcing_ratio |r|/|r_ref|), so that the
      /// linear error stays below the quadratic term of the Newton step.
      static double
      forcing_term(const double ratio);

    private:
      /// One Newton solve of r(u) + shift L (u - u_anchor) = 0.
      struct Phase
      {
        double         shift = 0.;
        BorderedVector anchor;
        unsigned int   max_iterations = 0;
        /// Converged at |r_s| <= tolerance |r_ref|.
        double tolerance = 0.;
      };

      /// The state of one phase's iteration (newton_solver.cc).
      struct Iteration;
      /// What a step of the iteration decided.
      enum class Outcome
      {
        go_on,
        converged,
        failed
      };

      /// Newton iterations of @p phase from @p u, in named steps:
      /// test_state(), newton_direction(), search_line(), update(). @p
      /// assembled: the residual at @p u that the problem has just assembled
      /// (with its tangent), so that the first iteration does not assemble
      /// again (in a shifted phase @p u must be its anchor, where the shift
      /// term vanishes).
      bool
      iterate(NonlinearProblem         &problem,
              BorderedVector           &u,
              const Phase              &phase,
              const double              r_ref,
              const ConditionalOStream &out,
              NewtonResult             &result,
              const BorderedVector     *assembled = nullptr) const;

      /// The residual of the phase at @p x into @p r (with the shift term
      /// s L (x - anchor)); returns |r|.
      double
      evaluate(NonlinearProblem     &problem,
               Iteration            &state,
               const BorderedVector &x,
               BorderedVector       &r) const;

      /// The convergence and failure tests of the state at iteration
      /// @p it: the residual, a non-finite residual, an interrupt, the
      /// iteration limit.
      Outcome
      test_state(NonlinearProblem &problem,
                 const Iteration  &state,
                 const unsigned    it,
                 NewtonResult     &result) const;

      /// The Newton direction (one linear solve), or after a failed watch
      /// the saved one; the test "update at the round-off floor".
      Outcome
      newton_direction(NonlinearProblem         &problem,
                       const BorderedVector     &u,
                       Iteration                &state,
                       const ConditionalOStream &out,
                       NewtonResult             &result) const;

      /// Armijo backtracking along the direction from @p u, with the
      /// watchdog; the step in state.step.
      void
      search_line(NonlinearProblem     &problem,
                  const BorderedVector &u,
                  Iteration            &state) const;

      /// The row of the convergence table.
      void
      print_iteration(NonlinearProblem         &problem,
                      const Iteration          &state,
                      const ConditionalOStream &out,
                      const NewtonResult       &result) const;

      /// Accept the step (the test "update predicted below tolerance"),
      /// or restore the watchdog's saved state.
      Outcome
      update(BorderedVector           &u,
             Iteration                &state,
             const ConditionalOStream &out,
             NewtonResult             &result) const;

      /// The stiffened start: u and r (assembled at u) advance by the
      /// solve with K + s L if that lowers |r|.
      void
      stiffened_first_iteration(NonlinearProblem         &problem,
                                BorderedVector           &u,
                                BorderedVector           &r,
                                const double              r_ref,
                                const ConditionalOStream &out,
                                NewtonResult             &result) const;

      /// Where the regularised iteration stands: its first shift (0: not
      /// started), its current one, the |r|/|r_ref| at which it hands
      /// over to pure Newton, and the iterations it has spent (its budget
      /// is 4 Maximum iterations; the pure Newton phases have their own).
      struct ContinuationPath
      {
        double       initial = 0., shift = 0., switch_ratio = 0.;
        unsigned int spent = 0;
      };

      /// The regularised iteration from @p u along @p path (from its
      /// start if it has none; @p fresh: @p r and the tangent last
      /// assembled are those at @p u); leaves in @p r the residual at the
      /// final @p u. True if the tangent last assembled is the one at
      /// @p u too (the next phase need not assemble again).
      bool
      continuation(NonlinearProblem         &problem,
                   BorderedVector           &u,
                   BorderedVector           &r,
                   const double              r_ref,
                   const ConditionalOStream &out,
                   NewtonResult             &result,
                   ContinuationPath         &path,
                   bool                      fresh = true) const;

      /// After a failed pure Newton phase: whether the continuation can go
      /// on (budget, shift and hand-over left), and if so @p path with a
      /// smaller shift and a tighter hand-over.
      bool
      back_to_continuation(NonlinearProblem &problem,
                           ContinuationPath &path) const;

      void
      print_header(NonlinearProblem         &problem,
                   const ConditionalOStream &out) const;

      unsigned int max_iter           = 25;
      double       residual_tolerance = 1e-8;
      double       update_tolerance   = 1e-8;
      double       shift_factor       = 1e-2;
      unsigned int max_line_search    = 6;
      unsigned int watchdog_steps     = 3;
      bool         line_search        = true;
      bool         stiffened_start    = true;
      bool         print_table        = true;
    };
  } // namespace solvers
} // namespace pneuma
