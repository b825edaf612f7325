/**
 * @file
 * The strategies of a run in turn (Simulator::Impl::run_once): those
 * placed before the stages, the stages' segments from the state the last
 * one handed over (or the checkpoint a restart continues), and those placed
 * after them.
 */

#include <pneuma/core/input_error.h>

#include "simulator_impl.h"

#include <csignal>

namespace pneuma
{
  using namespace dealii;
  using strategies::Outcome;
  using strategies::Placement;

  Outcome
  Simulator::Impl::run_before_stages(strategies::Run &run)
  {
    Outcome outcome;
    for (const auto &[name, s] : enabled(Placement::before_stages))
      {
        TimerOutput::Scope t(timer, name);
        outcome = s->run(run, {}, outcome);
        if (outcome.exit_code != success)
          break;
      }
    return outcome;
  }

  unsigned int
  Simulator::Impl::resume(strategies::Run &run, Outcome &outcome)
  {
    // A restart continues the checkpoint's state, strategy and output
    // files.
    const Checkpoint &cp    = *restart;
    const auto        time  = cp.get<double>("run/time");
    auto              state = model.load_checkpoint(cp, time);
    run.counters            = cp.get<strategies::RunCounters>("run/counters");
    run.mark_resumable();
    stability.load_checkpoint(cp);
    for (const auto &[name, s] : strategies)
      s->load_summary(cp);
    wall_offset  = cp.get<double>("run/wall_seconds");
    last_written = cp.get<unsigned int>("output/last_written");
    output.prepare_restart(comm,
                           run.counters.steps,
                           cp.get<std::string>("output/history"));
    segment        = cp.get<unsigned int>("run/segment");
    const auto all = stages.segments();
    check_input(segment < all.size(),
                "--restart " + cp.directory(),
                "the checkpoint was written in stage segment "
                  + std::to_string(segment + 1) + ", but the input has "
                  + std::to_string(all.size()));
    outcome.state = std::move(state[0]);
    outcome.time  = time;
    state.erase(state.begin());
    strategies.at(stages.strategy(all[segment].first))
      ->load_checkpoint(cp, state);
    pcout << "pneuma: restarting from " << cp.directory() << " after step "
          << run.counters.steps << ", t = " << time << std::endl;
    return segment;
  }

  Outcome
  Simulator::Impl::run_stages(strategies::Run   &run,
                              const unsigned int first,
                              const Outcome     &from)
  {
    Outcome    outcome = from;
    const auto all     = stages.segments();
    for (segment = first; segment < all.size(); ++segment)
      {
        auto &strategy = *strategies.at(stages.strategy(all[segment].first));
        outcome        = strategy.run(run, all[segment], outcome);
        if (outcome.exit_code != success || outcome.stop)
          break;
        if (run.stop_requested() && segment + 1 < all.size())
          {
            outcome.message = run.stop_message();
            break;
          }
      }
    // A run stopped by a signal leaves a checkpoint to continue from (not
    // an adaptive study: its cycles start again).
    if ((outcome.exit_code == 128 + SIGINT
         || outcome.exit_code == 128 + SIGTERM)
        && model.refinement_cycles() == 0)
      {
        save_checkpoint(run, outcome.state, outcome.time);
        outcome.message += " A checkpoint is in " + checkpoint_directory()
                           + "; continue with --restart "
                           + checkpoint_directory();
      }
    return outcome;
  }

  Outcome
  Simulator::Impl::run_after_stages(strategies::Run &run, const Outcome &from)
  {
    Outcome outcome = from;
    if (outcome.exit_code != success)
      return outcome;
    for (const auto &[name, s] : enabled(Placement::after_stages))
      {
        const Outcome after = s->run(run, {}, outcome);
        outcome.exit_code   = after.exit_code;
        outcome.message     = after.message;
        outcome.output_changed |= after.output_changed;
        if (outcome.exit_code != success)
          break;
      }
    return outcome;
  }
} // namespace pneuma
