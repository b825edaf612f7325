#include <pneuma/core/capabilities.h>
#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/newton_solver.h>
#include <pneuma/strategies/dynamic_relaxation/dynamic_relaxation.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/stability_monitor.h>
#include <pneuma/strategies/stages.h>

#include <csignal>
#include <iomanip>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;

    void
    DynamicRelaxation::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Dynamic relaxation");
      prm.add_parameter("Maximum iterations",
                        settings.max_iterations,
                        "Iterations (fictitious time steps) of one stage's "
                        "relaxation before it gives up (exit 2, the last "
                        "converged state written).",
                        Patterns::Integer(1));
      prm.add_parameter("Residual tolerance",
                        settings.residual_tolerance,
                        "The relaxation has converged when |r| <= this "
                        "times |r_ref| (Newton's reference: the larger of "
                        "the first residual and the loads) and the kinetic "
                        "energy has died out (Kinetic energy tolerance). "
                        "With Finish with Newton, the hand-over to Newton.",
                        Patterns::Double(0.));
      prm.add_parameter("Kinetic energy tolerance",
                        settings.kinetic_energy_tolerance,
                        "The kinetic energy of the last step must also be "
                        "below this fraction of its largest peak.",
                        Patterns::Double(0.));
      prm.add_parameter("Mass safety factor",
                        settings.safety,
                        "s in the fictitious mass M_i = s/4 max over the "
                        "node of sum_j |K_ij| (2: Barnes; at least 1, the "
                        "limit of stability by Gershgorin's bound).",
                        Patterns::Double(1.));
      prm.add_parameter("Finish with Newton",
                        settings.finish_with_newton,
                        "Newton finishes each stage from the relaxed state "
                        "(to the tolerances of the Newton subsection); if "
                        "it fails, the relaxation goes on to a 100 times "
                        "smaller residual and hands over again (three "
                        "times at most).",
                        Patterns::Bool());
      prm.add_parameter("Progress interval",
                        settings.print_every,
                        "Print a progress row every this many iterations.",
                        Patterns::Integer(1));
      prm.leave_subsection();
    }

    void
    DynamicRelaxation::parse_parameters(ParameterHandler &,
                                        const Stages &stages)
    {
      used = stages.uses("relaxation");
      check_input(settings.residual_tolerance > 0.
                    && settings.residual_tolerance < 1.,
                  "Dynamic relaxation/Residual tolerance",
                  "must be in (0, 1), got "
                    + std::to_string(settings.residual_tolerance));
      check_input(settings.kinetic_energy_tolerance < 1.,
                  "Dynamic relaxation/Kinetic energy tolerance",
                  "must be below 1, got "
                    + std::to_string(settings.kinetic_energy_tolerance));
    }

    void
    DynamicRelaxation::check(Model &model) const
    {
      // The border unknowns must follow the field without Newton.
      if (!used)
        return;
      for (const auto &s : model.all())
        check_input(s->n_border_unknowns() == 0
                      || dynamic_cast<const BorderFromField *>(s.get()),
                    "Load stepping/Strategy",
                    "the relaxation cannot follow the border unknowns of "
                    "the "
                      + s->name()
                      + " (they have no value for a given field); use "
                        "static");
    }

    Outcome
    DynamicRelaxation::run(Run           &run,
                           const Segment &segment,
                           const Outcome &from)
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
      for (unsigned int s = segment.first; s <= segment.last; ++s)
        {
          const double t = run.stages.end(s);
          // A restart continues after the stages it has done.
          if (run.stages.finished(result.time, t))
            continue;
          if (const int signal = interrupt_signal(model.mpi_communicator()))
            {
              result.exit_code = 128 + signal;
              result.message   = std::string("interrupted by ")
                               + (signal == SIGINT ? "SIGINT" : "SIGTERM");
              break;
            }
          run.out << "stage " << s + 1 << ": dynamic relaxation at t = " << t
                  << std::endl;
          BorderedVector state = result.state;
          StepReport     report;
          std::string    message;
          if (!solve_stage(run, state, t, report, message))
            {
              model.reject_step(result.time);
              result.exit_code = 2;
              result.message   = message + ". The last converged state (t = "
                               + std::to_string(result.time) + ") is written.";
              break;
            }
          accept(run, state, t, report);
          result.state = state;
          result.time  = t;
          if (run.stop_requested() && s < segment.last)
            {
              result.message = run.stop_message();
              result.stop    = true;
              break;
            }
        }
      model.refresh(result.state);
      return result;
    }

    void
    DynamicRelaxation::accept(Run                  &run,
                              const BorderedVector &state,
                              const double          t,
                              StepReport           &report) const
    {
      RunCounters &counters = run.counters;
      ++counters.steps;
      run.model.commit_step(t, state);
      counters.step_iterations.push_back(report.iterations);
      report.step        = counters.steps;
      report.time        = t;
      report.load_factor = 1.;
      run.out << "  converged in " << report.iterations << " iterations ("
              << report.convergence_test << "), wall " << std::fixed
              << std::setprecision(2) << run.wall_clock.wall_time() << " s"
              << std::defaultfloat << std::setprecision(6) << std::endl;
      // Resumable before the report, which may write a checkpoint.
      run.mark_resumable();
      run.report(report, state);
    }

    bool
    DynamicRelaxation::solve_stage(Run            &run,
                                   BorderedVector &state,
                                   const double    t,
                                   StepReport     &report,
                                   std::string    &message)
    {
      Model &model = run.model;
      message      = model.begin_step(t, state);
      if (!message.empty())
        return false;
      double tolerance = settings.residual_tolerance;
      bool   by_newton = false;
      for (unsigned int attempt = 0;; ++attempt)
        {
          const Result r = relax(run, state, t, tolerance);
          total_iterations += r.iterations;
          total_resets += r.resets;
          report.iterations += r.iterations;
          if (!r.converged)
            {
              message = "the dynamic relaxation failed: " + r.failure;
              return false;
            }
          report.convergence_test = "dynamic relaxation";
          if (!settings.finish_with_newton)
            break;
          BorderedVector polished = state;
          const auto     newton =
            run.newton.solve(model, polished, run.out, false, r.reference);
          newton_iterations += newton.iterations;
          run.counters.newton_iterations += newton.iterations;
          if (newton.converged)
            {
              state     = polished;
              by_newton = true;
              report.convergence_test =
                "relaxation, then Newton: " + newton.convergence_test;
              break;
            }
          if (attempt == 2)
            {
              message = "Newton failed from the relaxed state three times ("
                        + newton.failure_reason + ")";
              return false;
            }
          tolerance *= 1e-2;
          run.out << "  Newton failed from the relaxed state ("
                  << newton.failure_reason
                  << "); relaxing on to |r|/|r_ref| = " << tolerance
                  << std::endl;
        }
      message = model.check_state(state);
      if (!message.empty())
        return false;
      if (run.stability)
        report.stability = run.stability->judge(model, state, t, !by_newton);
      return true;
    }

    void
    DynamicRelaxation::add_summary(Statistics &row) const
    {
      const auto             run    = StatisticsGroup::run();
      constexpr unsigned int counts = Statistics::summary;
      row.add_count(run, "relaxation_iterations", total_iterations, counts);
      row.add_count(run, "relaxation_resets", total_resets, counts);
      row.add_count(run,
                    "relaxation_newton_iterations",
                    newton_iterations,
                    counts);
    }

    void
    DynamicRelaxation::save_summary(Checkpoint &checkpoint) const
    {
      checkpoint.put("relaxation/iterations", total_iterations);
      checkpoint.put("relaxation/resets", total_resets);
      checkpoint.put("relaxation/newton_iterations", newton_iterations);
    }

    void
    DynamicRelaxation::load_summary(const Checkpoint &checkpoint)
    {
      total_iterations = checkpoint.get<unsigned int>("relaxation/iterations");
      total_resets     = checkpoint.get<unsigned int>("relaxation/resets");
      newton_iterations =
        checkpoint.get<unsigned int>("relaxation/newton_iterations");
    }

    PNEUMA_REGISTER_STRATEGY(DynamicRelaxation,
                             "relaxation",
                             Placement::stage,
                             "dynamic relaxation with kinetic damping at "
                             "each stage's end, finished by Newton");
  } // namespace strategies
} // namespace pneuma
