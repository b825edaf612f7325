/**
 * @file
 * The acceptance of a converged step of the static load path: the state
 * committed and reported, the increment kept for the next predictor,
 * Bergan's stiffness parameter, the path's record (arc length, limit
 * points) and the end of a path-controlled stage.
 */

#include <pneuma/solvers/path_following.h>

#include "walk.h"

#include <iomanip>
#include <sstream>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;
    using solvers::PathConstraintProblem;

    void
    StaticLoadPath::accept(Walk &walk, Attempt &a)
    {
      RunCounters &counters = walk.run.counters;
      if (a.stability.computed && a.stability.energy_form)
        previous_stability = a.stability;
      current.cut_back = false;
      // The increment the next step's predictor extrapolates: after a
      // load-controlled step, not across a branch switch, nor from the
      // unstressed state (a membrane's first response, w ~ p^(1/3),
      // extrapolated linearly overshoots).
      const BorderedVector &state = walk.result.state;
      step_increment              = state;
      step_increment.field -= walk.last.field;
      step_increment.border -= walk.last.border;
      const double dt      = a.t_new - a.t_old;
      current.increment_dt = dt;
      current.reference_rate =
        a.newton.reference / std::max(std::abs(dt), 1e-300);
      current.increment_stage = a.stage;
      current.increment_load =
        !a.path_step && !a.switched && !a.from_unstressed;
      walk.t = a.t_new;
      ++counters.steps;
      walk.model.commit_step(a.t_new, state);
      counters.step_iterations.push_back(a.newton.iterations);
      counters.last_residual_history = a.newton.residual_history;
      counters.residual_histories.push_back(a.newton.residual_history);
      // Bergan's current stiffness parameter, relative to the stage's
      // first step.
      const double ratio =
        std::abs(dt) / std::max(step_increment.field.l2_norm(), 1e-300);
      if (a.stage != walk.stiffness_stage)
        {
          walk.stiffness_stage     = a.stage;
          walk.stiffness_reference = ratio;
        }
      walk.stiffness = ratio / walk.stiffness_reference;
      a.reached      = walk.forced;
      walk.forced    = PathControl::Forced::none;
      if (current.path.active)
        record_path_step(walk, a);
      walk.out << "  converged in " << a.newton.iterations << " iterations ("
               << a.newton.convergence_test << "), wall " << std::fixed
               << std::setprecision(2) << walk.run.wall_clock.wall_time()
               << " s" << std::defaultfloat << std::setprecision(6)
               << std::endl;
      walk.dt = a.path_step
                  ? stepping.grown(walk.dt, a.newton.iterations, false, a.t_new)
                  : stepping.grown(dt, a.newton.iterations, true, a.t_new);
      StepReport    report{counters.steps,
                        a.t_new,
                        a.newton.iterations,
                        a.newton.convergence_test,
                        walk.stiffness,
                        a.stability};
      const Stages &stages = walk.run.stages;
      report.load_factor   = (a.t_new - stages.start(a.stage))
                           / (stages.end(a.stage) - stages.start(a.stage));
      report.arc_length = current.path.active ? current.path.arc_length : 0.;
      if (current.path.active)
        end_path_stage(walk, a);
      snapshot(walk);
      walk.run.report(report, state);
    }

    void
    StaticLoadPath::record_path_step(Walk &walk, const Attempt &a)
    {
      // The path's record: the secant, the arc length, and the load factor
      // turning back (a limit point, if no stability check located it).
      PathRecord  &p    = current.path;
      const double dtau = a.t_new - a.t_old;
      p.arc_length += walk.problem.arc_length(
        PathConstraintProblem::extend(step_increment, dtau));
      ++p.steps;
      if (a.limit_located)
        p.limit_since_return = true;
      if (p.last_dtau * dtau < 0.)
        {
          if (!p.limit_since_return)
            {
              CriticalPoint c;
              c.type    = CriticalPointType::limit_point;
              c.step    = walk.run.counters.steps;
              c.time    = std::max(a.t_old, a.t_new);
              c.bracket = std::abs(dtau);
              c.monitor = walk.monitor(walk.last.field);
              c.before = c.after = previous_stability.negative;
              critical_points.push_back(c);
              walk.out << "  limit point: the load factor turned back "
                          "near t = "
                       << a.t_old << std::endl;
            }
          p.limit_since_return = false;
        }
      if (dtau != 0.)
        p.last_dtau = dtau;
      // After a branch switch the next predictor is the tangent of the
      // secondary branch, not the secant across branches.
      if (a.switched)
        p.secant = false;
      else if (a.reached == PathControl::Forced::none)
        p.secant = true;
    }

    void
    StaticLoadPath::end_path_stage(Walk &walk, const Attempt &a)
    {
      // Where a path-controlled stage ends: at its end time (the next
      // stage goes on), at the target, at the first critical point if
      // asked, or after too many steps.
      PathRecord   &p      = current.path;
      const Stages &stages = walk.run.stages;
      if (a.reached == PathControl::Forced::to_stage_end)
        {
          p.active = false;
          p.secant = false;
          walk.dt  = stepping.initial(stages.stage_of(a.t_new));
        }
      else if (a.reached == PathControl::Forced::to_target)
        {
          walk.done           = true;
          walk.result.message = "the monitored displacement reached its "
                                "target "
                                + std::to_string(path.target());
        }
      else if (path.stop_at_critical() && !critical_points.empty()
               && critical_points.back().step == walk.run.counters.steps)
        {
          walk.done = true;
          walk.result.message =
            "stopped at the first critical point (a "
            + to_string(critical_points.back().type)
            + " at t = " + std::to_string(critical_points.back().time)
            + ") as asked (Load stepping/Path following/Stop at "
              "critical point)";
        }
      else if (p.steps >= path.max_steps())
        {
          walk.result.exit_code = 2;
          std::ostringstream msg;
          msg << "stage " << a.stage + 1 << " did not reach its end ("
              << (path.has_target() && a.stage + 1 == stages.n_stages()
                    ? "the target monitor value "
                        + std::to_string(path.target()) + " or "
                    : std::string())
              << "t = " << stages.end(a.stage) << ") in " << path.max_steps()
              << " steps (Load stepping/Path following/Maximum "
                 "steps); the load factor is at t = "
              << a.t_new << ". The last converged state is written.";
          walk.result.message = msg.str();
          walk.done           = true;
        }
    }
  } // namespace strategies
} // namespace pneuma
