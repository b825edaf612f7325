#include <pneuma/core/capabilities.h>
#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/core/statistics.h>
#include <pneuma/strategies/explicit_dynamics/explicit_dynamics.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/stages.h>

#include <cmath>
#include <csignal>
#include <sstream>
#include <tuple>
#include <utility>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;


    std::string
    as_text(const double x)
    {
      std::ostringstream out;
      out << x;
      return out.str();
    }

    void
    ExplicitDynamics::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Explicit dynamics");
      prm.add_parameter("Time step",
                        settings.time_step,
                        "The time step [s]; 0: the stable step estimate "
                        "times the safety factor, estimated again every "
                        "Estimate interval steps. A step above the stable "
                        "one is refused.",
                        Patterns::Double(0.));
      prm.add_parameter("Time step safety factor",
                        settings.safety,
                        "The automatic step is this fraction of the stable "
                        "step estimate 2/omega_max (Gershgorin's bound).",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Mass scaling time step",
                        settings.mass_scaling_step,
                        "Mass scaling (LS-DYNA's DT2MS): the step [s] to "
                        "reach by adding mass to the unknowns whose stable "
                        "step (Gershgorin's row bound) is shorter, at every "
                        "estimate; the added mass fraction is reported "
                        "(history and summary). It slows the stiff parts' "
                        "motion: compare with a run without it. 0: off.",
                        Patterns::Double(0.));
      prm.add_parameter("Estimate interval",
                        settings.estimate_every,
                        "Steps between two estimates of the stable step "
                        "(each assembles the tangent once).",
                        Patterns::Integer(1));
      prm.add_parameter("Damping ratio",
                        settings.damping_ratio,
                        "zeta of mass-proportional damping alpha M, alpha = "
                        "2 zeta omega at the Damping frequency.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Damping frequency",
                        settings.damping_frequency,
                        "f [Hz] at which the Damping ratio holds; 0: the "
                        "lowest natural frequency of the state each "
                        "explicit stage starts from (a modal analysis "
                        "there, printed).",
                        Patterns::Double(0.));
      prm.add_parameter("Output interval",
                        settings.output_interval,
                        "A history row (and VTU) every this much time [s]; "
                        "0: at each stage's end only.",
                        Patterns::Double(0.));
      prm.add_parameter("Maximum steps",
                        settings.max_steps,
                        "A stage that needs more steps (estimated before it "
                        "starts) is refused.",
                        Patterns::Integer(1));
      prm.add_parameter("Progress interval",
                        settings.print_every,
                        "Print a progress row every this many steps.",
                        Patterns::Integer(1));
      prm.leave_subsection();
    }

    void
    ExplicitDynamics::parse_parameters(ParameterHandler &, const Stages &stages)
    {
      used = stages.uses("explicit");
      check_input(settings.safety > 0.,
                  "Explicit dynamics/Time step safety factor",
                  "must be positive");
      damping_frequency = settings.damping_frequency;
      alpha = 4. * M_PI * settings.damping_ratio * damping_frequency;
    }

    void
    ExplicitDynamics::check(Model &model) const
    {
      if (!used)
        return;
      for (const auto &s : model.all())
        check_input(s->n_border_unknowns() == 0
                      || dynamic_cast<const BorderFromField *>(s.get()),
                    "Load stepping/Strategy",
                    "explicit dynamics cannot follow the border unknowns "
                    "of the "
                      + s->name() + " (they have no value for a given field)");
      const LA::Vector m        = model.lumped_mass();
      const auto      &c        = model.constraints();
      unsigned int     massless = 0;
      for (const auto row : model.locally_owned())
        if (!c.is_constrained(row) && !(m[row] > 0.))
          ++massless;
      massless = Utilities::MPI::sum(massless, model.mpi_communicator());
      check_input(massless == 0,
                  "Load stepping/Strategy",
                  "explicit dynamics needs a mass on every free unknown; "
                    + std::to_string(massless)
                    + " have none (give every membrane region and cable a "
                      "Density)");
    }

    Outcome
    ExplicitDynamics::run(Run &run, const Segment &segment, const Outcome &from)
    {
      Model  &model = run.model;
      Outcome result;
      if (from.state.field.size() > 0)
        {
          result.state = from.state;
          result.time  = from.time;
        }
      else
        {
          model.ramp_initial_loads(0., 0.);
          result.state = model.initial_state();
          run.report(StepReport{}, result.state);
        }
      // The lumped mass, zero on constrained dofs (they follow their
      // prescribed values), and its inverse (a restart restores the
      // scaled one); at rest unless a restart restored the motion.
      mass = model.lumped_mass();
      for (const auto row : model.locally_owned())
        if (model.constraints().is_constrained(row))
          mass[row] = 0.;
      mass.compress(VectorOperation::insert);
      if (!resumed)
        set_inverse_mass(mass);
      if (!resumed)
        {
          motion                = Motion();
          motion.velocity       = result.state;
          motion.velocity.field = 0.;
          motion.velocity.border.reinit(0);
          motion.increment = motion.velocity;
        }
      previous_increment   = motion.increment.field;
      bool resuming        = resumed;
      resumed              = false;
      BorderedVector x     = result.state;
      double         t     = result.time;
      const double   every = settings.output_interval;
      for (unsigned int s = segment.first; s <= segment.last; ++s)
        {
          const double t_end = run.stages.end(s);
          if (run.stages.finished(t, t_end))
            continue;
          run.out << "stage " << s + 1 << ": explicit dynamics to t = " << t_end
                  << std::endl;
          const std::string start = begin_stage(run, x, t, t_end, s, resuming);
          resuming                = false;
          if (!start.empty())
            {
              result.exit_code = 2;
              result.message   = "explicit dynamics failed: " + start;
              return result;
            }
          while (!run.stages.finished(t, t_end))
            {
              const double next =
                every > 0.
                  ? std::min(t_end, every * (std::floor(t / every + 1e-9) + 1.))
                  : t_end;
              const std::string failure = integrate(run, x, t, next);
              if (const int signal = interrupt_signal(model.mpi_communicator()))
                {
                  accept(run, x, t);
                  result.exit_code = 128 + signal;
                  result.message   = std::string("interrupted by ")
                                   + (signal == SIGINT ? "SIGINT" : "SIGTERM");
                  result.state = x;
                  result.time  = t;
                  return result;
                }
              if (!failure.empty())
                {
                  model.reject_step(result.time);
                  result.exit_code = 2;
                  result.message   = "explicit dynamics failed: " + failure
                                   + ". The last reported state (t = "
                                   + as_text(result.time) + ") is written.";
                  model.refresh(result.state);
                  return result;
                }
              accept(run, x, t);
              result.state = x;
              result.time  = t;
              if (run.stop_requested())
                {
                  result.message = run.stop_message();
                  result.stop    = true;
                  return result;
                }
            }
        }
      model.refresh(result.state);
      return result;
    }

    std::string
    ExplicitDynamics::begin_stage(Run               &run,
                                  BorderedVector    &x,
                                  const double       t,
                                  const double       t_end,
                                  const unsigned int stage,
                                  const bool         resuming)
    {
      Model            &model = run.model;
      const std::string error = model.begin_step(t, x);
      if (!error.empty())
        return error;
      // A restart inside the stage goes on with the checkpoint's estimate
      // (the same steps as the run it continues).
      if (model.n_border() > 0)
        x.border = model.border_for(x.field, t);
      if (!resuming && settings.damping_ratio > 0.
          && settings.damping_frequency == 0.)
        damp_lowest_mode(run, x, t);
      if (!resuming)
        motion.stable_step = estimate_step(model, x, t);
      else
        {
          residual = x;
          model.assemble_residual(x, t, residual);
        }
      // The run's first stable step judges the input's Time step; later
      // ones the state's (integrate(): exit 2).
      check_input(settings.time_step <= motion.stable_step
                    || total_estimates > 1,
                  "Explicit dynamics/Time step",
                  "the time step " + as_text(settings.time_step)
                    + " s is above the stable step "
                    + as_text(motion.stable_step) + " s (the estimate "
                    + "2/omega_max at the start, t = " + as_text(t) + ")");
      const double dt     = settings.time_step > 0.
                              ? settings.time_step
                              : settings.safety * motion.stable_step;
      const double needed = (t_end - t) / dt;
      check_input(needed <= settings.max_steps,
                  "Explicit dynamics/Maximum steps",
                  "stage " + std::to_string(stage + 1)
                    + " (to t = " + as_text(t_end) + ") needs about "
                    + std::to_string(static_cast<long long>(std::ceil(needed)))
                    + " steps of " + as_text(dt)
                    + " s (the stable step estimate at t = " + as_text(t)
                    + " is " + as_text(motion.stable_step) + " s), more than "
                    + std::to_string(settings.max_steps));
      run.out << "  stable time step " << motion.stable_step
              << " s (Gershgorin), step " << dt << " s, about "
              << static_cast<long long>(std::ceil(needed)) << " steps";
      if (settings.mass_scaling_step > 0.)
        run.out << "; mass scaling added " << 100. * motion.added_mass
                << " % of the mass";
      run.out << std::endl;
      stage_end         = t_end;
      stage_start_wall  = run.wall_clock.wall_time();
      stage_start_steps = motion.steps;
      return "";
    }

    void
    ExplicitDynamics::accept(Run &run, const BorderedVector &x, const double t)
    {
      RunCounters &counters = run.counters;
      ++counters.steps;
      StepReport report;
      report.step             = counters.steps;
      report.time             = t;
      report.iterations       = motion.steps - steps_at_report;
      report.convergence_test = "explicit";
      report.load_factor      = 1.;
      steps_at_report         = motion.steps;
      counters.step_iterations.push_back(report.iterations);
      run.mark_resumable();
      run.report(report, x);
    }

    void
    ExplicitDynamics::add_history(Statistics       &row,
                                  const StepReport &report,
                                  const BorderedVector &,
                                  Run &run)
    {
      if (!used)
        return;
      const auto     g   = StatisticsGroup::run();
      constexpr auto use = Statistics::history;
      row.add(g, "kinetic_energy", "J", motion.kinetic, use);
      row.add(g, "residual_work", "J", motion.work, use);
      row.add(g, "damping_energy", "J", motion.damping, use);
      row.add(g, "energy_balance_error", "", motion.balance_error(), use);
      row.add(g, "stable_time_step", "s", motion.stable_step, use);
      if (settings.mass_scaling_step > 0.)
        row.add(g, "added_mass_fraction", "", motion.added_mass, use);
      if (settings.damping_ratio > 0.)
        row.add(g, "damping_frequency", "Hz", damping_frequency, use);
      // A static stage's state has no inertia.
      const auto [inertial, damping] =
        report.convergence_test == "explicit"
          ? resultant_forces(run.model)
          : std::pair<std::array<double, 3>, std::array<double, 3>>();
      row.add_vector(g, "inertial_force", "N", inertial, use);
      if (settings.damping_ratio > 0.)
        row.add_vector(g, "damping_force", "N", damping, use);
      // With chambers: the largest relative error of the border
      // constraints (prescribed volumes) at the steps since the last row.
      if (run.model.n_border() > 0)
        row.add(g, "constraint_error", "", motion.constraint_error, use);
      motion.constraint_error = 0.;
    }

    void
    ExplicitDynamics::add_summary(Statistics &row) const
    {
      if (!used)
        return;
      const auto             g      = StatisticsGroup::run();
      constexpr unsigned int counts = Statistics::summary;
      row.add_count(g, "explicit_steps", total_steps, counts);
      row.add_count(g, "explicit_step_estimates", total_estimates, counts);
      row.add(g, "explicit_smallest_step", "s", smallest_step, counts);
      if (settings.mass_scaling_step > 0.)
        row.add(g, "largest_added_mass_fraction", "", largest_added, counts);
      if (settings.damping_ratio > 0.)
        row.add(g, "damping_frequency", "Hz", damping_frequency, counts);
      row.add(g, "kinetic_energy", "J", motion.kinetic, counts);
      row.add(g, "energy_balance_error", "", motion.balance_error(), counts);
    }

    void
    ExplicitDynamics::save_checkpoint(
      Checkpoint                          &checkpoint,
      std::vector<const BorderedVector *> &vectors) const
    {
      checkpoint.put("explicit/motion", motion);
      checkpoint.put("explicit/damping",
                     std::make_pair(alpha, damping_frequency));
      vectors.push_back(&motion.velocity);
      vectors.push_back(&motion.increment);
      checkpoint_mass.field = inverse_mass;
      vectors.push_back(&checkpoint_mass);
    }

    void
    ExplicitDynamics::load_checkpoint(const Checkpoint            &checkpoint,
                                      std::vector<BorderedVector> &vectors)
    {
      motion = checkpoint.get<Motion>("explicit/motion");
      std::tie(alpha, damping_frequency) =
        checkpoint.get<std::pair<double, double>>("explicit/damping");
      AssertThrow(vectors.size() >= 3, ExcInternalError());
      motion.velocity  = std::move(vectors[0]);
      motion.increment = std::move(vectors[1]);
      inverse_mass     = std::move(vectors[2].field);
      steps_at_report  = motion.steps;
      resumed          = true;
    }

    void
    ExplicitDynamics::save_summary(Checkpoint &checkpoint) const
    {
      checkpoint.put("explicit/steps", total_steps);
      checkpoint.put("explicit/largest_added_mass", largest_added);
      checkpoint.put("explicit/estimates", total_estimates);
      checkpoint.put("explicit/smallest_step", smallest_step);
    }

    void
    ExplicitDynamics::load_summary(const Checkpoint &checkpoint)
    {
      total_steps     = checkpoint.get<unsigned int>("explicit/steps");
      largest_added   = checkpoint.get<double>("explicit/largest_added_mass");
      total_estimates = checkpoint.get<unsigned int>("explicit/estimates");
      smallest_step   = checkpoint.get<double>("explicit/smallest_step");
    }

    PNEUMA_REGISTER_STRATEGY(ExplicitDynamics,
                             "explicit",
                             Placement::stage,
                             "explicit dynamics in real time: central "
                             "differences with the lumped mass");
  } // namespace strategies
} // namespace pneuma
