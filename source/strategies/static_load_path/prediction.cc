/**
 * @file
 * The first half of a step of the static load path: the attempt prepared
 * (its stage, a path-controlled stage entered), predicted and solved.
 */

#include <pneuma/core/input_error.h>
#include <pneuma/solvers/path_following.h>

#include "walk.h"

#include <cmath>

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
      /// The path's tangent du/dt at the converged state of @p walk, and
      /// |dR/dt| in @p force_rate.
      template <typename Walk>
      BorderedVector
      path_tangent(Walk &walk, double &force_rate)
      {
        BorderedVector state(walk.result.state);
        walk.model.begin_step(walk.t, state);
        const BorderedVector tangent =
          walk.problem.tangent(PathConstraintProblem::extend(state, walk.t),
                               force_rate);
        walk.model.reject_step(walk.t);
        return tangent;
      }
    } // namespace

    StaticLoadPath::Attempt
    StaticLoadPath::prepare(Walk &walk)
    {
      Attempt a;
      a.stage   = current.path.active ? current.path.stage
                                      : walk.run.stages.stage_of(walk.t);
      a.control = control_of(a.stage);
      a.t_old   = walk.t;
      walk.last = walk.result.state;
      // A step from the unstressed state may use Newton's continuation,
      // and is no increment to extrapolate.
      a.from_unstressed = walk.last.field.linfty_norm() == 0.;
      if (a.control != Control::load && !current.path.active)
        enter_path_stage(walk, a);
      a.path_step = a.control != Control::load
                    && walk.forced != PathControl::Forced::to_stage_end;
      return a;
    }

    void
    StaticLoadPath::enter_path_stage(Walk &walk, Attempt &a)
    {
      // Its scales from the path's tangent at the converged state.
      const std::string entry      = "Load stepping/Control";
      const std::string name       = "stage " + std::to_string(a.stage + 1);
      double            force_rate = 0.;
      a.tangent                    = path_tangent(walk, force_rate);
      check_input(force_rate > 0.,
                  entry,
                  name
                    + " is path-controlled, but no load changes "
                      "in it (no load curve varies over its "
                      "pseudo times)");
      PathRecord &p = current.path;
      p.u_scale     = a.tangent.field.l2_norm();
      check_input(p.u_scale > 0. && std::isfinite(p.u_scale),
                  entry,
                  name
                    + ": the loads that change in it do not move "
                      "the structure");
      p.force_scale  = force_rate;
      p.monitor_rate = walk.monitor(a.tangent.field);
      check_input(a.control != Control::displacement
                    || std::abs(p.monitor_rate) > 1e-9 * p.u_scale,
                  entry,
                  name
                    + " is under displacement control, but the "
                      "monitored component does not move with "
                      "its loads");
      p.active             = true;
      p.stage              = a.stage;
      p.arc_length         = 0.;
      p.steps              = 0;
      p.last_dtau          = 0.;
      p.limit_since_return = false;
      p.secant             = false;
      walk.forced          = PathControl::Forced::none;
      walk.dt              = stepping.initial(a.stage);
      walk.out << "Stage " << a.stage + 1 << " under "
               << control_names[controls.size() == 1 ? 0 : a.stage]
               << " control: |du/dt| = " << p.u_scale
               << ", |dR/dt| = " << force_rate << std::endl;
    }

    bool
    StaticLoadPath::solve_load_step(Walk &walk, Attempt &a)
    {
      // The load step from the last converged state.
      a.t_new = walk.forced == PathControl::Forced::to_stage_end
                  ? walk.run.stages.end(a.stage)
                  : stepping.next_time(a.t_old, walk.dt);
      walk.out << "Step " << walk.run.counters.steps + 1 << "  t = " << a.t_new
               << "  dt = " << a.t_new - a.t_old << std::endl;
      // The predictor: the last step's increment scaled to this one
      // (before the step sets its prescribed values), within a
      // load-controlled stage (the loads' rates change at stage ends:
      // sealing, a new load). Its tolerance keeps the scale of the last
      // step's residual per unit pseudo time.
      BorderedVector &state     = walk.result.state;
      double          reference = 0.;
      if (extrapolate && !current.cut_back && current.increment_dt != 0.
          && current.increment_load && current.increment_stage == a.stage
          && step_increment.field.size() == state.field.size()
          && step_increment.border.size() == state.border.size())
        {
          const double factor = (a.t_new - a.t_old) / current.increment_dt;
          state.field.add(factor, step_increment.field);
          state.border.add(factor, step_increment.border);
          reference      = current.reference_rate * std::abs(a.t_new - a.t_old);
          a.extrapolated = true;
        }
      const std::string impossible = walk.model.begin_step(a.t_new, state);
      if (!impossible.empty())
        {
          walk.result.exit_code = 2;
          walk.result.message = impossible + ". The last converged state (t = "
                                + std::to_string(a.t_old) + ") is written.";
          state = walk.last;
          walk.model.reject_step(a.t_old);
          return false;
        }
      a.newton = walk.run.newton.solve(
        walk.model, state, walk.out, a.from_unstressed, reference);
      return true;
    }

    void
    StaticLoadPath::solve_path_step(Walk &walk, Attempt &a)
    {
      PathRecord &p = current.path;
      a.x_last      = PathConstraintProblem::extend(walk.result.state, a.t_old);
      walk.problem.set_scales(p.u_scale,
                              path.psi2(),
                              p.force_scale,
                              std::abs(p.monitor_rate));
      const bool by_displacement =
        a.control == Control::displacement
        || walk.forced == PathControl::Forced::to_target;
      // The predictor: along the path's tangent at the start of the stage
      // (or after a restart), else the secant (the last accepted
      // increment), scaled to the constraint.
      BorderedVector direction;
      if (p.secant)
        direction =
          PathConstraintProblem::extend(step_increment, current.increment_dt);
      else
        {
          double force_rate = 0.;
          if (a.tangent.field.size() == 0)
            a.tangent = path_tangent(walk, force_rate);
          direction = PathConstraintProblem::extend(a.tangent, 1.);
          if (p.last_dtau < 0.)
            direction *= -1.;
        }
      const double factor =
        scale_predictor(walk, a, direction, by_displacement);
      a.x = a.x_last;
      a.x.add(factor, direction);
      a.predictor = a.x;
      a.t_new     = PathConstraintProblem::load_factor(a.x);
      walk.out << "Step " << walk.run.counters.steps + 1 << "  "
               << (by_displacement ? "monitor increment " : "arc length ")
               << a.size << "  predicted t = " << a.t_new << std::endl;
      BorderedVector    state      = PathConstraintProblem::model_part(a.x);
      const std::string impossible = walk.model.begin_step(a.t_new, state);
      if (!impossible.empty())
        {
          a.newton.converged = false;
          a.newton.fail(solvers::NewtonFailure::impossible_step, impossible);
          return;
        }
      // The bordered system.
      a.x      = PathConstraintProblem::extend(state, a.t_new);
      a.newton = walk.run.newton.solve(walk.problem, a.x, walk.out, false);
      walk.result.state = PathConstraintProblem::model_part(a.x);
      a.t_new           = PathConstraintProblem::load_factor(a.x);
    }

    double
    StaticLoadPath::scale_predictor(Walk                 &walk,
                                    Attempt              &a,
                                    const BorderedVector &direction,
                                    const bool            by_displacement)
    {
      const PathRecord &p      = current.path;
      const double      m_last = walk.monitor(walk.result.state.field);
      double            factor = 0.;
      if (by_displacement)
        {
          const double sign  = path.has_target()
                                 ? (path.target() >= m_last ? 1. : -1.)
                                 : (p.monitor_rate >= 0. ? 1. : -1.);
          a.size             = walk.forced == PathControl::Forced::to_target
                                 ? path.target() - m_last
                                 : sign * walk.dt * std::abs(p.monitor_rate);
          const double along = walk.monitor(direction.field);
          factor             = along != 0. ? a.size / along : 0.;
          walk.problem.set_constraint(Control::displacement, a.x_last, a.size);
        }
      else
        {
          a.size = walk.dt;
          factor =
            walk.dt / std::max(walk.problem.arc_length(direction), 1e-300);
          walk.problem.set_constraint(Control::arc_length, a.x_last, a.size);
        }
      // The load factor changes by at most the maximum increment per step;
      // the arc length itself is free to grow where the load hardly
      // changes (past a limit or bifurcation point, where the path's scale
      // of the stage start is far too small).
      const double dtau_predicted =
        factor * PathConstraintProblem::load_factor(direction);
      const auto shorten = [&](const double s) {
        walk.dt *= s;
        a.size *= s;
        factor *= s;
        walk.problem.set_size(a.size);
      };
      if (walk.forced != PathControl::Forced::to_target
          && std::abs(dtau_predicted) > stepping.maximum(a.stage))
        shorten(stepping.maximum(a.stage) / std::abs(dtau_predicted));
      // Under displacement control the monitor's increment is prescribed:
      // a step that would pass the target ends on it (under arc-length
      // control only the solved step tells).
      if (a.control == Control::displacement && path.has_target()
          && walk.forced == PathControl::Forced::none
          && a.stage + 1 == walk.run.stages.n_stages())
        {
          const double rest = path.target() - m_last;
          if (a.size * rest > 0. && std::abs(a.size) >= std::abs(rest))
            {
              shorten(rest / a.size);
              a.size      = rest;
              walk.forced = PathControl::Forced::to_target;
              walk.problem.set_size(a.size);
            }
        }
      return factor;
    }
  } // namespace strategies
} // namespace pneuma
