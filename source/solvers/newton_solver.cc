#include <deal.II/base/utilities.h>

#include <pneuma/solvers/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <regex>

namespace pneuma
{
  namespace solvers
  {
    namespace
    {
      /// Armijo constant c of the sufficient decrease (1 - c alpha)|r|: any
      /// decrease proportional to the step is accepted (Nocedal & Wright).
      constexpr double armijo = 1e-4;
      /// Step length reduction of each backtracking step.
      constexpr double backtrack = 0.5;
      /// "update at the round-off floor": |r| may be this much above the
      /// tolerance when the update has vanished (stiff plates beside a soft
      /// membrane: |r| cannot drop further, yet u no longer changes).
      constexpr double floor_update = 1e4;
      /// "no descent at the round-off floor": no step reduces |r| while it
      /// is within this factor of the tolerance (a penalty beside a
      /// prestressed cable).
      constexpr double floor_descent = 1e2;
      /// The predicted-update test trusts the quadratic model only once
      /// the updates contract at least this fast.
      constexpr double contraction = 0.1;
      /// Inexact Newton forcing: eta = min(max_forcing, forcing_ratio
      /// |r|/|r_ref|).
      constexpr double max_forcing = 1e-3, forcing_ratio = 1e-2;
      /// The watchdog does not take a full step that raises |r| more than
      /// this factor: such a state (a residual of 1e78 from a contact
      /// point thrown through the membrane) is no iterate to go on from.
      constexpr double max_watched_growth = 1e6;

      /// The continuation schedule (doc/theory.md "Newton").
      struct ContinuationSchedule
      {
        /// Implicit steps are solved to |r_s| <= inner_tolerance |r_ref| in
        /// at most inner_iterations; they need not be accurate.
        static constexpr double       inner_tolerance  = 1e-3;
        static constexpr unsigned int inner_iterations = 6;
        /// The shift after a successful / failed implicit step.
        static constexpr double shrink = 0.5, grow = 3.;
        /// Pure Newton takes over once |r| <= switch_ratio |r_ref|, or the
        /// shift has fallen to min_shift times its start.
        static constexpr double switch_ratio = 1e-2, min_shift = 1e-6;
        /// After a failed pure Newton phase the continuation goes on to a
        /// hand-over tighter by this factor, down to min_switch_ratio.
        static constexpr double tighter = 1e-2, min_switch_ratio = 1e-9;
        /// Failures that cost no iteration (the linear solver) stop it.
        static constexpr unsigned int max_failures = 20;
        /// Iteration budget, in units of Newton/Maximum iterations.
        static constexpr unsigned int budget = 4;
      };

      /**
       * The watchdog: a full step that raises |r| is taken from a saved
       * state, and the watch runs for `steps` more iterations. Progress
       * below the saved |r| ends it; otherwise the saved state comes back
       * and the line search must backtrack from it (the watch is barred
       * until a step is accepted normally). The direction from the saved
       * state is saved with it: the backtracking resumes along it at half
       * the step, without solving for it again (its full step is the one
       * the watch took, which failed the Armijo test).
       */
      class Watchdog
      {
      public:
        explicit Watchdog(const unsigned int steps)
          : steps(steps)
        {
        }

        /// May the rejected full step @p trial_norm from |r| = @p r_norm
        /// be taken anyway? Never if it is not finite or absurd.
        bool
        may_take(const double trial_norm, const double r_norm) const
        {
          return steps > 0 && !barred && std::isfinite(trial_norm)
                 && trial_norm <= max_watched_growth * r_norm;
        }

        /// Take it: save the state, its |r| and the direction @p du from
        /// it, unless a watch is already on.
        void
        start(const BorderedVector &u,
              const double          r_norm,
              const BorderedVector &du)
        {
          if (left > 0)
            return;
          saved           = u;
          saved_norm      = r_norm;
          saved_direction = du;
          left            = steps + 1;
        }

        /**
         * After a step to |r| = @p r_norm: true if the watch failed, and
         * @p u and its norm must be restored from the saved state.
         */
        bool
        failed(const double r_norm)
        {
          if (left == 0)
            {
              barred = false;
              return false;
            }
          if (r_norm <= (1. - armijo) * saved_norm)
            left = 0; // progress: the watch ends
          else if (--left == 0)
            {
              barred = true;
              return true;
            }
          return false;
        }

        const BorderedVector &
        saved_state() const
        {
          return saved;
        }
        double
        saved_residual_norm() const
        {
          return saved_norm;
        }
        const BorderedVector &
        saved_step() const
        {
          return saved_direction;
        }

      private:
        unsigned int   steps, left = 0;
        bool           barred     = false;
        double         saved_norm = 0.;
        BorderedVector saved, saved_direction;
      };

      /// Outcome of the line search along one Newton direction.
      struct Step
      {
        bool   accepted = false, watched = false;
        double alpha = 1., norm = 0.;
      };
    } // namespace

    double
    NewtonSolver::forcing_term(const double ratio)
    {
      return std::min(max_forcing, forcing_ratio * ratio);
    }

    void
    NewtonSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      prm.add_parameter("Maximum iterations",
                        max_iter,
                        "Newton iterations per load step before the step is "
                        "cut back.",
                        Patterns::Integer(1, 1000));
      prm.add_parameter("Residual tolerance",
                        residual_tolerance,
                        "Converged when |r| <= tol * max(|r_0|, |f|), f the "
                        "force scale of the loads (test 'residual').",
                        Patterns::Double(1e-16, 1.));
      prm.add_parameter("Update tolerance",
                        update_tolerance,
                        "Also converged when an update has |du| <= tol |u| "
                        "while |r| is within 1e4 of the residual tolerance "
                        "(test 'update at the round-off floor' of stiff "
                        "parts).",
                        Patterns::Double(1e-16, 1.));
      prm.add_parameter("Line search",
                        line_search,
                        "Backtrack when a full step does not reduce |r| "
                        "(Armijo).");
      prm.add_parameter("Maximum line search steps",
                        max_line_search,
                        "Halvings of the step length at most.",
                        Patterns::Integer(0, 30));
      prm.add_parameter("Watchdog steps",
                        watchdog_steps,
                        "A full Newton step that raises |r| is still taken, "
                        "and the iteration goes on for up to this many "
                        "steps; if |r| has not dropped below its value "
                        "before, that state is restored and the line "
                        "search backtracks from it (0: backtrack at once). "
                        "A step to a non-finite residual or one raising it "
                        "more than 1e6-fold is never taken.",
                        Patterns::Integer(0, 20));
      prm.add_parameter("Stiffened start",
                        stiffened_start,
                        "From an unstressed state, solve the first "
                        "iteration with the geometric stiffness of the mean "
                        "membrane force that the virial of the loads "
                        "predicts, so that the linear solution does not "
                        "kink the surface at supports (fewer iterations on "
                        "fine meshes). Kept only if it lowers |r|.");
      prm.add_parameter("Regularisation factor",
                        shift_factor,
                        "First continuation shift, relative to "
                        "mean(diag K)/mean(diag L), used when Newton fails "
                        "from the unstressed state (0: never). Changes the "
                        "iteration only, not the equilibrium.",
                        Patterns::Double(0.));
      prm.add_parameter("Print convergence table",
                        print_table,
                        "Print one line per Newton iteration.");
      prm.leave_subsection();
    }

    void
    NewtonSolver::parse_parameters(ParameterHandler &)
    {
      // Every entry is bound by declare_parameters().
    }

    void
    NewtonSolver::print_header(NonlinearProblem         &problem,
                               const ConditionalOStream &out) const
    {
      if (!print_table)
        return;
      out << "      it  |r|/|r_ref|";
      for (const auto &name : problem.block_names())
        out << std::setw(11) << name;
      out << "   |du|/|u|    shift     step\n";
    }

    /**
     * The state of one phase's iteration: its vectors (allocated once),
     * |r| at the iterate, the Newton direction, the line search's step,
     * the watchdog and what the convergence tests remember.
     */
    struct NewtonSolver::Iteration
    {
      Iteration(const BorderedVector &u,
                const Phase          &phase,
                const double          r_ref,
                const unsigned int    watchdog_steps)
        : phase(phase)
        , r_ref(r_ref)
        , tolerance(phase.tolerance * r_ref)
        , pure(phase.shift == 0.)
        , residual(u)
        , trial(u)
        , du(u)
        , u_trial(u)
        , Lx(u)
        , offset(u)
        , watchdog(watchdog_steps)
      {
      }

      const Phase &phase;
      const double r_ref, tolerance;
      /// No shift: the unregularised equations (the tests that accept a
      /// state short of the residual tolerance apply to these only).
      const bool pure;
      // du must survive the line search: a backtracking step reuses it;
      // Lx and offset are the scratch of the shift term.
      BorderedVector residual, trial, du, u_trial, Lx, offset;
      /// |r| at the iterate and |du| of the direction.
      double r_norm = 0., du_norm = 0.;
      /// Block norms of the first residual, for the table.
      std::vector<double> block_reference;
      /// |du| of the last full, unwatched step (0: none), for the
      /// predicted-update test.
      double last_full_update = 0.;
      /// The next line search resumes along the direction of a failed
      /// watch's saved state.
      bool     resume = false;
      Watchdog watchdog;
      Step     step;
    };

    double
    NewtonSolver::evaluate(NonlinearProblem     &problem,
                           Iteration            &state,
                           const BorderedVector &x,
                           BorderedVector       &r) const
    {
      // r_s(x) = r(x) + s L (x - x_anchor): the regularised residual.
      problem.assemble(x, r);
      if (state.phase.shift > 0.)
        {
          state.offset = x;
          state.offset -= state.phase.anchor;
          problem.laplacian_vmult(state.offset, state.Lx);
          r.add(state.phase.shift, state.Lx);
        }
      return r.l2_norm();
    }

    NewtonSolver::Outcome
    NewtonSolver::test_state(NonlinearProblem &problem,
                             const Iteration  &state,
                             const unsigned    it,
                             NewtonResult     &result) const
    {
      if (!std::isfinite(state.r_norm))
        {
          result.fail(NewtonFailure::not_finite, "residual is not finite");
          return Outcome::failed;
        }
      // A state that meets the tolerance at once (a stage whose loads no
      // longer change it) costs no factorization.
      if (state.r_norm <= state.tolerance)
        {
          result.convergence_test = "residual";
          return Outcome::converged;
        }
      if (problem.interrupted())
        {
          result.fail(NewtonFailure::interrupted, "interrupted");
          return Outcome::failed;
        }
      if (it >= state.phase.max_iterations)
        {
          result.fail(NewtonFailure::no_convergence,
                      "no convergence in "
                        + std::to_string(state.phase.max_iterations)
                        + " iterations");
          return Outcome::failed;
        }
      return Outcome::go_on;
    }

    NewtonSolver::Outcome
    NewtonSolver::newton_direction(NonlinearProblem         &problem,
                                   const BorderedVector     &u,
                                   Iteration                &state,
                                   const ConditionalOStream &out,
                                   NewtonResult             &result) const
    {
      // After a failed watch: the direction from the state it restored.
      if (state.resume)
        {
          state.du      = state.watchdog.saved_step();
          state.du_norm = state.du.l2_norm();
          return Outcome::go_on;
        }
      state.du = 0.;
      state.residual *= -1.;
      try
        {
          problem.set_linear_tolerance(
            forcing_term(state.r_norm / state.r_ref));
          problem.solve_linear(state.phase.shift, state.residual, state.du);
        }
      catch (const std::exception &e)
        {
          // The whole message (without deal.II's frame and stack trace)
          // reaches the log and the failure reason.
          std::string text = e.what();
          const auto  info = text.find("Additional information:");
          if (info != std::string::npos)
            text = text.substr(info + 23);
          text = text.substr(0, text.find("Stacktrace:"));
          text = std::regex_replace(text, std::regex("-{3,}"), " ");
          const std::string message =
            Utilities::trim(std::regex_replace(text, std::regex("\\s+"), " "));
          result.fail(NewtonFailure::linear_solver,
                      "linear solver failed: " + message);
          if (print_table)
            out << "    (linear solver: " << message << ")\n";
          return Outcome::failed;
        }
      ++result.iterations;
      state.du_norm = state.du.l2_norm();
      if (!std::isfinite(state.du_norm))
        {
          result.fail(NewtonFailure::linear_solver, "linear solver failed");
          return Outcome::failed;
        }
      if (state.pure && state.du_norm <= update_tolerance * u.l2_norm()
          && state.r_norm <= floor_update * state.tolerance)
        {
          if (print_table)
            out << "    " << std::setw(4) << result.iterations
                << std::scientific << std::setprecision(3) << "  "
                << state.r_norm / state.r_ref << "  (|du|/|u| = "
                << state.du_norm / std::max(u.l2_norm(), 1e-300)
                << ": the update has vanished)" << std::defaultfloat
                << std::endl;
          result.convergence_test = "update at the round-off floor";
          return Outcome::converged;
        }
      return Outcome::go_on;
    }

    void
    NewtonSolver::search_line(NonlinearProblem     &problem,
                              const BorderedVector &u,
                              Iteration            &state) const
    {
      // Along du, with the watchdog; resumed at half the step after a
      // failed watch.
      Step &step = state.step;
      step       = Step();
      if (state.resume)
        step.alpha = backtrack;
      for (unsigned int ls = state.resume ? 1 : 0;
           ls <= (line_search ? max_line_search : 0);
           ++ls, step.alpha *= backtrack)
        {
          state.u_trial = u;
          state.u_trial.add(step.alpha, state.du);
          step.norm = evaluate(problem, state, state.u_trial, state.trial);
          if (!line_search
              || (std::isfinite(step.norm)
                  && (step.norm <= (1. - armijo * step.alpha) * state.r_norm
                      || step.norm <= state.tolerance)))
            {
              step.accepted = true;
              return;
            }
          if (ls == 0 && state.watchdog.may_take(step.norm, state.r_norm))
            {
              state.watchdog.start(u, state.r_norm, state.du);
              step.accepted = step.watched = true;
              return;
            }
        }
    }

    void
    NewtonSolver::print_iteration(NonlinearProblem         &problem,
                                  const Iteration          &state,
                                  const ConditionalOStream &out,
                                  const NewtonResult       &result) const
    {
      if (!print_table)
        return;
      const Step &step = state.step;
      out << "    " << std::setw(4) << result.iterations << std::scientific
          << std::setprecision(3) << "  " << step.norm / state.r_ref;
      const auto blocks = problem.block_norms(state.trial);
      for (unsigned int b = 0; b < blocks.size(); ++b)
        out << "  "
            << blocks[b]
                 / (state.block_reference[b] > 1e-8 * state.r_ref
                      ? state.block_reference[b]
                      : state.r_ref);
      out << "  "
          << step.alpha * state.du_norm
               / std::max(state.u_trial.l2_norm(), 1e-300)
          << "  " << state.phase.shift << "  " << std::defaultfloat
          << std::setprecision(3) << (step.accepted ? step.alpha : 0.)
          << (step.watched ? " (watchdog)" : "") << std::endl;
    }

    NewtonSolver::Outcome
    NewtonSolver::update(BorderedVector           &u,
                         Iteration                &state,
                         const ConditionalOStream &out,
                         NewtonResult             &result) const
    {
      const Step &step = state.step;
      u                = state.u_trial;
      state.residual   = state.trial;
      state.r_norm     = step.norm;
      // The next update of a quadratic iteration, |du_{k+1}| ~ C |du_k|^2
      // with C = |du_k|/|du_{k-1}|^2 from the last two full steps: once it
      // is below the update tolerance the state is as accurate as the
      // update test would find it, without the factorization that
      // computes it.
      const double du = state.du_norm, last = state.last_full_update;
      const bool   full = step.alpha == 1. && !step.watched;
      if (state.pure && full && last > 0. && du <= contraction * last
          && state.r_norm > state.tolerance
          && state.r_norm <= floor_update * state.tolerance
          && du * du * du <= update_tolerance * u.l2_norm() * last * last)
        {
          if (print_table)
            out << "    (the next update is predicted at |du|/|u| = "
                << std::scientific << std::setprecision(3)
                << du * du * du / (last * last * std::max(u.l2_norm(), 1e-300))
                << std::defaultfloat << ")\n";
          result.residual_history.push_back(state.r_norm);
          result.convergence_test = "update predicted below tolerance";
          return Outcome::converged;
        }
      state.last_full_update = full ? du : 0.;
      state.resume           = false;
      if (state.watchdog.failed(state.r_norm))
        {
          // The residual vector is that of the last iterate until the
          // resumed line search accepts a step (it is not needed before).
          u                      = state.watchdog.saved_state();
          state.r_norm           = state.watchdog.saved_residual_norm();
          state.last_full_update = 0.;
          state.resume           = true;
          if (print_table)
            out << "    (watchdog: back to |r|/|r_ref| = " << std::scientific
                << std::setprecision(3) << state.r_norm / state.r_ref
                << std::defaultfloat << ", on along its step)\n";
          return Outcome::go_on;
        }
      if (state.pure)
        result.residual_history.push_back(state.r_norm);
      return Outcome::go_on;
    }

    bool
    NewtonSolver::iterate(NonlinearProblem         &problem,
                          BorderedVector           &u,
                          const Phase              &phase,
                          const double              r_ref,
                          const ConditionalOStream &out,
                          NewtonResult             &result,
                          const BorderedVector     *assembled) const
    {
      Iteration state(u, phase, r_ref, line_search ? watchdog_steps : 0);
      // The caller's assembly at u serves the first iteration (at the
      // anchor of a shifted phase the shift term vanishes).
      if (assembled)
        {
          state.residual = *assembled;
          state.r_norm   = state.residual.l2_norm();
        }
      else
        state.r_norm = evaluate(problem, state, u, state.residual);
      for (unsigned int it = 0;; ++it)
        {
          if (print_table && state.block_reference.empty())
            state.block_reference = problem.block_norms(state.residual);
          // 1. Convergence and failure tests.
          Outcome outcome = test_state(problem, state, it, result);
          // 2. The Newton direction.
          if (outcome == Outcome::go_on)
            outcome = newton_direction(problem, u, state, out, result);
          if (outcome != Outcome::go_on)
            return outcome == Outcome::converged;
          // 3. Line search.
          search_line(problem, u, state);
          print_iteration(problem, state, out, result);
          if (!state.step.accepted)
            {
              if (state.pure && state.r_norm <= floor_descent * state.tolerance)
                {
                  result.convergence_test = "no descent at the round-off floor";
                  return true;
                }
              result.fail(NewtonFailure::line_search, "line search failed");
              return false;
            }
          // 4. Update, or back to the watchdog's saved state.
          if (update(u, state, out, result) == Outcome::converged)
            return true;
        }
    }

    bool
    NewtonSolver::continuation(NonlinearProblem         &problem,
                               BorderedVector           &u,
                               BorderedVector           &r,
                               const double              r_ref,
                               const ConditionalOStream &out,
                               NewtonResult             &result,
                               ContinuationPath         &path,
                               bool                      fresh) const
    {
      using S = ContinuationSchedule;
      if (path.initial == 0.)
        {
          problem.assemble(u, r); // the scale is taken from K at the start
          fresh        = true;
          path.initial = problem.initial_shift(shift_factor);
          path.shift   = path.initial;
        }
      Phase phase;
      phase.shift           = path.shift;
      phase.max_iterations  = S::inner_iterations;
      phase.tolerance       = S::inner_tolerance;
      unsigned int failures = 0;
      // r and the tangent last assembled are those at u when fresh: a
      // phase starting there need not assemble again.
      const unsigned int start = result.iterations;
      while (path.spent + (result.iterations - start) < S::budget * max_iter
             && !problem.interrupted())
        {
          phase.anchor = u;
          if (!iterate(
                problem, u, phase, r_ref, out, result, fresh ? &r : nullptr))
            {
              u     = phase.anchor; // r is still its residual, the tangent not
              fresh = false;
              phase.shift *= S::grow;
              // A failure that costs no iteration (the linear solver) must
              // not loop for ever.
              if (++failures > S::max_failures)
                break;
              continue;
            }
          problem.assemble(u, r);
          fresh = true;
          if (r.l2_norm() <= path.switch_ratio * r_ref
              || phase.shift < S::min_shift * path.initial)
            break;
          phase.shift *= S::shrink;
        }
      path.shift = phase.shift;
      path.spent += result.iterations - start;
      result.residual_history.assign(1, r.l2_norm());
      result.fail(NewtonFailure::none, "");
      result.convergence_test.clear();
      return fresh;
    }

    void
    NewtonSolver::stiffened_first_iteration(NonlinearProblem         &problem,
                                            BorderedVector           &u,
                                            BorderedVector           &r,
                                            const double              r_ref,
                                            const ConditionalOStream &out,
                                            NewtonResult &result) const
    {
      const double s = problem.start_prestress();
      if (!(s > 0.) || !std::isfinite(s))
        return;
      const double   r_norm = r.l2_norm();
      BorderedVector du(u), rhs(r), u_trial(u), trial(r);
      rhs *= -1.;
      du = 0.;
      try
        {
          problem.solve_linear(s, rhs, du);
        }
      catch (const std::exception &)
        {
          problem.assemble(u, r); // the tangent at u again
          return;
        }
      ++result.iterations;
      u_trial.add(1., du);
      double norm = std::numeric_limits<double>::infinity();
      if (std::isfinite(du.l2_norm()))
        {
          problem.assemble(u_trial, trial);
          norm = trial.l2_norm();
        }
      const bool kept = std::isfinite(norm) && norm < r_norm;
      if (print_table)
        out << "    " << std::setw(4) << result.iterations << std::scientific
            << std::setprecision(3) << "  " << norm / r_ref
            << "  (stiffened start, s = " << s << " N/m"
            << (kept ? ")" : ": not kept)") << std::defaultfloat << std::endl;
      if (kept)
        {
          u = u_trial;
          r = trial;
          result.residual_history.push_back(norm);
        }
      else
        problem.assemble(u, r);
    }

    bool
    NewtonSolver::back_to_continuation(NonlinearProblem &problem,
                                       ContinuationPath &path) const
    {
      using S = ContinuationSchedule;
      // Not after an interrupt, a spent budget or a spent shift.
      if (problem.interrupted() || path.spent >= S::budget * max_iter
          || path.shift < S::min_shift * path.initial
          || path.switch_ratio < S::min_switch_ratio)
        return false;
      path.switch_ratio *= S::tighter;
      path.shift *= S::shrink;
      return true;
    }

    NewtonResult
    NewtonSolver::solve(NonlinearProblem         &problem,
                        BorderedVector           &u,
                        const ConditionalOStream &out,
                        const bool                allow_continuation,
                        const double              reference) const
    {
      NewtonResult   result;
      BorderedVector r(u);
      problem.assemble(u, r);
      const double r0    = r.l2_norm();
      const double r_ref = std::max({r0, problem.load_norm(), reference});
      result.reference   = r_ref;
      result.residual_history.push_back(r0);
      if (r_ref == 0.)
        {
          result.converged        = true;
          result.convergence_test = "no load";
          return result;
        }
      print_header(problem, out);

      // 1. Pure Newton with backtracking.
      Phase newton;
      newton.max_iterations = max_iter;
      newton.tolerance      = residual_tolerance;
      const BorderedVector u_start(u);
      if (allow_continuation && stiffened_start)
        stiffened_first_iteration(problem, u, r, r_ref, out, result);
      if (iterate(problem, u, newton, r_ref, out, result, &r))
        {
          result.converged = true;
          return result;
        }
      if (shift_factor == 0. || !allow_continuation
          || result.iterations >= max_iter)
        return result;

      // 2. Continuation from the start of the step, 3. pure Newton from
      //    where it ends.
      if (print_table)
        out << "    (" << result.failure_reason
            << ": continuing with the regularised iteration)\n";
      //    A pure Newton phase that fails (it explodes from a hand-over
      //    that is still far from equilibrium, a flaccid airbag on a fine
      //    mesh) is not kept: the continuation goes on from its hand-over
      //    with smaller shifts, to a 100 times tighter hand-over, until the
      //    shift is spent.
      u = u_start;
      result.residual_history.assign(1, r0);
      ContinuationPath path;
      path.switch_ratio = ContinuationSchedule::switch_ratio;
      bool fresh        = continuation(problem, u, r, r_ref, out, result, path);
      while (true)
        {
          const BorderedVector u_handover(u), r_handover(r);
          result.converged = iterate(
            problem, u, newton, r_ref, out, result, fresh ? &r : nullptr);
          if (result.converged || !back_to_continuation(problem, path))
            return result;
          if (print_table)
            out << "    (" << result.failure_reason
                << ": back to the regularised iteration at |r|/|r_ref| = "
                << std::scientific << std::setprecision(3)
                << r_handover.l2_norm() / r_ref << ", shift " << path.shift
                << std::defaultfloat << ")\n";
          u     = u_handover;
          r     = r_handover;
          fresh = continuation(problem, u, r, r_ref, out, result, path, false);
        }
    }
  } // namespace solvers
} // namespace pneuma
