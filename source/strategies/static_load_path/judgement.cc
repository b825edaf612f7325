/**
 * @file
 * The judgement of a step of the static load path: is the converged state
 * admissible, did a path step go on along the path, is it stable (critical
 * points located, bifurcations left); and the rejection of a failed step.
 */

#include <pneuma/solvers/path_following.h>
#include <pneuma/strategies/stability_monitor.h>

#include "walk.h"

#include <algorithm>
#include <sstream>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;
    using solvers::Control;
    using solvers::PathConstraintProblem;

    namespace
    {
      /// Below this current stiffness parameter a failed step is reported
      /// as a limit point (the tangent stiffness along the path has fallen
      /// to a tenth of the stage's first step).
      constexpr double limit_point_stiffness = 0.1;
    } // namespace

    StaticLoadPath::Verdict
    StaticLoadPath::judge(Walk &walk, Attempt &a)
    {
      walk.run.counters.newton_iterations += a.newton.iterations;
      if (a.newton.converged)
        {
          const std::string reason = walk.model.check_state(walk.result.state);
          if (!reason.empty())
            {
              a.newton.converged = false;
              a.newton.fail(solvers::NewtonFailure::state_rejected, reason);
            }
        }
      if (a.newton.converged && a.path_step
          && judge_path_step(walk, a) == Verdict::again)
        return Verdict::again;
      if (a.newton.converged && walk.run.stability
          && judge_stability(walk, a) == Verdict::again)
        return Verdict::again;
      // The automatic first step: a first state that is unstable under
      // the full initial prestress (a tube crushed by a cable before it is
      // inflated) is taken again with the prestress growing over the first
      // stage.
      if (a.newton.converged && a.stability.computed && a.stability.negative > 0
          && first_step_may_ramp(walk, a) && ramp_initial_loads(walk))
        {
          walk.out << "  (the first state was unstable under the full "
                      "prestress: the step is taken again)"
                   << std::endl;
          again(walk, a);
          return Verdict::again;
        }
      // A signal inside Newton: the loop stops at its top.
      if (!a.newton.converged
          && a.newton.failure == solvers::NewtonFailure::interrupted)
        {
          again(walk, a);
          return Verdict::again;
        }
      return a.newton.converged ? Verdict::accept : Verdict::reject;
    }

    StaticLoadPath::Verdict
    StaticLoadPath::judge_path_step(Walk &walk, Attempt &a)
    {
      // A path step must go on along the path, and stops where its stage
      // ends: at the stage's end time or at the target (a step that passes
      // one is taken again to end there exactly).
      BorderedVector step(a.x);
      step -= a.x_last;
      const double m_old   = walk.monitor(walk.last.field),
                   m_new   = walk.monitor(walk.result.state.field);
      const Stages &stages = walk.run.stages;
      if (current.path.secant
          && walk.problem.dot(step,
                              PathConstraintProblem::extend(
                                step_increment, current.increment_dt))
               < 0.)
        {
          a.newton.converged = false;
          a.newton.fail(solvers::NewtonFailure::turned_back,
                        "the step turned back along the path");
        }
      else if (a.t_new > stages.end(a.stage) + 1e-12 * stages.end_time())
        {
          walk.forced = PathControl::Forced::to_stage_end;
          again(walk, a);
          walk.out << "  past the stage's end (t = " << a.t_new
                   << "): the step is taken again to t = "
                   << stages.end(a.stage) << std::endl;
          return Verdict::again;
        }
      else if (path.has_target()
               && walk.forced != PathControl::Forced::to_target
               && a.stage + 1 == stages.n_stages()
               && (m_new - path.target()) * (m_old - path.target()) < 0.)
        {
          walk.forced = PathControl::Forced::to_target;
          again(walk, a);
          walk.out << "  past the target (monitor " << m_new
                   << "): the step is taken again to " << path.target()
                   << std::endl;
          return Verdict::again;
        }
      return Verdict::accept;
    }

    StaticLoadPath::Verdict
    StaticLoadPath::judge_stability(Walk &walk, Attempt &a)
    {
      // The stability of the converged state, before it is committed; a
      // change of the count is located between the two states.
      StabilityMonitor &monitor = *walk.run.stability;
      a.stability =
        monitor.judge(walk.model, walk.result.state, walk.model.time(), false);
      const auto changed = [&]() {
        return previous_stability.computed
               && a.stability.negative != previous_stability.negative;
      };
      // A change counted on Newton's factorization (the tangent of the
      // last iterate) is confirmed on the state's own.
      if (a.stability.from_newton && changed())
        a.stability =
          monitor.judge(walk.model, walk.result.state, walk.model.time(), true);
      // A change of the count after an extrapolated start may be the
      // extrapolation's: past a critical point it can reach another
      // equilibrium (a crumpled balloon, thousands of negative
      // eigenvalues). The step is taken again from the converged state.
      if (a.extrapolated && a.stability.computed && changed())
        {
          walk.out << "  (the stability count changed after the "
                      "extrapolated start: the step is taken again "
                      "from the last converged state)"
                   << std::endl;
          walk.result.state = walk.last;
          current.cut_back  = true;
          walk.model.reject_step(a.t_old);
          return Verdict::again;
        }
      if (monitor.locate_tolerance() > 0. && a.stability.computed
          && a.stability.energy_form && previous_stability.energy_form
          && changed())
        locate_critical_point(walk, a);
      return Verdict::accept;
    }

    void
    StaticLoadPath::locate_critical_point(Walk &walk, Attempt &a)
    {
      StabilityMonitor         &monitor = *walk.run.stability;
      const CriticalPointSearch search(walk.run, monitor.locate_tolerance());
      const BorderedVector      accepted(walk.result.state);
      CriticalPoint             c;
      if (a.path_step)
        {
          BorderedVector increment(a.x);
          increment -= a.x_last;
          c               = search.locate_on_path(walk.problem,
                                    a.x_last,
                                    increment,
                                    a.size,
                                    walk.w,
                                    previous_stability.negative,
                                    a.stability.negative);
          a.limit_located = c.type == CriticalPointType::limit_point;
        }
      else
        {
          c         = search.locate(walk.last,
                            a.t_old,
                            a.t_new,
                            previous_stability.negative,
                            a.stability.negative);
          c.monitor = walk.monitor(walk.result.state.field);
        }
      c.step = walk.run.counters.steps + 1;
      // Back to the accepted state: prepare the step exactly as before the
      // probes (the same prescribed values, contact candidates and border
      // scales that the accepted state was solved with), then judge it
      // again (an assembly at it: its friction state).
      BorderedVector again_state =
        a.path_step ? PathConstraintProblem::model_part(a.predictor)
                    : walk.last;
      walk.model.begin_step(a.path_step
                              ? PathConstraintProblem::load_factor(a.predictor)
                              : a.t_new,
                            again_state);
      walk.result.state = accepted;
      a.stability = monitor.judge(walk.model, walk.result.state, a.t_new, true);
      walk.out << "  critical point: " << to_string(c.type)
               << " at t = " << c.time << " (+-" << 0.5 * c.bracket
               << "), negative eigenvalues " << c.before << " -> " << c.after
               << ", " << c.probes << " probes" << std::endl;
      // The first bifurcation: onto the secondary branch.
      const bool first_bifurcation =
        std::none_of(critical_points.begin(),
                     critical_points.end(),
                     [](const CriticalPoint &p) {
                       return p.type == CriticalPointType::bifurcation;
                     });
      if (monitor.branch_switching() && c.type == CriticalPointType::bifurcation
          && first_bifurcation)
        {
          LA::Vector step_field(walk.result.state.field);
          step_field -= walk.last.field;
          a.switched = search.switch_branch(
            walk.result.state, a.t_new, step_field.l2_norm(), a.stability, c);
        }
      critical_points.push_back(c);
    }

    void
    StaticLoadPath::again(Walk &walk, const Attempt &a)
    {
      walk.result.state = walk.last;
      walk.model.reject_step(a.t_old);
    }

    bool
    StaticLoadPath::reject(Walk &walk, Attempt &a)
    {
      // Back to the last state with a smaller increment.
      ++walk.run.counters.cutbacks;
      current.cut_back = true;
      again(walk, a);
      const double tried =
        a.control != Control::load ? walk.dt : a.t_new - a.t_old;
      // An exact end that could not be reached from here: go on along the
      // path with a shorter step.
      walk.forced = PathControl::Forced::none;
      walk.dt     = stepping.cut(tried);
      walk.out << "  Newton failed (" << a.newton.failure_reason
               << "); cutting back to "
               << (a.control != Control::load ? "a step of " : "dt = ")
               << walk.dt << std::endl;
      // The automatic first step: a cut back does not reduce the loads
      // that act in full from t = 0; from now on they grow with the others
      // over the first stage.
      if (first_step_may_ramp(walk, a))
        ramp_initial_loads(walk);
      if (walk.dt < stepping.minimum())
        {
          std::ostringstream msg;
          msg << "the load step could not be completed at t = " << a.t_old
              << " even with the minimum increment " << stepping.minimum()
              << " (" << a.newton.failure_reason << ")";
          if (walk.stiffness < limit_point_stiffness
              && a.control == Control::load)
            msg << "; a limit point was reached: the current "
                   "stiffness parameter fell to "
                << walk.stiffness
                << ", so the load cannot grow further under load "
                   "control (use Load stepping/Control = arc-length, "
                   "or volume or gas-amount control)";
          else if (a.from_unstressed)
            msg << "; the step starts from the unstressed state, which "
                   "has no stiffness (a flaccid start): relax the first "
                   "stage instead (Load stepping/Strategy = relaxation, "
                   "static)";
          msg << ". The last converged state (t = " << a.t_old
              << ") is written.";
          walk.result.exit_code = 2;
          walk.result.message   = msg.str();
          return false;
        }
      snapshot(walk);
      return true;
    }
  } // namespace strategies
} // namespace pneuma
