#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/load_path.h>

#include <csignal>
#include <iomanip>
#include <sstream>

namespace pneuma
{
  namespace solvers
  {
    namespace
    {
      /// Below this current stiffness parameter a failed step is reported
      /// as a limit point (the tangent stiffness along the path has fallen
      /// to a tenth of the stage's first step).
      constexpr double limit_point_stiffness = 0.1;
    } // namespace

    void
    StaticLoadPath::declare_parameters(ParameterHandler &prm)
    {
      stepping.declare_parameters(prm);
      newton_solver.declare_parameters(prm);
    }

    void
    StaticLoadPath::parse_parameters(ParameterHandler &prm)
    {
      stepping.parse_parameters(prm);
      newton_solver.parse_parameters(prm);
    }

    CriticalPoint
    StaticLoadPath::locate(Model                &model,
                           const BorderedVector &last,
                           const double          t_old,
                           const double          t_new,
                           const long long       before,
                           const long long       after)
    {
      // Each probe solves from the last accepted state (its subsystems'
      // committed state is intact: the new step is not yet committed) to
      // the middle of the bracket, judges it and is rejected.
      const ConditionalOStream quiet(std::cout, false);
      CriticalPoint            c;
      c.before  = before;
      c.after   = after;
      double lo = t_old, hi = t_new;
      while (hi - lo > locate_tolerance * (t_new - t_old) && c.probes < 40)
        {
          const double mid = 0.5 * (lo + hi);
          model.reject_step(t_old);
          BorderedVector    probe(last);
          const std::string impossible = model.begin_step(mid, probe);
          ++c.probes;
          if (!impossible.empty())
            break;
          const auto newton = newton_solver.solve(model, probe, quiet, false);
          if (!newton.converged || !model.check_state(probe).empty())
            break;
          const StabilityReport r = stability_judge(probe);
          if (!r.computed)
            break;
          (r.negative == before ? lo : hi) = mid;
        }
      model.reject_step(t_old);
      c.time    = 0.5 * (lo + hi);
      c.bracket = hi - lo;
      return c;
    }

    PathResult
    StaticLoadPath::run(Model                                      &model,
                        const ConditionalOStream                   &out,
                        dealii::Timer                              &wall_clock,
                        const Observer                             &observer,
                        const std::pair<PathState, BorderedVector> *resume)
    {
      PathResult result;
      double     t  = 0.;
      double     dt = stepping.initial();
      // Bergan's current stiffness parameter, per stage.
      double       stiffness_reference = 0., stiffness = 1.;
      unsigned int stiffness_stage = numbers::invalid_unsigned_int;
      if (resume)
        {
          const PathState &p           = resume->first;
          result.state                 = resume->second;
          t                            = p.time;
          dt                           = p.increment;
          result.steps                 = p.steps;
          result.cutbacks              = p.cutbacks;
          result.newton_iterations     = p.newton_iterations;
          result.step_iterations       = p.step_iterations;
          result.last_residual_history = p.last_residual_history;
          stiffness_reference          = p.stiffness_reference;
          stiffness                    = p.stiffness;
          stiffness_stage              = p.stiffness_stage_set
                                           ? p.stiffness_stage
                                           : numbers::invalid_unsigned_int;
          current                      = p;
          previous_stability           = StabilityReport();
          previous_stability.computed  = p.negative_eigenvalues >= 0;
          previous_stability.negative  = p.negative_eigenvalues;
          result.critical_points       = p.critical_points;
        }
      else
        {
          result.state       = model.initial_state();
          current            = PathState();
          previous_stability = StabilityReport();
          current.increment  = dt;
          observer(PathStep{}, result.state);
        }
      BorderedVector last(result.state);
      // The resumable state, after every accepted or cut-back step.
      const auto snapshot = [&]() {
        current.time                = t;
        current.increment           = dt;
        current.steps               = result.steps;
        current.cutbacks            = result.cutbacks;
        current.newton_iterations   = result.newton_iterations;
        current.stiffness_reference = stiffness_reference;
        current.stiffness           = stiffness;
        current.stiffness_stage_set =
          stiffness_stage != numbers::invalid_unsigned_int;
        current.stiffness_stage =
          current.stiffness_stage_set ? stiffness_stage : 0;
        current.step_iterations       = result.step_iterations;
        current.last_residual_history = result.last_residual_history;
        current.negative_eigenvalues =
          previous_stability.computed ? previous_stability.negative : -1;
        current.critical_points = result.critical_points;
      };

      while (!stepping.finished(t))
        {
          // A signal stops the path between steps, or inside Newton
          // (below), with the last converged state.
          if (const int signal = interrupt_signal(model.mpi_communicator()))
            {
              result.exit_code = 128 + signal;
              result.message   = std::string("interrupted by ")
                               + (signal == SIGINT ? "SIGINT" : "SIGTERM")
                               + ". The last converged state (t = "
                               + std::to_string(t) + ") is written.";
              break;
            }
          // 1. Prepare the step from the last converged state.
          const double t_old = t, t_new = stepping.next_time(t_old, dt);
          last = result.state;
          out << "Step " << result.steps + 1 << "  t = " << t_new
              << "  dt = " << t_new - t_old << std::endl;
          const std::string impossible = model.begin_step(t_new, result.state);
          if (!impossible.empty())
            {
              result.exit_code = 2;
              result.message   = impossible + ". The last converged state (t = "
                               + std::to_string(t_old) + ") is written.";
              result.state = last;
              model.reject_step(t_old);
              break;
            }

          // 2. Solve, and check that the state is admissible.
          auto newton = newton_solver.solve(model,
                                            result.state,
                                            out,
                                            last.field.linfty_norm() == 0.);
          result.newton_iterations += newton.iterations;
          if (newton.converged)
            {
              const std::string reason = model.check_state(result.state);
              if (!reason.empty())
                {
                  newton.converged      = false;
                  newton.failure_reason = reason;
                }
            }

          // The stability of the converged state, before it is committed;
          // a change of the count is located between the two states.
          StabilityReport stability;
          if (newton.converged && stability_judge)
            {
              stability = stability_judge(result.state);
              if (locate_tolerance > 0. && stability.computed
                  && stability.energy_form && previous_stability.computed
                  && previous_stability.energy_form
                  && stability.negative != previous_stability.negative)
                {
                  const BorderedVector accepted(result.state);
                  CriticalPoint        c = locate(model,
                                           last,
                                           t_old,
                                           t_new,
                                           previous_stability.negative,
                                           stability.negative);
                  c.step                 = result.steps + 1;
                  // Back to the accepted state: prepare the step exactly
                  // as before the probes (from the last state: the same
                  // prescribed values, contact candidates and border
                  // scales that the accepted state was solved with), then
                  // judge it again (an assembly at it: its friction state).
                  BorderedVector again(last);
                  model.begin_step(t_new, again);
                  result.state = accepted;
                  stability    = stability_judge(result.state);
                  out << "  critical point: " << c.type << " at t = " << c.time
                      << " (+-" << 0.5 * c.bracket << "), negative eigenvalues "
                      << c.before << " -> " << c.after << ", " << c.probes
                      << " probes" << std::endl;
                  result.critical_points.push_back(c);
                }
            }

          // 3. Reject: back to the last state with a smaller increment.
          if (!newton.converged && newton.failure_reason == "interrupted")
            {
              result.state = last;
              model.reject_step(t_old);
              continue; // stops at the top of the loop
            }
          if (!newton.converged)
            {
              ++result.cutbacks;
              result.state = last;
              model.reject_step(t_old);
              dt = stepping.cut(t_new - t_old);
              out << "  Newton failed (" << newton.failure_reason
                  << "); cutting back to dt = " << dt << std::endl;
              if (dt < stepping.minimum())
                {
                  std::ostringstream msg;
                  msg << "the load step could not be completed at t = " << t_old
                      << " even with the minimum increment "
                      << stepping.minimum() << " (" << newton.failure_reason
                      << ")";
                  if (stiffness < limit_point_stiffness)
                    msg << "; a limit point was reached: the current "
                           "stiffness parameter fell to "
                        << stiffness
                        << ", so the load cannot grow further under load "
                           "control (use volume or gas-amount control)";
                  msg << ". The last converged state (t = " << t_old
                      << ") is written.";
                  result.exit_code = 2;
                  result.message   = msg.str();
                  break;
                }
              snapshot();
              continue;
            }

          // 4. Accept.
          if (stability.computed && stability.energy_form)
            previous_stability = stability;
          t = t_new;
          ++result.steps;
          model.commit_step(t_new, result.state);
          result.step_iterations.push_back(newton.iterations);
          result.last_residual_history = newton.residual_history;
          LA::Vector increment(result.state.field);
          increment -= last.field;
          const double ratio =
            (t_new - t_old) / std::max(increment.l2_norm(), 1e-300);
          const unsigned int stage = stepping.stage_of(t_old);
          if (stage != stiffness_stage)
            {
              stiffness_stage     = stage;
              stiffness_reference = ratio;
            }
          stiffness = ratio / stiffness_reference;
          out << "  converged in " << newton.iterations << " iterations ("
              << newton.convergence_test << "), wall " << std::fixed
              << std::setprecision(2) << wall_clock.wall_time() << " s"
              << std::defaultfloat << std::setprecision(6) << std::endl;
          dt = stepping.grown(t_new - t_old, newton.iterations);
          snapshot();
          observer(PathStep{result.steps,
                            t_new,
                            newton.iterations,
                            newton.convergence_test,
                            stiffness,
                            stability},
                   result.state);
          if (stop_step > 0 && result.steps >= stop_step
              && !stepping.finished(t))
            {
              result.message = "stopped after step "
                               + std::to_string(result.steps)
                               + " as asked (Checkpoint/Stop after step); "
                                 "continue with --restart";
              break;
            }
        }
      result.final_time = t;
      // The reports of the last converged state.
      model.refresh(result.state);
      return result;
    }
  } // namespace solvers
} // namespace pneuma
