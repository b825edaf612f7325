#pragma once

/**
 * @file
 * The state of StaticLoadPath::run() while it goes (private to the
 * strategy's files): the path as a whole (Walk) and one attempt of a step
 * (Attempt).
 */

#include <deal.II/base/numbers.h>

#include <pneuma/core/model.h>
#include <pneuma/strategies/stages.h>
#include <pneuma/strategies/static_load_path/static_load_path.h>

namespace pneuma
{
  namespace strategies
  {
    /// The path while run() goes.
    struct StaticLoadPath::Walk
    {
      Walk(Run &run, const Segment &segment)
        : run(run)
        , model(run.model)
        , out(run.out)
        , segment(segment)
        , problem(run.model, 1e-6 * run.stages.end_time())
      {
      }

      Run                              &run;
      Model                            &model;
      const dealii::ConditionalOStream &out;
      const Segment                     segment;
      /// The last converged state (the current one while a step is
      /// solved), how the path ends.
      Outcome result;
      /// The last converged state, while a step is tried.
      solvers::BorderedVector last;
      /// Pseudo time of the last converged state and the next increment.
      double t = 0., dt = 0.;
      /// Bergan's current stiffness parameter, per stage.
      double       stiffness_reference = 0., stiffness = 1.;
      unsigned int stiffness_stage = dealii::numbers::invalid_unsigned_int;
      /// A step forced to end exactly at a stage's end or the target.
      PathControl::Forced forced = PathControl::Forced::none;
      /// A path-controlled stage ended the run (target, critical point,
      /// too many steps).
      bool done = false;
      /// The model bordered by the path constraint, and the monitor.
      solvers::PathConstraintProblem problem;
      LA::Vector                     w;

      /// The monitored component of @p field (NaN without a monitor).
      double
      monitor(const LA::Vector &field) const
      {
        return monitor_value(w, field);
      }
    };

    /// One attempt of a step.
    struct StaticLoadPath::Attempt
    {
      unsigned int     stage   = 0;
      solvers::Control control = solvers::Control::load;
      /// From the last converged pseudo time to the step's.
      double t_old = 0., t_new = 0.;
      /// From the unstressed state (Newton's continuation allowed; no
      /// increment to extrapolate).
      bool from_unstressed = false;
      /// Under path control (not a step forced to a stage's end).
      bool path_step = false;
      /// The load step starts from the extrapolated increment.
      bool extrapolated = false;
      /// The path's tangent at the last converged state (on entering a
      /// path-controlled stage).
      solvers::BorderedVector tangent;
      /// A path step: the extended last state, the solution, the
      /// predictor, the constraint's size.
      solvers::BorderedVector x_last, x, predictor;
      double                  size = 0.;
      solvers::NewtonResult   newton;
      /// The judgement: stability, a limit point located, a branch left.
      solvers::StabilityReport stability;
      bool                     limit_located = false, switched = false;
      /// The forced end the accepted step reached.
      PathControl::Forced reached = PathControl::Forced::none;
    };
  } // namespace strategies
} // namespace pneuma
