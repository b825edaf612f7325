/**
 * @file
 * What the Simulator records of a run: the observer of every converged
 * state (history.csv, VTU, checkpoints) and the summary.
 */

#include <deal.II/base/utilities.h>

#include "simulator_impl.h"

namespace pneuma
{
  using namespace dealii;

  void
  Simulator::Impl::record(strategies::Run               &run,
                          const strategies::StepReport  &step,
                          const solvers::BorderedVector &state)
  {
    last_step = step;
    last_seen = state;
    history.push_back(history_row(run, step, state));
    collectively([&]() { output.history_row(history.back()); },
                 output.directory() + "/history.csv");
    if (output.write_vtu()
        && (step.step == 0
            || (output.vtu_interval() > 0
                && step.step % output.vtu_interval() == 0)))
      write_vtu(step.step, step.time, state);
    if (step.step > 0
        && checkpoints.due(step.step, since_checkpoint.wall_time() / 60.))
      save_checkpoint(run, state, step.time);
  }

  Statistics
  Simulator::Impl::history_row(strategies::Run               &run,
                               const strategies::StepReport  &step,
                               const solvers::BorderedVector &state)
  {
    Statistics row;
    const auto g = StatisticsGroup::run();
    row.add_count(g, "step", step.step, Statistics::history);
    row.add(g, "time", "", step.time, Statistics::history);
    row.add_count(g, "newton_iterations", step.iterations, Statistics::history);
    row.add(g, "wall_seconds", "s", wall_time(), Statistics::history);
    // The columns of the stages' strategies, the model's state, its
    // stability, then the analyses of the state.
    for (const auto &e : strategies::strategy_entries())
      if (e.placement == strategies::Placement::stage && stages.uses(e.name))
        strategies.at(e.name)->add_history(row, step, state, run);
    model.add_statistics(row, state, step.time);
    if (stability.enabled())
      stability.add_history(row, step, pcout);
    for (const auto &[name, strategy] :
         enabled(strategies::Placement::after_stages))
      strategy->add_history(row, step, state, run);
    row.reduce(comm);
    return row;
  }

  void
  Simulator::Impl::write_vtu(const unsigned int             step,
                             const double                   t,
                             const solvers::BorderedVector &state)
  {
    TimerOutput::Scope ts(timer, "output");
    collectively(
      [&]() { model.write_output(output.directory(), step, t, state); },
      output.directory() + "/solution_" + Utilities::int_to_string(step, 4));
    last_written = step;
  }

  void
  Simulator::Impl::save_checkpoint(const strategies::Run         &run,
                                   const solvers::BorderedVector &state,
                                   const double                   t)
  {
    TimerOutput::Scope ts(timer, "checkpoint");
    const auto        &strategy =
      *strategies.at(stages.strategy(stages.segments()[segment].first));
    checkpoints.write(checkpoint_directory(), comm, [&](Checkpoint &cp) {
      // The state, then the vectors the strategy keeps (the static path's
      // last increment).
      std::vector<const solvers::BorderedVector *> states{&state};
      strategy.save_checkpoint(cp, states);
      model.save_checkpoint(cp, states);
      cp.put("run/segment", segment);
      cp.put("run/time", t);
      cp.put("run/counters", run.resumable);
      cp.put("run/wall_seconds", wall_time());
      cp.put("output/history", output.history_so_far());
      cp.put("output/last_written", last_written);
      stability.save_checkpoint(cp);
      for (const auto &[name, s] : strategies)
        s->save_summary(cp);
    });
    since_checkpoint.restart();
  }

  RunResult
  Simulator::Impl::summarize(const strategies::Run     &run,
                             const strategies::Outcome &end)
  {
    RunResult result;
    result.exit_code              = end.exit_code;
    result.message                = end.message;
    result.history                = history;
    result.step_iterations        = run.counters.step_iterations;
    result.last_residual_history  = run.counters.last_residual_history;
    result.residual_histories     = run.counters.residual_histories;
    Statistics            &row    = result.summary;
    const auto             g      = StatisticsGroup::run();
    constexpr unsigned int counts = Statistics::summary;
    row.add_count(g, "exit_code", end.exit_code, counts | Statistics::test);
    row.add_count(g, "dofs", model.n_dofs(), counts | Statistics::test);
    row.add_count(g,
                  "mpi_ranks",
                  Utilities::MPI::n_mpi_processes(comm),
                  counts);
    row.add_count(g, "steps", run.counters.steps, counts);
    row.add_count(g, "cutbacks", run.counters.cutbacks, counts);
    row.add_count(g,
                  "newton_iterations",
                  run.counters.newton_iterations,
                  counts);
    row.add_count(g, "linear_solves", model.n_linear_solves(), counts);
    model.linear_solver().add_statistics(row);
    row.add(g, "final_time", "", end.time, counts | Statistics::test);
    model.add_statistics(row, end.state, end.time);
    for (const auto &[name, strategy] : strategies)
      if (strategy->enabled() || stages.uses(name))
        strategy->add_summary(row);
    if (stability.enabled())
      {
        stability.add_summary(row);
        const std::string warning = stability.warning();
        if (!warning.empty() && result.exit_code == success)
          result.message =
            result.message.empty() ? warning : result.message + "; " + warning;
      }
    row.add(g, "wall_seconds", "s", wall_time(), counts);
    row.reduce(comm);
    try
      {
        output.summary(row, result.message, timer);
      }
    catch (const OutputError &e)
      {
        result.message   = result.exit_code == success
                             ? e.what()
                             : result.message + "; also " + e.what();
        result.exit_code = solver_failed;
      }
    // Every rank ends with the same outcome.
    result.exit_code =
      Utilities::MPI::max(static_cast<unsigned int>(result.exit_code), comm);
    output.test_output(row);
    return result;
  }
} // namespace pneuma
