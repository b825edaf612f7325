#pragma once

/**
 * @file
 * The Simulator's state (private to source/simulator): the model, the
 * stages and their strategies, the run's services (Newton, the stability
 * monitor), the outputs and the checkpoints.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <pneuma/core/checkpoint.h>
#include <pneuma/core/model.h>
#include <pneuma/core/output.h>
#include <pneuma/simulator/simulator.h>
#include <pneuma/solvers/newton_solver.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/solution_strategy.h>
#include <pneuma/strategies/stability_monitor.h>
#include <pneuma/strategies/stages.h>

#include <map>
#include <memory>
#include <string>

namespace pneuma
{
  class Simulator::Impl
  {
  public:
    Impl(const MPI_Comm comm, const InputLayout &layout);

    /// One run of the strategies on the current mesh.
    RunResult
    run_once();

    // ---- the parts of run_once() (simulator.cc)
    /// Before the stages (form finding): its outcome.
    strategies::Outcome
    run_before_stages(strategies::Run &run);
    /// Restore the checkpoint of a restart into @p run and @p outcome;
    /// returns the segment to continue.
    unsigned int
    resume(strategies::Run &run, strategies::Outcome &outcome);
    /// The stages' segments from @p first on.
    strategies::Outcome
    run_stages(strategies::Run           &run,
               const unsigned int         first,
               const strategies::Outcome &from);
    /// After the stages (an eigen analysis of the final state).
    strategies::Outcome
    run_after_stages(strategies::Run &run, const strategies::Outcome &from);

    // ---- what is recorded (reporting.cc)
    /// The observer of every converged state: history row, VTU,
    /// checkpoint when due.
    void
    record(strategies::Run               &run,
           const strategies::StepReport  &step,
           const solvers::BorderedVector &state);
    /// The row of history.csv at a converged step.
    Statistics
    history_row(strategies::Run               &run,
                const strategies::StepReport  &step,
                const solvers::BorderedVector &state);
    /// Write the VTU files of @p state at @p step.
    void
    write_vtu(const unsigned int             step,
              const double                   t,
              const solvers::BorderedVector &state);
    /// Write a checkpoint of the converged @p state at @p t.
    void
    save_checkpoint(const strategies::Run         &run,
                    const solvers::BorderedVector &state,
                    const double                   t);
    /// summary.json, the test output and the run's result, which ended
    /// with @p end.
    RunResult
    summarize(const strategies::Run &run, const strategies::Outcome &end);

    /// Every rank's write either succeeds or throws, on all ranks alike,
    /// WriteError naming @p file or NonFiniteOutput (a state with NaN or
    /// inf is never written).
    template <typename Write>
    void
    collectively(const Write &write, const std::string &file) const;

    /// The enabled strategies of placement @p p with their names, in
    /// registry order.
    std::vector<std::pair<std::string, strategies::SolutionStrategy *>>
    enabled(const strategies::Placement p) const;

    double
    wall_time() const
    {
      return wall_offset + wall_clock.wall_time();
    }
    std::string
    checkpoint_directory() const
    {
      return output.directory() + "/checkpoint";
    }

    MPI_Comm                   comm;
    InputLayout                layout;
    dealii::ConditionalOStream pcout;
    /// The model (whose subsystems check the input layout) before the
    /// timer: no TimerOutput is alive while a construction error
    /// propagates.
    Model               model;
    dealii::TimerOutput timer;
    dealii::Timer       wall_clock;
    OutputWriter        output;
    CheckpointPolicy    checkpoints;
    strategies::Stages  stages;
    /// Newton's method of the implicit strategies ("Newton").
    solvers::NewtonSolver        newton;
    strategies::StabilityMonitor stability;
    /// One instance of every registered strategy (declared; the run uses
    /// the enabled ones and those its stages name).
    std::map<std::string, std::unique_ptr<strategies::SolutionStrategy>>
      strategies;

    /// The checkpoint a restart continues (null: a fresh run).
    std::unique_ptr<Checkpoint> restart;
    /// Wall time of the run before its restart.
    double wall_offset = 0.;

    // ---- the state of run_once()
    /// The segment running (checkpoints name it).
    unsigned int segment = 0;
    /// The last converged state of run_once() (refinement starts there).
    solvers::BorderedVector last_state;
    /// The last state and step the observer saw.
    strategies::StepReport  last_step;
    solvers::BorderedVector last_seen;
    /// The step of the last VTU written.
    unsigned int  last_written = 0;
    dealii::Timer since_checkpoint;
    /// The rows of history.csv so far.
    std::vector<Statistics> history;
  };

  template <typename Write>
  void
  Simulator::Impl::collectively(const Write       &write,
                                const std::string &file) const
  {
    // 1: a write failed (the disk); 2: the state is not finite (every
    // rank knows it alike; not the disk's fault); 3: another error, whose
    // message is kept (not blamed on the disk).
    unsigned int failed = 0;
    std::string  what;
    try
      {
        write();
      }
    catch (const NonFiniteOutput &e)
      {
        failed = 2;
        what   = e.what();
      }
    catch (const WriteError &)
      {
        failed = 1;
      }
    catch (const std::exception &e)
      {
        failed = 3;
        what   = e.what();
      }
    failed = dealii::Utilities::MPI::max(failed, comm);
    if (failed == 3)
      for (const auto &m : dealii::Utilities::MPI::all_gather(comm, what))
        if (!m.empty())
          throw OutputError("cannot write '" + file + "': " + m);
    if (failed == 2)
      {
        // The message of the first rank that has one (a cable's writer
        // is one rank).
        for (const auto &m : dealii::Utilities::MPI::all_gather(comm, what))
          if (!m.empty())
            throw NonFiniteOutput(m);
      }
    if (failed == 1)
      throw WriteError(file);
  }
} // namespace pneuma
