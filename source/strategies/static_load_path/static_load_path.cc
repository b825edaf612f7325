#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/selection_parameter.h>

#include <pneuma/strategies/stability_monitor.h>

#include "walk.h"

#include <csignal>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;
    using solvers::Control;

    void
    StaticLoadPath::declare_parameters(ParameterHandler &prm)
    {
      stepping.declare_parameters(prm);
      prm.enter_subsection("Load stepping");
      prm.add_parameter(
        "Control",
        control_names,
        "How each stage of the static strategy is driven, one entry per "
        "stage (or one for all): "
        "load (the pseudo time is prescribed), arc-length (the pseudo time "
        "is the load factor, an unknown; the step is an arc length, see "
        "Path following/Constraint) or displacement (the monitored "
        "component of Path following is prescribed, the load factor is "
        "an unknown). The loads that change over a path-controlled stage "
        "are the ones it scales; its prescribed displacements must not "
        "change. Increments of a path-controlled stage are in pseudo "
        "time: the first step of the stage moves the load by Initial "
        "increment.",
        Patterns::List(Patterns::Selection("load|arc-length|displacement"), 1));
      add_selection(
        prm,
        "Initial prestress",
        initial_prestress,
        {{"automatic", InitialPrestress::automatic},
         {"ramped", InitialPrestress::ramped},
         {"full", InitialPrestress::full}},
        "Loads that act in full from t = 0 whatever the load curves (a "
        "cable's Prestress force or short Unstressed length): full keeps "
        "them so; ramped lets them grow linearly over the first stage "
        "(from 0 at t = 0 to full at its end), with the loads that inflate "
        "the structure, so that cut backs reduce them too; automatic "
        "(default) ramps them only once the first step has failed in full, "
        "or converged to an unstable state (judged with Stability/Check "
        "inertia). From the end of the first stage on the loads are the same; "
        "a run whose "
        "first step converges to a stable state is the same under "
        "automatic and full.");
      add_selection(
        prm,
        "Extrapolation",
        extrapolate,
        {{"linear", true}, {"none", false}},
        "Start of a load-controlled step: linear (default) extrapolates "
        "the last step's increment of the state, scaled to this step "
        "(Abaqus' EXTRAPOLATION=LINEAR), where that step was "
        "load-controlled, of the same stage and not from the unstressed "
        "state, and this one is not taken again after a cut back; none "
        "starts from the last converged state. Changes the iterations, "
        "not the equilibrium.");
      path.declare_parameters(prm);
      prm.leave_subsection();
    }

    void
    StaticLoadPath::parse_parameters(ParameterHandler &prm,
                                     const Stages     &stages)
    {
      stepping.parse_parameters(prm, stages);
      const std::string p = "Load stepping/";
      check_input(control_names.size() == 1
                    || control_names.size() == stages.n_stages(),
                  p + "Control",
                  "needs one entry, or one per stage ("
                    + std::to_string(stages.n_stages()) + " stages in "
                    + "Stage end times), not "
                    + std::to_string(control_names.size()));
      controls.clear();
      for (const auto &c : control_names)
        controls.push_back(c == "load"         ? Control::load
                           : c == "arc-length" ? Control::arc_length
                                               : Control::displacement);
      path.parse_parameters(control_of(stages.n_stages() - 1) != Control::load);
    }

    bool
    StaticLoadPath::follows_path() const
    {
      for (unsigned int s = 0; s < stepping.stages().n_stages(); ++s)
        if (control_of(s) != Control::load)
          return true;
      return false;
    }

    void
    StaticLoadPath::check(Model &model) const
    {
      // What the path-controlled stages need, before any step.
      const Stages      &stages   = stepping.stages();
      const unsigned int n_points = model.n_monitor_points();
      // A monitor point other than the default must exist, used or not.
      if (path.monitor_point_index() > 0)
        path.check_monitor_point(n_points, "no such monitor point");
      if (!follows_path())
        return;
      for (unsigned int stage = 0; stage < stages.n_stages(); ++stage)
        if (control_of(stage) != Control::load)
          {
            check_input(!model.prescribed_values_change(stages.start(stage),
                                                        stages.end(stage)),
                        "Load stepping/Control",
                        "stage " + std::to_string(stage + 1)
                          + " is path-controlled, but prescribed "
                            "displacements change in it: give them "
                            "their own load-controlled stage");
            if (control_of(stage) == Control::displacement)
              path.check_monitor_point(
                n_points, "displacement control needs a monitor point");
          }
      if (path.has_target())
        path.check_monitor_point(n_points,
                                 "a target monitor value needs a monitor "
                                 "point");
    }

    Outcome
    StaticLoadPath::run(Run &run, const Segment &segment, const Outcome &from)
    {
      Walk walk(run, segment);
      start(walk, from);
      const double t_end = run.stages.end(segment.last);
      while (!walk.done
             && (current.path.active || !run.stages.finished(walk.t, t_end)))
        {
          if (interrupted(walk))
            break;
          Attempt a = prepare(walk);
          if (!a.path_step)
            {
              if (!solve_load_step(walk, a))
                break;
            }
          else
            solve_path_step(walk, a);
          const Verdict verdict = judge(walk, a);
          if (verdict == Verdict::again)
            continue;
          if (verdict == Verdict::reject)
            {
              if (!reject(walk, a))
                break;
              continue;
            }
          accept(walk, a);
          if (walk.done)
            {
              walk.result.stop = true;
              break;
            }
          if (run.stop_requested()
              && (current.path.active || !run.stages.finished(walk.t, t_end)))
            {
              walk.result.message = run.stop_message();
              walk.result.stop    = true;
              break;
            }
        }
      walk.result.time = walk.t;
      resumed          = false;
      // The reports of the last converged state.
      walk.model.refresh(walk.result.state);
      return walk.result;
    }

    void
    StaticLoadPath::start(Walk &walk, const Outcome &from)
    {
      Model &model = walk.model;
      walk.dt      = stepping.initial(walk.segment.first);
      branch_switching =
        walk.run.stability && walk.run.stability->branch_switching();
      if (resumed)
        {
          // Continue the checkpoint's path (load_checkpoint()).
          const PathState &p       = current;
          walk.result.state        = from.state;
          walk.t                   = p.time;
          walk.dt                  = p.increment;
          walk.stiffness_reference = p.stiffness_reference;
          walk.stiffness           = p.stiffness;
          walk.stiffness_stage     = p.stiffness_stage_set
                                       ? p.stiffness_stage
                                       : numbers::invalid_unsigned_int;
          model.ramp_initial_loads(p.ramp_start, p.ramp_end);
          previous_stability          = solvers::StabilityReport();
          previous_stability.computed = p.negative_eigenvalues >= 0;
          previous_stability.negative = p.negative_eigenvalues;
          critical_points             = p.critical_points;
        }
      else
        {
          current            = PathState();
          step_increment     = BorderedVector();
          previous_stability = solvers::StabilityReport();
          critical_points.clear();
          current.increment = walk.dt;
          if (from.state.field.size() > 0)
            {
              // Handed over by the segment before.
              walk.result.state = from.state;
              walk.t            = from.time;
            }
          else
            {
              // A new run: no ramp from an earlier one (refinement
              // cycles).
              model.ramp_initial_loads(0., 0.);
              walk.result.state = model.initial_state();
              // Load stepping/Initial prestress = ramped: over the first
              // step.
              if (initial_prestress == InitialPrestress::ramped
                  && control_of(0) == Control::load)
                ramp_initial_loads(walk);
              walk.run.report(StepReport{}, walk.result.state);
            }
        }
      walk.last = walk.result.state;
      walk.w = follows_path() ? path.monitor_functional(model) : LA::Vector();
      walk.problem.set_monitor(walk.w);
    }

    bool
    StaticLoadPath::interrupted(Walk &walk) const
    {
      // A signal stops the path between steps, or inside Newton, with the
      // last converged state.
      const int signal = interrupt_signal(walk.model.mpi_communicator());
      if (!signal)
        return false;
      walk.result.exit_code = 128 + signal;
      walk.result.message   = std::string("interrupted by ")
                            + (signal == SIGINT ? "SIGINT" : "SIGTERM")
                            + ". The last converged state (t = "
                            + std::to_string(walk.t) + ") is written.";
      return true;
    }

    void
    StaticLoadPath::snapshot(const Walk &walk)
    {
      // The resumable state, after every accepted or cut-back step.
      current.time                = walk.t;
      current.increment           = walk.dt;
      current.stiffness_reference = walk.stiffness_reference;
      current.stiffness           = walk.stiffness;
      current.stiffness_stage_set =
        walk.stiffness_stage != numbers::invalid_unsigned_int;
      current.stiffness_stage =
        current.stiffness_stage_set ? walk.stiffness_stage : 0;
      current.negative_eigenvalues =
        previous_stability.computed ? previous_stability.negative : -1;
      current.critical_points = critical_points;
      walk.run.mark_resumable();
    }

    bool
    StaticLoadPath::first_step_may_ramp(const Walk    &walk,
                                        const Attempt &a) const
    {
      return initial_prestress == InitialPrestress::automatic
             && walk.run.counters.steps == 0 && a.t_old == 0.
             && a.control == Control::load
             && current.ramp_end <= current.ramp_start;
    }

    bool
    StaticLoadPath::ramp_initial_loads(Walk &walk)
    {
      const double t1 = walk.run.stages.end(0);
      if (!walk.model.ramp_initial_loads(0., t1))
        return false;
      current.ramp_start = 0.;
      current.ramp_end   = t1;
      walk.out << "  the prestress acting at t = 0 grows with the loads of "
                  "the first stage, to full at t = "
               << t1 << " (Load stepping/Initial prestress)" << std::endl;
      return true;
    }

    void
    StaticLoadPath::add_history(Statistics       &row,
                                const StepReport &report,
                                const BorderedVector &,
                                Run &)
    {
      if (!follows_path())
        return;
      const auto run = StatisticsGroup::run();
      row.add(run, "load_factor", "", report.load_factor, Statistics::history);
      row.add(run, "arc_length", "", report.arc_length, Statistics::history);
    }

    void
    StaticLoadPath::add_summary(Statistics &row) const
    {
      constexpr unsigned int counts = Statistics::summary;
      // Load stepping/Initial prestress: where the ramp of the prestress
      // acting at t = 0 ended, if it was ramped.
      if (current.ramp_end > current.ramp_start)
        row.add(StatisticsGroup::run(),
                "prestress_ramp_end",
                "",
                current.ramp_end,
                counts);
      // Critical points: located by the stability check, or limit points
      // where a followed path turned back.
      for (unsigned int k = 0; k < critical_points.size(); ++k)
        {
          const auto           &c = critical_points[k];
          const StatisticsGroup g{"cp", "critical_points", "point", k + 1};
          row.add(g, "time", "", c.time, counts);
          row.add(g, "bracket", "", c.bracket, counts);
          row.add_count(g, "step", c.step, counts);
          row.add_count(g,
                        "limit_point",
                        c.type == CriticalPointType::limit_point,
                        counts);
          row.add_count(g, "negative_before", c.before, counts);
          row.add_count(g, "negative_after", c.after, counts);
          if (follows_path())
            row.add(g, "monitor", "m", c.monitor, counts);
          if (branch_switching && c.type == CriticalPointType::bifurcation)
            {
              row.add_count(g, "switched", c.switched, counts);
              row.add(g, "switch_amplitude", "m", c.amplitude, counts);
            }
        }
    }

    void
    StaticLoadPath::save_checkpoint(
      Checkpoint                          &checkpoint,
      std::vector<const BorderedVector *> &vectors) const
    {
      checkpoint.put("static/path", current);
      // The last step's increment (the predictors').
      if (step_increment.field.size() > 0)
        vectors.push_back(&step_increment);
      checkpoint.put("static/increment", step_increment.field.size() > 0);
    }

    void
    StaticLoadPath::load_checkpoint(const Checkpoint            &checkpoint,
                                    std::vector<BorderedVector> &vectors)
    {
      current        = checkpoint.get<PathState>("static/path");
      step_increment = BorderedVector();
      if (checkpoint.get<bool>("static/increment") && !vectors.empty())
        step_increment = std::move(vectors[0]);
      resumed = true;
    }

    PNEUMA_REGISTER_STRATEGY(StaticLoadPath,
                             "static",
                             Placement::stage,
                             "Newton's method through the stage under load, "
                             "arc-length or displacement control");
  } // namespace strategies
} // namespace pneuma
