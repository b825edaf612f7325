#include <pneuma/core/input_error.h>
#include <pneuma/core/restart_check.h>

#include "simulator_impl.h"

#include <csignal>

namespace pneuma
{
  using namespace dealii;
  using strategies::Outcome;
  using strategies::Placement;

  Simulator::Impl::Impl(const MPI_Comm comm, const InputLayout &layout)
    : comm(comm)
    , layout(layout)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , model(comm, layout)
    , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
  {
    model.set_timer(timer);
    for (const auto &e : strategies::strategy_entries())
      strategies[e.name] = e.create();
  }

  Simulator::Simulator(const MPI_Comm comm, const InputLayout &layout)
    : impl(std::make_unique<Impl>(comm, layout))
  {
  }

  Simulator::~Simulator() = default;

  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    Impl &s = *impl;
    s.model.declare_parameters(prm, s.layout);
    s.stages.declare_parameters(prm);
    s.newton.declare_parameters(prm);
    s.stability.declare_parameters(prm);
    for (const auto &[name, strategy] : s.strategies)
      strategy->declare_parameters(prm);
    s.output.declare_parameters(prm);
    s.checkpoints.declare_parameters(prm);
  }

  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    Impl &s = *impl;
    s.model.parse_parameters(prm);
    s.stages.parse_parameters(prm);
    s.newton.parse_parameters(prm);
    s.stability.parse_parameters(prm);
    for (const auto &[name, strategy] : s.strategies)
      strategy->parse_parameters(prm, s.stages);
    s.output.parse_parameters(prm);
    s.checkpoints.parse_parameters(prm);
    // An adaptive study restarts from its beginning: each cycle is a new
    // run on a mesh refined from the last one's result.
    check_input(!s.checkpoints.enabled() || s.model.refinement_cycles() == 0,
                "Checkpoint",
                "adaptive refinement studies (Adaptive refinement/Cycles > "
                "0) cannot be checkpointed; run the cycles again instead");
    if (s.output.quiet())
      {
        s.pcout.set_condition(false);
        s.model.out().set_condition(false);
      }
  }

  void
  Simulator::restart_from(const std::string &directory)
  {
    Impl &s = *impl;
    check_input(s.model.refinement_cycles() == 0,
                "--restart " + directory,
                "adaptive refinement studies (Adaptive refinement/Cycles > "
                "0) cannot be restarted; run the cycles again instead");
    s.restart = std::make_unique<Checkpoint>(directory);
    s.restart->read_state(s.comm);
    check_restart_parameters(*s.restart, s.checkpoints.parameters());
    s.model.set_restart_directory(directory);
  }

  void
  Simulator::setup()
  {
    Impl              &s = *impl;
    TimerOutput::Scope t(s.timer, "setup");
    // The output directory must be writable before any work.
    s.output.check_directory(s.comm);
    // No matrix where no strategy of the run assembles a tangent (nor the
    // stability check).
    bool tangent = s.stability.enabled();
    for (const auto &[name, strategy] : s.strategies)
      if (strategy->enabled() || s.stages.uses(name))
        tangent = tangent || strategy->needs_tangent();
    if (!tangent)
      s.model.set_matrix_free(true);
    s.model.setup();
    for (const auto &[name, strategy] : s.strategies)
      strategy->check(s.model);
  }

  Model &
  Simulator::model()
  {
    return impl->model;
  }

  const solvers::BorderedVector &
  Simulator::final_state() const
  {
    return impl->last_state;
  }

  std::pair<double, double>
  Simulator::check_tangent(const double t,
                           const double amplitude,
                           const double h,
                           const bool   path_constraint)
  {
    const TangentCheck c =
      impl->model.check_tangent(t, amplitude, h, path_constraint);
    return {c.relative_error, c.tangent_norm};
  }

  RunResult
  Simulator::run()
  {
    Impl              &s      = *impl;
    const unsigned int cycles = s.model.refinement_cycles();
    if (cycles == 0)
      return s.run_once();
    // Convergence study: the strategies on each adapted mesh, outputs per
    // cycle, one table of all cycles (refinement.csv).
    const std::string       base = s.output.directory();
    RunResult               result;
    std::vector<Statistics> summaries;
    for (unsigned int cycle = 0; cycle <= cycles; ++cycle)
      {
        if (cycle > 0)
          {
            TimerOutput::Scope t(s.timer, "setup");
            s.model.refine(s.last_state);
          }
        s.output.set_directory(base + "/cycle-" + std::to_string(cycle));
        s.pcout << "Adaptive refinement: cycle " << cycle << std::endl;
        result = s.run_once();
        summaries.push_back(result.summary);
        if (result.exit_code != success)
          break;
      }
    s.output.set_directory(base);
    result.cycles = summaries;
    s.output.refinement_table(s.comm, summaries);
    return result;
  }

  std::vector<std::pair<std::string, strategies::SolutionStrategy *>>
  Simulator::Impl::enabled(const Placement p) const
  {
    std::vector<std::pair<std::string, strategies::SolutionStrategy *>> all;
    for (const auto &e : strategies::strategy_entries())
      if (e.placement == p && strategies.at(e.name)->enabled())
        all.emplace_back(e.name, strategies.at(e.name).get());
    return all;
  }

  RunResult
  Simulator::Impl::run_once()
  {
    model.check_well_posed();
    strategies::Run run(model,
                        stages,
                        newton,
                        stability.enabled() ? &stability : nullptr,
                        pcout,
                        wall_clock);
    run.set_observer([this, &run](const strategies::StepReport  &step,
                                  const solvers::BorderedVector &state) {
      record(run, step, state);
    });
    run.stop_step = checkpoints.stop_after();
    history.clear();
    last_written = numbers::invalid_unsigned_int;
    // The shape the analysis starts from (again after a restart: the
    // iteration is deterministic).
    Outcome      outcome = run_before_stages(run);
    unsigned int first   = 0;
    if (restart)
      first = resume(run, outcome);
    else
      output.prepare(comm);
    pcout << "pneuma: " << model.n_dofs() << " dofs in";
    for (const auto &s : model.all())
      pcout << " " << s->name();
    pcout << ", " << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << std::endl;
    since_checkpoint.restart();
    // A file that cannot be written stops the run (exit 2) with a message
    // naming it; the run is never reported a success.
    Outcome end;
    try
      {
        if (outcome.exit_code != success)
          {
            // A failed start: the reference state is the run's.
            end       = outcome;
            end.state = model.initial_state();
            record(run, strategies::StepReport{}, end.state);
          }
        else
          end = run_after_stages(run, run_stages(run, first, outcome));
        // The last converged state is always written.
        if (output.write_vtu()
            && (last_written != run.counters.steps || end.output_changed))
          write_vtu(run.counters.steps, end.time, end.state);
      }
    catch (const OutputError &e)
      {
        // The run stopped inside the observer: its last converged state
        // is the one the observer saw.
        if (end.state.field.size() == 0)
          {
            end.state = last_seen;
            end.time  = last_step.time;
          }
        end.exit_code = solver_failed;
        end.message   = e.what();
      }
    last_state = end.state;
    return summarize(run, end);
  }

} // namespace pneuma
