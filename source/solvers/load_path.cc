#include <pneuma/core/input_error.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/solvers/load_path.h>

#include <algorithm>
#include <limits>

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

      /// The monitored component w . u, or NaN without a monitor.
      double
      monitor_value(const LA::Vector &w, const LA::Vector &field)
      {
        return w.size() > 0 ? w * field
                            : std::numeric_limits<double>::quiet_NaN();
      }
    } // namespace

    void
    StaticLoadPath::declare_parameters(ParameterHandler &prm)
    {
      stepping.declare_parameters(prm);
      newton_solver.declare_parameters(prm);
      prm.enter_subsection("Load stepping");
      prm.add_parameter(
        "Control",
        control_names,
        "How each stage is driven, one entry per stage (or one for all): "
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
      prm.add_parameter(
        "Initial prestress",
        initial_prestress,
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
        "automatic and full.",
        Patterns::Selection("automatic|ramped|full"));
      prm.add_parameter(
        "Extrapolation",
        extrapolation_name,
        "Start of a load-controlled step: linear (default) extrapolates "
        "the last step's increment of the state, scaled to this step "
        "(Abaqus' EXTRAPOLATION=LINEAR), where that step was "
        "load-controlled, of the same stage and not from the unstressed "
        "state, and this one is not taken again after a cut back; none "
        "starts from the last converged state. Changes the iterations, "
        "not the equilibrium.",
        Patterns::Selection("linear|none"));
      prm.enter_subsection("Path following");
      prm.add_parameter("Constraint",
                        constraint_name,
                        "Arc-length constraint: cylindrical (Crisfield: "
                        "the displacement increment alone) or spherical "
                        "(displacement and load factor increments alike).",
                        Patterns::Selection("cylindrical|spherical"));
      prm.add_parameter("Monitor point",
                        monitor_point,
                        "Index (from 0) into Output/Monitor points of the "
                        "point whose displacement is monitored: prescribed "
                        "under displacement control, the target below, and "
                        "reported at critical points.",
                        Patterns::Integer(0));
      prm.add_parameter("Monitor component",
                        monitor_component,
                        "Displacement component of the monitor.",
                        Patterns::Selection("x|y|z"));
      prm.add_parameter("Target monitor value",
                        target_text,
                        "The last stage, if path-controlled, ends when the "
                        "monitored displacement [m] reaches this value "
                        "(empty: when the load factor reaches the stage's "
                        "end).",
                        Patterns::Anything());
      prm.add_parameter("Maximum steps",
                        max_path_steps,
                        "A path-controlled stage that has not reached its "
                        "end in this many steps stops the run (exit 2).",
                        Patterns::Integer(1));
      prm.add_parameter("Stop at critical point",
                        stop_at_critical,
                        "Stop the run (exit 0) at the first critical point "
                        "of a path-controlled stage, once located.");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    StaticLoadPath::parse_parameters(ParameterHandler &prm)
    {
      stepping.parse_parameters(prm);
      newton_solver.parse_parameters(prm);
      extrapolate         = extrapolation_name == "linear";
      const std::string p = "Load stepping/";
      check_input(control_names.size() == 1
                    || control_names.size() == stepping.n_stages(),
                  p + "Control",
                  "needs one entry, or one per stage ("
                    + std::to_string(stepping.n_stages()) + " stages in "
                    + "Stage end times), not "
                    + std::to_string(control_names.size()));
      controls.clear();
      for (const auto &c : control_names)
        controls.push_back(c == "load"         ? Control::load
                           : c == "arc-length" ? Control::arc_length
                                               : Control::displacement);
      has_target = !Utilities::trim(target_text).empty();
      if (has_target)
        {
          char        *end   = nullptr;
          const auto   text  = Utilities::trim(target_text);
          const double value = std::strtod(text.c_str(), &end);
          check_input(end != text.c_str() && *end == '\0'
                        && std::isfinite(value),
                      p + "Path following/Target monitor value",
                      "must be a finite number or empty, not '" + text + "'");
          target = value;
          check_input(control_of(stepping.n_stages() - 1) != Control::load,
                      p + "Path following/Target monitor value",
                      "applies to the last stage, which is under load "
                      "control (set Load stepping/Control)");
        }
    }

    bool
    StaticLoadPath::first_step_may_ramp(const unsigned int steps,
                                        const double       t_old,
                                        const Control      control) const
    {
      return initial_prestress == "automatic" && steps == 0 && t_old == 0.
             && control == Control::load
             && current.ramp_end <= current.ramp_start;
    }

    bool
    StaticLoadPath::ramp_initial_loads(Model                    &model,
                                       const ConditionalOStream &out)
    {
      const double t1 = stepping.stage_end(0);
      if (!model.ramp_initial_loads(0., t1))
        return false;
      current.ramp_start = 0.;
      current.ramp_end   = t1;
      out << "  the prestress acting at t = 0 grows with the loads of the "
             "first stage, to full at t = "
          << t1 << " (Load stepping/Initial prestress)" << std::endl;
      return true;
    }

    bool
    StaticLoadPath::follows_path() const
    {
      for (unsigned int s = 0; s < stepping.n_stages(); ++s)
        if (control_of(s) != Control::load)
          return true;
      return false;
    }

    LA::Vector
    StaticLoadPath::monitor_functional(const Model &model) const
    {
      const auto *membrane = model.find<membrane::MembraneSubsystem>();
      if (!membrane || monitor_point >= membrane->n_monitor_points())
        return LA::Vector();
      LA::Vector         w = model.make_field();
      const unsigned int c = monitor_component[0] - 'x';
      const auto         i = membrane->monitor_dof(monitor_point, c);
      if (i != numbers::invalid_dof_index)
        w[i] = 1.;
      w.compress(VectorOperation::insert);
      return w;
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
          const StabilityReport r = stability_judge(probe, true);
          if (!r.computed)
            break;
          (r.negative == before ? lo : hi) = mid;
        }
      model.reject_step(t_old);
      c.time    = 0.5 * (lo + hi);
      c.bracket = hi - lo;
      return c;
    }

    bool
    StaticLoadPath::switch_branch(Model                    &model,
                                  BorderedVector           &state,
                                  const double              t,
                                  const double              amplitude,
                                  StabilityReport          &stability,
                                  CriticalPoint            &c,
                                  const ConditionalOStream &out)
    {
      // The critical mode: the negative eigenvalue nearest zero (the one
      // that just crossed it).
      model.current_time = t;
      EigenParameters p;
      p.type              = "tangent";
      p.n_modes           = 1;
      p.write_modes       = false;
      const EigenResult e = EigenAnalysis::run(model, state, p);
      if (!e.computed || e.values.empty() || e.values[0] >= 0.)
        {
          out << "  branch switching: no critical mode ("
              << (e.computed ? "no negative eigenvalue" : e.error)
              << "); the path stays on the primary branch" << std::endl;
          return false;
        }
      LA::Vector phi(e.modes[0]);
      model.constraints().distribute(phi);
      phi /= phi.l2_norm();
      const ConditionalOStream quiet(std::cout, false);
      double                   xi = amplitude > 0. ? amplitude : 1e-3;
      for (unsigned int attempt = 0; attempt < 4; ++attempt, xi *= 3.)
        {
          BorderedVector probe(state);
          probe.field.add(xi, phi);
          const auto newton = newton_solver.solve(model, probe, quiet, false);
          if (!newton.converged || !model.check_state(probe).empty())
            continue;
          const StabilityReport r = stability_judge(probe, true);
          if (!r.computed || r.negative < 0 || r.negative >= stability.negative)
            continue;
          LA::Vector away(probe.field);
          away -= state.field;
          c.switched           = true;
          c.amplitude          = away.l2_norm();
          c.negative_secondary = r.negative;
          out << "  branch switching: along the critical mode (eigenvalue "
              << e.values[0] << " N/m), perturbation " << xi
              << ": on the secondary branch at |u - u_primary| = "
              << c.amplitude << ", negative eigenvalues " << stability.negative
              << " -> " << r.negative << std::endl;
          state     = probe;
          stability = r;
          return true;
        }
      out << "  branch switching: no perturbation up to " << xi / 3.
          << " along the critical mode left the primary branch; the path "
             "stays on it"
          << std::endl;
      return false;
    }

    CriticalPoint
    StaticLoadPath::locate_on_path(Model                 &model,
                                   PathConstraintProblem &problem,
                                   const BorderedVector  &last,
                                   const BorderedVector  &increment,
                                   const double           size,
                                   const LA::Vector      &w,
                                   const long long        before,
                                   const long long        after)
    {
      // Probes solve the constraint of a smaller size from the last
      // accepted state, predicted along the accepted increment; each is
      // judged and rejected.
      const ConditionalOStream quiet(std::cout, false);
      const double             t_old = PathConstraintProblem::load_factor(last);
      const auto               monitor = [&](const BorderedVector &x) {
        return monitor_value(w, x.field);
      };
      struct Probe
      {
        double r, tau, m;
      };
      BorderedVector end(last);
      end.add(1., increment);
      std::vector<Probe> probes = {{0., t_old, monitor(last)},
                                   {size,
                                    PathConstraintProblem::load_factor(end),
                                    monitor(end)}};
      CriticalPoint      c;
      c.before  = before;
      c.after   = after;
      double lo = 0., hi = size;
      while (std::abs(hi - lo) > locate_tolerance * std::abs(size)
             && c.probes < 40)
        {
          const double mid = 0.5 * (lo + hi);
          model.reject_step(t_old);
          BorderedVector x(last);
          x.add(mid / size, increment);
          BorderedVector    state      = PathConstraintProblem::model_part(x);
          const double      tau        = PathConstraintProblem::load_factor(x);
          const std::string impossible = model.begin_step(tau, state);
          ++c.probes;
          if (!impossible.empty())
            break;
          x = PathConstraintProblem::extend(state, tau);
          problem.set_size(mid);
          const auto newton = newton_solver.solve(problem, x, quiet, false);
          const BorderedVector probe = PathConstraintProblem::model_part(x);
          if (!newton.converged || !model.check_state(probe).empty())
            break;
          const StabilityReport r = stability_judge(probe, true);
          if (!r.computed)
            break;
          probes.push_back(
            {mid, PathConstraintProblem::load_factor(x), monitor(x)});
          (r.negative == before ? lo : hi) = mid;
        }
      problem.set_size(size);
      model.reject_step(t_old);
      std::sort(probes.begin(), probes.end(), [](const auto &a, const auto &b) {
        return a.r < b.r;
      });
      // The bracket [lo, hi] and its neighbours: the load factor rises
      // towards the bracket on one side and falls away on the other at a
      // limit point.
      unsigned int i_lo = 0, i_hi = probes.size() - 1;
      for (unsigned int i = 0; i < probes.size(); ++i)
        {
          if (probes[i].r == lo)
            i_lo = i;
          if (probes[i].r == hi)
            i_hi = i;
        }
      const Probe &a = probes[i_lo], &b = probes[i_hi];
      c.time    = 0.5 * (a.tau + b.tau);
      c.monitor = 0.5 * (a.m + b.m);
      c.bracket = std::abs(b.tau - a.tau);
      if (i_lo > 0 && i_hi + 1 < probes.size())
        {
          const double left  = probes[i_lo].tau - probes[i_lo - 1].tau;
          const double right = probes[i_hi + 1].tau - probes[i_hi].tau;
          c.type = left * right < 0. ? "limit point" : "bifurcation";
        }
      return c;
    }

    PathResult
    StaticLoadPath::run(Model                    &model,
                        const ConditionalOStream &out,
                        dealii::Timer            &wall_clock,
                        const Observer           &observer,
                        const PathResume         *resume)
    {
      PathResult result;
      double     t  = 0.;
      double     dt = stepping.initial(0);
      // Bergan's current stiffness parameter, per stage.
      double       stiffness_reference = 0., stiffness = 1.;
      unsigned int stiffness_stage = numbers::invalid_unsigned_int;
      if (resume)
        {
          const PathState &p           = resume->path;
          result.state                 = resume->state;
          step_increment               = resume->increment;
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
          model.ramp_initial_loads(p.ramp_start, p.ramp_end);
          previous_stability          = StabilityReport();
          previous_stability.computed = p.negative_eigenvalues >= 0;
          previous_stability.negative = p.negative_eigenvalues;
          result.critical_points      = p.critical_points;
        }
      else
        {
          // A new run: no ramp from an earlier one (refinement cycles).
          model.ramp_initial_loads(0., 0.);
          result.state       = model.initial_state();
          current            = PathState();
          step_increment     = BorderedVector();
          previous_stability = StabilityReport();
          current.increment  = dt;
          // Load stepping/Initial prestress = ramped: over the first step.
          if (initial_prestress == "ramped" && control_of(0) == Control::load)
            ramp_initial_loads(model, out);
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

      // Path following (solvers/path_following.h): the bordered problem,
      // the monitor, the last accepted increment (the secant predictor)
      // and a step forced to end a stage exactly.
      PathConstraintProblem problem(model, 1e-6 * stepping.end_time());
      const LA::Vector      w =
        follows_path() ? monitor_functional(model) : LA::Vector();
      const auto monitor = [&](const LA::Vector &field) {
        return monitor_value(w, field);
      };
      problem.set_monitor(w);
      // The path's tangent du/dt at the converged state, and |dR/dt|.
      const auto path_tangent = [&](double &force_rate) {
        BorderedVector state(result.state);
        model.begin_step(t, state);
        const BorderedVector tangent =
          problem.tangent(PathConstraintProblem::extend(state, t), force_rate);
        model.reject_step(t);
        return tangent;
      };
      const double psi2 = constraint_name == "spherical" ? 1. : 0.;
      // The secant predictor of a path-controlled stage (where
      // current.secant says it has one; a restart keeps it): the last
      // accepted step, extended by its change of the load factor.
      const auto secant = [&]() {
        return PathConstraintProblem::extend(step_increment,
                                             current.increment_dt);
      };

      enum class Forced
      {
        none,
        to_stage_end,
        to_target
      } forced       = Forced::none;
      bool path_done = false;

      // What the path-controlled stages need, checked before any step.
      for (unsigned int stage = 0; stage < stepping.n_stages(); ++stage)
        if (control_of(stage) != Control::load)
          {
            check_input(
              !model.prescribed_values_change(stepping.stage_start(stage),
                                              stepping.stage_end(stage)),
              "Load stepping/Control",
              "stage " + std::to_string(stage + 1)
                + " is path-controlled, but prescribed "
                  "displacements change in it: give them "
                  "their own load-controlled stage");
            check_input(control_of(stage) == Control::arc_length
                          || w.size() > 0,
                        "Load stepping/Path following/Monitor point",
                        "displacement control needs a monitor point "
                        "(Output/Monitor points)");
          }
      check_input(!has_target || w.size() > 0,
                  "Load stepping/Path following/Monitor point",
                  "a target monitor value needs a monitor point "
                  "(Output/Monitor points)");

      while (!path_done && (current.path_active || !stepping.finished(t)))
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
          const unsigned int stage =
            current.path_active ? current.path_stage : stepping.stage_of(t);
          const Control control = control_of(stage);
          const double  t_old   = t;
          last                  = result.state;
          // A step from the unstressed state may use Newton's continuation,
          // and is no increment to extrapolate.
          const bool from_unstressed = last.field.linfty_norm() == 0.;

          // Entering a path-controlled stage: its scales from the path's
          // tangent at the converged state.
          BorderedVector tangent;
          if (control != Control::load && !current.path_active)
            {
              const std::string entry = "Load stepping/Control";
              const std::string name  = "stage " + std::to_string(stage + 1);
              double            force_rate = 0.;
              tangent                      = path_tangent(force_rate);
              check_input(force_rate > 0.,
                          entry,
                          name
                            + " is path-controlled, but no load changes "
                              "in it (no load curve varies over its "
                              "pseudo times)");
              current.u_scale = tangent.field.l2_norm();
              check_input(current.u_scale > 0.
                            && std::isfinite(current.u_scale),
                          entry,
                          name
                            + ": the loads that change in it do not move "
                              "the structure");
              current.force_scale  = force_rate;
              current.monitor_rate = monitor(tangent.field);
              check_input(control != Control::displacement
                            || std::abs(current.monitor_rate)
                                 > 1e-9 * current.u_scale,
                          entry,
                          name
                            + " is under displacement control, but the "
                              "monitored component does not move with "
                              "its loads");
              current.path_active        = true;
              current.path_stage         = stage;
              current.arc_length         = 0.;
              current.path_steps         = 0;
              current.last_dtau          = 0.;
              current.limit_since_return = false;
              current.secant             = false;
              forced                     = Forced::none;
              dt                         = stepping.initial(stage);
              out << "Stage " << stage + 1 << " under "
                  << control_names[controls.size() == 1 ? 0 : stage]
                  << " control: |du/dt| = " << current.u_scale
                  << ", |dR/dt| = " << force_rate << std::endl;
            }

          const bool path_step =
            control != Control::load && forced != Forced::to_stage_end;
          double         t_new = 0.;
          NewtonResult   newton;
          BorderedVector x_last, x, predictor;
          bool           extrapolated = false;
          double         size         = 0.;
          if (!path_step)
            {
              // 1. Prepare the load step from the last converged state.
              t_new = forced == Forced::to_stage_end
                        ? stepping.stage_end(stage)
                        : stepping.next_time(t_old, dt);
              out << "Step " << result.steps + 1 << "  t = " << t_new
                  << "  dt = " << t_new - t_old << std::endl;
              // The predictor: the last step's increment scaled to this
              // one (before the step sets its prescribed values), within
              // a load-controlled stage (the loads' rates change at stage
              // ends: sealing, a new load). Its tolerance keeps the scale
              // of the last step's residual per unit pseudo time.
              double reference = 0.;
              if (extrapolate && !current.cut_back && current.increment_dt != 0.
                  && current.increment_load && current.increment_stage == stage
                  && step_increment.field.size() == result.state.field.size()
                  && step_increment.border.size() == result.state.border.size())
                {
                  const double factor = (t_new - t_old) / current.increment_dt;
                  result.state.field.add(factor, step_increment.field);
                  result.state.border.add(factor, step_increment.border);
                  reference = current.reference_rate * std::abs(t_new - t_old);
                  extrapolated = true;
                }
              const std::string impossible =
                model.begin_step(t_new, result.state);
              if (!impossible.empty())
                {
                  result.exit_code = 2;
                  result.message   = impossible
                                   + ". The last converged state (t = "
                                   + std::to_string(t_old) + ") is written.";
                  result.state = last;
                  model.reject_step(t_old);
                  break;
                }
              // 2. Solve.
              newton = newton_solver.solve(
                model, result.state, out, from_unstressed, reference);
            }
          else
            {
              // 1. The predictor: along the path's tangent at the start
              //    of the stage (or after a restart), else the secant (the
              //    last accepted increment), scaled to the constraint.
              x_last = PathConstraintProblem::extend(result.state, t_old);
              problem.set_scales(current.u_scale,
                                 psi2,
                                 current.force_scale,
                                 std::abs(current.monitor_rate));
              const bool by_displacement =
                control == Control::displacement || forced == Forced::to_target;
              BorderedVector direction;
              if (current.secant)
                direction = secant();
              else
                {
                  double force_rate = 0.;
                  if (tangent.field.size() == 0)
                    tangent = path_tangent(force_rate);
                  direction = PathConstraintProblem::extend(tangent, 1.);
                  if (current.last_dtau < 0.)
                    direction *= -1.;
                }
              double factor = 0.;
              if (by_displacement)
                {
                  const double sign =
                    has_target
                      ? (target >= monitor(result.state.field) ? 1. : -1.)
                      : (current.monitor_rate >= 0. ? 1. : -1.);
                  size               = forced == Forced::to_target
                                         ? target - monitor(result.state.field)
                                         : sign * dt * std::abs(current.monitor_rate);
                  const double along = monitor(direction.field);
                  factor             = along != 0. ? size / along : 0.;
                  problem.set_constraint(Control::displacement, x_last, size);
                }
              else
                {
                  size   = dt;
                  factor = dt / std::max(problem.arc_length(direction), 1e-300);
                  problem.set_constraint(Control::arc_length, x_last, size);
                }
              // The load factor changes by at most the maximum increment
              // per step; the arc length itself is free to grow where the
              // load hardly changes (past a limit or bifurcation point,
              // where the path's scale of the stage start is far too
              // small).
              const double dtau_predicted =
                factor * PathConstraintProblem::load_factor(direction);
              const auto shorten = [&](const double s) {
                dt *= s;
                size *= s;
                factor *= s;
                problem.set_size(size);
              };
              if (forced != Forced::to_target
                  && std::abs(dtau_predicted) > stepping.maximum(stage))
                shorten(stepping.maximum(stage) / std::abs(dtau_predicted));
              // Under displacement control the monitor's increment is
              // prescribed: a step that would pass the target ends on it
              // (under arc-length control only the solved step tells).
              if (control == Control::displacement && has_target
                  && forced == Forced::none && stage + 1 == stepping.n_stages())
                {
                  const double rest = target - monitor(result.state.field);
                  if (size * rest > 0. && std::abs(size) >= std::abs(rest))
                    {
                      shorten(rest / size);
                      size   = rest;
                      forced = Forced::to_target;
                      problem.set_size(size);
                    }
                }
              x = x_last;
              x.add(factor, direction);
              predictor = x;
              t_new     = PathConstraintProblem::load_factor(x);
              out << "Step " << result.steps + 1 << "  "
                  << (by_displacement ? "monitor increment " : "arc length ")
                  << size << "  predicted t = " << t_new << std::endl;
              BorderedVector    state = PathConstraintProblem::model_part(x);
              const std::string impossible = model.begin_step(t_new, state);
              if (!impossible.empty())
                {
                  newton.converged      = false;
                  newton.failure_reason = impossible;
                }
              else
                {
                  x = PathConstraintProblem::extend(state, t_new);
                  // 2. Solve the bordered system.
                  newton       = newton_solver.solve(problem, x, out, false);
                  result.state = PathConstraintProblem::model_part(x);
                  t_new        = PathConstraintProblem::load_factor(x);
                }
            }
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
          // A path step must go on along the path, and stops where its
          // stage ends: at the stage's end time or at the target (a step
          // that passes one is taken again to end there exactly).
          if (newton.converged && path_step)
            {
              BorderedVector step(x);
              step -= x_last;
              const double m_old = monitor(last.field),
                           m_new = monitor(result.state.field);
              if (current.secant && problem.dot(step, secant()) < 0.)
                {
                  newton.converged      = false;
                  newton.failure_reason = "the step turned back along the path";
                }
              else if (t_new > stepping.stage_end(stage)
                                 + 1e-12 * stepping.end_time())
                {
                  forced       = Forced::to_stage_end;
                  result.state = last;
                  model.reject_step(t_old);
                  out << "  past the stage's end (t = " << t_new
                      << "): the step is taken again to t = "
                      << stepping.stage_end(stage) << std::endl;
                  continue;
                }
              else if (has_target && forced != Forced::to_target
                       && stage + 1 == stepping.n_stages()
                       && (m_new - target) * (m_old - target) < 0.)
                {
                  forced       = Forced::to_target;
                  result.state = last;
                  model.reject_step(t_old);
                  out << "  past the target (monitor " << m_new
                      << "): the step is taken again to " << target
                      << std::endl;
                  continue;
                }
            }

          // The stability of the converged state, before it is committed;
          // a change of the count is located between the two states.
          StabilityReport stability;
          bool            limit_located = false, switched = false;
          if (newton.converged && stability_judge)
            {
              stability = stability_judge(result.state, false);
              // A change counted on Newton's factorization (the tangent
              // of the last iterate) is confirmed on the state's own.
              if (stability.from_newton && previous_stability.computed
                  && stability.negative != previous_stability.negative)
                stability = stability_judge(result.state, true);
              // A change of the count after an extrapolated start may be
              // the extrapolation's: past a critical point it can reach
              // another equilibrium (a crumpled balloon, thousands of
              // negative eigenvalues). The step is taken again from the
              // converged state.
              if (extrapolated && stability.computed
                  && previous_stability.computed
                  && stability.negative != previous_stability.negative)
                {
                  out << "  (the stability count changed after the "
                         "extrapolated start: the step is taken again "
                         "from the last converged state)"
                      << std::endl;
                  result.state     = last;
                  current.cut_back = true;
                  model.reject_step(t_old);
                  continue;
                }
              if (locate_tolerance > 0. && stability.computed
                  && stability.energy_form && previous_stability.computed
                  && previous_stability.energy_form
                  && stability.negative != previous_stability.negative)
                {
                  const BorderedVector accepted(result.state);
                  CriticalPoint        c;
                  if (path_step)
                    {
                      BorderedVector increment(x);
                      increment -= x_last;
                      c             = locate_on_path(model,
                                         problem,
                                         x_last,
                                         increment,
                                         size,
                                         w,
                                         previous_stability.negative,
                                         stability.negative);
                      limit_located = c.type == "limit point";
                    }
                  else
                    {
                      c         = locate(model,
                                 last,
                                 t_old,
                                 t_new,
                                 previous_stability.negative,
                                 stability.negative);
                      c.monitor = monitor(result.state.field);
                    }
                  c.step = result.steps + 1;
                  // Back to the accepted state: prepare the step exactly
                  // as before the probes (the same prescribed values,
                  // contact candidates and border scales that the
                  // accepted state was solved with), then judge it again
                  // (an assembly at it: its friction state).
                  BorderedVector again =
                    path_step ? PathConstraintProblem::model_part(predictor)
                              : last;
                  model.begin_step(path_step
                                     ? PathConstraintProblem::load_factor(
                                       predictor)
                                     : t_new,
                                   again);
                  result.state       = accepted;
                  model.current_time = t_new;
                  stability          = stability_judge(result.state, true);
                  out << "  critical point: " << c.type << " at t = " << c.time
                      << " (+-" << 0.5 * c.bracket << "), negative eigenvalues "
                      << c.before << " -> " << c.after << ", " << c.probes
                      << " probes" << std::endl;
                  // The first bifurcation: onto the secondary branch.
                  const bool first_bifurcation =
                    std::none_of(result.critical_points.begin(),
                                 result.critical_points.end(),
                                 [](const CriticalPoint &p) {
                                   return p.type == "bifurcation";
                                 });
                  if (branch_switching && c.type == "bifurcation"
                      && first_bifurcation)
                    {
                      LA::Vector step_field(result.state.field);
                      step_field -= last.field;
                      switched = switch_branch(model,
                                               result.state,
                                               t_new,
                                               step_field.l2_norm(),
                                               stability,
                                               c,
                                               out);
                    }
                  result.critical_points.push_back(c);
                }
            }

          // The automatic first step: a first state that is unstable
          // under the full initial prestress (a tube crushed by a cable
          // before it is inflated) is taken again with the prestress
          // growing over the first stage.
          if (newton.converged && stability.computed && stability.negative > 0
              && first_step_may_ramp(result.steps, t_old, control)
              && ramp_initial_loads(model, out))
            {
              out << "  (the first state was unstable under the full "
                     "prestress: the step is taken again)"
                  << std::endl;
              result.state = last;
              model.reject_step(t_old);
              continue;
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
              current.cut_back = true;
              result.state     = last;
              model.reject_step(t_old);
              const double tried =
                control != Control::load ? dt : t_new - t_old;
              // An exact end that could not be reached from here: go on along
              // the path with a shorter step.
              forced = Forced::none;
              dt     = stepping.cut(tried);
              out << "  Newton failed (" << newton.failure_reason
                  << "); cutting back to "
                  << (control != Control::load ? "a step of " : "dt = ") << dt
                  << std::endl;
              // The automatic first step: a cut back does not reduce the
              // loads that act in full from t = 0; from now on they grow
              // with the others over the first stage.
              if (first_step_may_ramp(result.steps, t_old, control))
                ramp_initial_loads(model, out);
              if (dt < stepping.minimum())
                {
                  std::ostringstream msg;
                  msg << "the load step could not be completed at t = " << t_old
                      << " even with the minimum increment "
                      << stepping.minimum() << " (" << newton.failure_reason
                      << ")";
                  if (stiffness < limit_point_stiffness
                      && control == Control::load)
                    msg << "; a limit point was reached: the current "
                           "stiffness parameter fell to "
                        << stiffness
                        << ", so the load cannot grow further under load "
                           "control (use Load stepping/Control = arc-length, "
                           "or volume or gas-amount control)";
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
          current.cut_back = false;
          // The increment the next step's predictor extrapolates: after a
          // load-controlled step, not across a branch switch, nor from the
          // unstressed state (a membrane's first response, w ~ p^(1/3),
          // extrapolated linearly overshoots).
          step_increment = result.state;
          step_increment.field -= last.field;
          step_increment.border -= last.border;
          current.increment_dt = t_new - t_old;
          current.reference_rate =
            newton.reference / std::max(std::abs(t_new - t_old), 1e-300);
          current.increment_stage = stage;
          current.increment_load  = !path_step && !switched && !from_unstressed;
          t                       = t_new;
          ++result.steps;
          model.current_time = t_new;
          model.commit_step(t_new, result.state);
          result.step_iterations.push_back(newton.iterations);
          result.last_residual_history = newton.residual_history;
          result.residual_histories.push_back(newton.residual_history);
          const double ratio =
            std::abs(t_new - t_old)
            / std::max(step_increment.field.l2_norm(), 1e-300);
          if (stage != stiffness_stage)
            {
              stiffness_stage     = stage;
              stiffness_reference = ratio;
            }
          stiffness           = ratio / stiffness_reference;
          double     step_arc = 0.;
          const auto reached  = forced;
          forced              = Forced::none;
          if (current.path_active)
            {
              // The path's record: the secant, the arc length, and the
              // load factor turning back (a limit point, if no stability
              // check located it).
              step_arc = problem.arc_length(
                PathConstraintProblem::extend(step_increment, t_new - t_old));
              current.arc_length += step_arc;
              ++current.path_steps;
              const double dtau = t_new - t_old;
              if (limit_located)
                current.limit_since_return = true;
              if (current.last_dtau * dtau < 0.)
                {
                  if (!current.limit_since_return)
                    {
                      CriticalPoint c;
                      c.type    = "limit point";
                      c.step    = result.steps;
                      c.time    = std::max(t_old, t_new);
                      c.bracket = std::abs(dtau);
                      c.monitor = monitor(last.field);
                      c.before = c.after = previous_stability.negative;
                      result.critical_points.push_back(c);
                      out << "  limit point: the load factor turned back "
                             "near t = "
                          << t_old << std::endl;
                    }
                  current.limit_since_return = false;
                }
              if (dtau != 0.)
                current.last_dtau = dtau;
              // After a branch switch the next predictor is the tangent
              // of the secondary branch, not the secant across branches.
              if (switched)
                current.secant = false;
              else if (reached == Forced::none)
                current.secant = true;
            }
          out << "  converged in " << newton.iterations << " iterations ("
              << newton.convergence_test << "), wall " << std::fixed
              << std::setprecision(2) << wall_clock.wall_time() << " s"
              << std::defaultfloat << std::setprecision(6) << std::endl;
          dt =
            path_step
              ? stepping.grown(dt, newton.iterations, false, t_new)
              : stepping.grown(t_new - t_old, newton.iterations, true, t_new);
          PathStep report{result.steps,
                          t_new,
                          newton.iterations,
                          newton.convergence_test,
                          stiffness,
                          stability};
          report.load_factor =
            (t_new - stepping.stage_start(stage))
            / (stepping.stage_end(stage) - stepping.stage_start(stage));
          report.arc_length = current.path_active ? current.arc_length : 0.;
          // Where a path-controlled stage ends.
          std::string end_message;
          if (current.path_active)
            {
              if (reached == Forced::to_stage_end)
                {
                  current.path_active = false;
                  current.secant      = false;
                  dt = stepping.initial(stepping.stage_of(t_new));
                }
              else if (reached == Forced::to_target)
                {
                  path_done   = true;
                  end_message = "the monitored displacement reached its "
                                "target "
                                + std::to_string(target);
                }
              else if (stop_at_critical && !result.critical_points.empty()
                       && result.critical_points.back().step == result.steps)
                {
                  path_done = true;
                  end_message =
                    "stopped at the first critical point (a "
                    + result.critical_points.back().type + " at t = "
                    + std::to_string(result.critical_points.back().time)
                    + ") as asked (Load stepping/Path following/Stop at "
                      "critical point)";
                }
              else if (current.path_steps >= max_path_steps)
                {
                  result.exit_code = 2;
                  std::ostringstream msg;
                  msg << "stage " << stage + 1 << " did not reach its end ("
                      << (has_target && stage + 1 == stepping.n_stages()
                            ? "the target monitor value "
                                + std::to_string(target) + " or "
                            : std::string())
                      << "t = " << stepping.stage_end(stage) << ") in "
                      << max_path_steps
                      << " steps (Load stepping/Path following/Maximum "
                         "steps); the load factor is at t = "
                      << t_new << ". The last converged state is written.";
                  end_message = msg.str();
                  path_done   = true;
                }
            }
          snapshot();
          observer(report, result.state);
          if (path_done)
            {
              result.message = end_message;
              break;
            }
          if (stop_step > 0 && result.steps >= stop_step
              && (current.path_active || !stepping.finished(t)))
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
