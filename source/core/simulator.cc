#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/core/output.h>
#include <pneuma/core/simulator.h>
#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/solvers/form_finding.h>
#include <pneuma/solvers/load_path.h>
#include <pneuma/solvers/stability.h>

#include <csignal>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace pneuma
{
  using namespace dealii;

  class Simulator::Impl
  {
  public:
    Impl(const MPI_Comm comm, const InputLayout &layout)
      : comm(comm)
      , layout(layout)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , model(comm, layout)
      , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
    {
      model.set_timer(timer);
    }

    /// One run of the load path on the current mesh.
    RunResult
    run_once();

    /// Print the eigen analysis' outcome.
    void
    report_eigen();

    /// The row of history.csv at a converged step.
    Statistics
    history_row(const solvers::PathStep       &step,
                const solvers::BorderedVector &state);

    MPI_Comm           comm;
    InputLayout        layout;
    ConditionalOStream pcout;
    /// The model (whose subsystems check the input layout) before the
    /// timer: no TimerOutput is alive while a construction error
    /// propagates.
    Model                   model;
    TimerOutput             timer;
    Timer                   wall_clock;
    solvers::StaticLoadPath path;
    OutputWriter            output;
    CheckpointPolicy        checkpoints;
    /// The inertia of every converged state (solvers/stability.h).
    bool                                     check_stability = true;
    std::unique_ptr<solvers::StabilityCheck> stability;
    solvers::StabilityReport                 last_stability;
    bool                                     branch_switching = false;
    /// Form finding before the analysis (solvers/form_finding.h).
    solvers::FormFinding       form_finding;
    solvers::FormFindingResult form_found;
    /// The eigen analysis of the final state (solvers/eigen_analysis.h).
    solvers::EigenParameters eigen;
    solvers::EigenResult     eigen_result;
    unsigned int             unstable_steps = 0;
    double first_unstable = std::numeric_limits<double>::quiet_NaN();
    /// Bracket of the bisection of a critical point, relative to the step.
    double locate_tolerance = 1e-2;
    /// The checkpoint a restart continues (null: a fresh run).
    std::unique_ptr<Checkpoint> restart;
    /// Wall time of the run before its restart.
    double wall_offset = 0.;
    /// The last converged state of run_once().
    solvers::BorderedVector last_state;

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
  };

  Simulator::Simulator(const MPI_Comm comm, const InputLayout &layout)
    : impl(std::make_unique<Impl>(comm, layout))
  {
  }

  Simulator::~Simulator() = default;

  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    impl->model.declare_parameters(prm, impl->layout);
    impl->path.declare_parameters(prm);
    impl->output.declare_parameters(prm);
    impl->checkpoints.declare_parameters(prm);
    impl->eigen.declare_parameters(prm);
    impl->form_finding.declare_parameters(prm);
    prm.enter_subsection("Stability");
    prm.add_parameter(
      "Check inertia",
      impl->check_stability,
      "Count the negative eigenvalues of the tangent at every converged "
      "step, chamber terms included (MUMPS LDL^T of the field block and "
      "the chamber Schur complement). With Newton's LDL^T factorization "
      "the count is that of its last iterate (no extra cost; a changed "
      "count is confirmed on the state's own factorization); with an LU, "
      "one extra symmetric factorization per step. An unstable state gets "
      "a warning.");
    prm.add_parameter(
      "Locate critical points",
      impl->locate_tolerance,
      "Where the count changes between two converged steps (a bifurcation "
      "under load control), bisect in pseudo time until the bracket is this "
      "fraction of the step (each probe is a Newton solve from the earlier "
      "state); 0: do not locate.",
      Patterns::Double(0., 1.));
    prm.add_parameter(
      "Branch switching",
      impl->branch_switching,
      "At the first located bifurcation point, leave the primary path for "
      "the secondary branch: the state just past the point is perturbed "
      "along the critical mode (the eigenvector of the negative eigenvalue "
      "nearest zero) by the last step's displacement norm, then 3, 9 and 27 "
      "times it, each solved at the same load, until a state with fewer "
      "negative eigenvalues is found; the path goes on from there.");
    prm.leave_subsection();
  }

  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    impl->model.parse_parameters(prm);
    impl->path.parse_parameters(prm);
    impl->output.parse_parameters(prm);
    impl->checkpoints.parse_parameters(prm);
    impl->eigen.parse_parameters(prm);
    impl->form_finding.parse_parameters(prm);
    // An adaptive study restarts from its beginning: each cycle is a new
    // run on a mesh refined from the last one's result.
    check_input(!impl->checkpoints.enabled()
                  || impl->model.refinement_cycles() == 0,
                "Checkpoint",
                "adaptive refinement studies (Adaptive refinement/Cycles > "
                "0) cannot be checkpointed; run the cycles again instead");
    impl->path.stop_after(impl->checkpoints.stop_after());
    check_input(!impl->branch_switching
                  || (impl->check_stability && impl->locate_tolerance > 0.),
                "Stability/Branch switching",
                "needs the located bifurcation: Stability/Check inertia = "
                "true and Stability/Locate critical points > 0");
    impl->path.set_branch_switching(impl->branch_switching);
    if (impl->check_stability)
      {
        Impl &s = *impl;
        // A factorization that fails (MUMPS workspace, a broken tangent)
        // leaves the state unjudged, never the run stopped.
        s.path.set_judge(
          [&s](const solvers::BorderedVector &state, const bool exact) {
            if (!s.stability)
              s.stability = std::make_unique<solvers::StabilityCheck>(s.comm);
            try
              {
                return s.stability->check(s.model, state, exact);
              }
            catch (const std::exception &e)
              {
                solvers::StabilityReport r;
                r.note = std::string("not computed: ") + e.what();
                return r;
              }
          },
          s.locate_tolerance);
      }
    if (impl->output.quiet())
      {
        impl->pcout.set_condition(false);
        impl->model.out().set_condition(false);
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
    s.model.set_restart_directory(directory);
  }

  void
  Simulator::setup()
  {
    TimerOutput::Scope t(impl->timer, "setup");
    // The output directory must be writable before any work.
    impl->output.check_directory(impl->comm);
    impl->model.setup();
    impl->form_finding.check(impl->model);
    solvers::EigenAnalysis::check_size(impl->model, impl->eigen);
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

  // ------------------------------------------------------------------
  // Running
  // ------------------------------------------------------------------
  RunResult
  Simulator::run()
  {
    Impl              &s      = *impl;
    const unsigned int cycles = s.model.refinement_cycles();
    if (cycles == 0)
      return s.run_once();

    // Convergence study: the load path on each adapted mesh, outputs per
    // cycle, one table of all cycles.
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
    // refinement.csv: one row per cycle of the test-level values.
    if (Utilities::MPI::this_mpi_process(s.comm) == 0)
      {
        std::ofstream table(base + "/refinement.csv");
        table << "cycle";
        for (const auto &e : summaries[0].entries())
          if (e.uses & Statistics::test)
            for (unsigned int c = 0; c < e.values.size(); ++c)
              table << "," << e.header(c);
        table << "\n" << std::setprecision(10);
        for (unsigned int k = 0; k < summaries.size(); ++k)
          {
            table << k;
            for (const auto &e : summaries[k].entries())
              if (e.uses & Statistics::test)
                for (const double v : e.values)
                  table << "," << v;
            table << "\n";
          }
      }
    return result;
  }

  Statistics
  Simulator::Impl::history_row(const solvers::PathStep       &step,
                               const solvers::BorderedVector &state)
  {
    Statistics row;
    const auto run = StatisticsGroup::run();
    row.add_count(run, "step", step.step, Statistics::history);
    row.add(run, "time", "", step.time, Statistics::history);
    row.add_count(run,
                  "newton_iterations",
                  step.iterations,
                  Statistics::history);
    row.add(run, "wall_seconds", "s", wall_time(), Statistics::history);
    if (path.follows_path())
      {
        row.add(run, "load_factor", "", step.load_factor, Statistics::history);
        row.add(run, "arc_length", "", step.arc_length, Statistics::history);
      }
    model.add_statistics(row, state);
    if (check_stability)
      {
        // The converged states after the reference state (whose tangent
        // is singular for a stress-free membrane).
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const solvers::StabilityReport &r = step.stability;
        if (step.step > 0)
          {
            if (r.energy_form)
              last_stability = r;
            if (!r.computed)
              pcout << "  stability: " << r.note << std::endl;
            else if (!r.energy_form)
              pcout << "  stability: under prescribed pressures "
                    << r.negative_field << " negative eigenvalue(s); " << r.note
                    << std::endl;
            else
              pcout << "  stability: " << r.negative
                    << " negative eigenvalue(s); under prescribed pressures "
                    << r.negative_field
                    << (r.note.empty() ? "" : " (" + r.note + ")") << std::endl;
            if (r.computed && r.energy_form && r.negative > 0)
              {
                if (unstable_steps == 0)
                  first_unstable = step.time;
                ++unstable_steps;
                pcout << "pneuma: warning: the converged state at t = "
                      << step.time << " is unstable (" << r.negative
                      << " negative eigenvalue(s) of the tangent)" << std::endl;
              }
          }
        row.add_count(run,
                      "negative_eigenvalues",
                      r.computed && r.energy_form ? r.negative : nan,
                      Statistics::history);
        row.add_count(run,
                      "negative_eigenvalues_prescribed_pressure",
                      r.computed ? r.negative_field : nan,
                      Statistics::history);
        row.add_count(run,
                      "zero_pivots",
                      r.computed ? r.zero : nan,
                      Statistics::history);
      }
    // The lowest eigenvalues along the path (not at the reference state,
    // whose tangent is singular for a stress-free membrane).
    if (eigen.active() && eigen.every_step)
      {
        solvers::EigenResult r;
        if (step.step > 0)
          {
            r = solvers::EigenAnalysis::run(model, state, eigen);
            if (!r.computed)
              pcout << "  eigen analysis: " << r.error << std::endl;
            else
              {
                pcout << "  eigen analysis: lowest";
                for (const double v : r.values)
                  pcout << " " << v;
                pcout << (eigen.type == "tangent" ? " N/m"
                          : eigen.type == "modal" ? " 1/s^2"
                                                  : " (load factors)")
                      << std::endl;
              }
          }
        for (unsigned int k = 0; k < eigen.n_modes; ++k)
          {
            const double          v = k < r.values.size()
                                        ? r.values[k]
                                        : std::numeric_limits<double>::quiet_NaN();
            const StatisticsGroup g{"mode", "", "", k + 1};
            if (eigen.type == "tangent")
              row.add(g, "eigenvalue", "N/m", v, Statistics::history);
            else if (eigen.type == "modal")
              row.add(g,
                      "frequency",
                      "Hz",
                      solvers::EigenAnalysis::frequency(v),
                      Statistics::history);
            else
              row.add(
                g, "critical_time", "", step.time + v, Statistics::history);
          }
      }
    row.reduce(comm);
    return row;
  }

  void
  Simulator::Impl::report_eigen()
  {
    const solvers::EigenResult &r = eigen_result;
    if (!r.computed)
      {
        pcout << "eigen analysis (" << eigen.type << "): " << r.error
              << std::endl;
        return;
      }
    pcout << "eigen analysis (" << eigen.type << ") at t = " << r.time << ": "
          << r.values.size() << " modes in " << r.iterations
          << " ARPACK restarts, largest relative residual " << std::scientific
          << std::setprecision(2) << r.residual;
    if (r.non_symmetric)
      pcout << "; non-symmetric tangent: Arnoldi on its LU, the "
               "eigenvalues nearest the shift (largest |Im|/|lambda| "
            << r.imaginary << ")";
    else if (eigen.type != "buckling")
      pcout << ", " << r.below_shift << " eigenvalue(s) below the shift";
    pcout << std::endl;
    for (unsigned int k = 0; k < r.values.size(); ++k)
      {
        pcout << "  mode " << std::setw(3) << k + 1 << ": " << std::setw(14)
              << std::setprecision(6) << r.values[k];
        if (eigen.type == "tangent")
          pcout << " N/m";
        else if (eigen.type == "modal")
          pcout << " 1/s^2, f = " << std::setw(13)
                << solvers::EigenAnalysis::frequency(r.values[k]) << " Hz";
        else
          pcout << ", critical t = " << std::setw(13) << r.time + r.values[k];
        pcout << std::endl;
      }
    pcout << std::defaultfloat;
  }

  RunResult
  Simulator::Impl::run_once()
  {
    RunResult result;
    model.check_well_posed();
    // The shape the analysis starts from (again after a restart: the
    // iteration is deterministic).
    if (form_finding.enabled())
      {
        TimerOutput::Scope ts(timer, "form finding");
        form_found = form_finding.run(model, path.newton(), pcout);
      }
    // A restart continues the checkpoint's state and output files.
    std::unique_ptr<solvers::PathResume> resume;
    unsigned int last_written = numbers::invalid_unsigned_int;
    if (restart)
      {
        resume        = std::make_unique<solvers::PathResume>();
        resume->path  = restart->get<solvers::PathState>("path");
        auto states   = model.load_checkpoint(*restart, resume->path.time);
        resume->state = std::move(states[0]);
        if (states.size() > 1)
          resume->increment = std::move(states[1]);
        wall_offset    = restart->get<double>("run/wall_seconds");
        const auto s   = restart->get<std::vector<double>>("run/stability");
        unstable_steps = static_cast<unsigned int>(s[0]);
        first_unstable = s[1];
        last_stability.computed = s[2] != 0.;
        last_stability.negative = static_cast<long long>(s[3]);
        last_written = restart->get<unsigned int>("output/last_written");
        output.prepare_restart(comm,
                               resume->path.steps,
                               restart->get<std::string>("output/history"));
        pcout << "pneuma: restarting from " << restart->directory()
              << " after step " << resume->path.steps
              << ", t = " << resume->path.time << std::endl;
      }
    else
      output.prepare(comm);
    pcout << "pneuma: " << model.n_dofs() << " dofs in";
    for (const auto &s : model.all())
      pcout << " " << s->name();
    pcout << ", " << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)"
          << std::endl;

    // Every write is checked on every rank alike: a rank whose write
    // failed makes all of them stop (WriteError), none is left waiting.
    const auto collectively = [&](const auto &write, const std::string &file) {
      bool failed = false;
      try
        {
          write();
        }
      catch (const std::exception &)
        {
          failed = true;
        }
      if (Utilities::MPI::max(static_cast<unsigned int>(failed), comm) > 0)
        throw WriteError(file);
    };
    solvers::PathStep       last_step;
    solvers::BorderedVector last_seen;
    const auto              write_vtu = [&](const unsigned int             step,
                               const double                   t,
                               const solvers::BorderedVector &state) {
      TimerOutput::Scope ts(timer, "output");
      collectively(
        [&]() { model.write_output(output.directory(), step, t, state); },
        output.directory() + "/solution_" + Utilities::int_to_string(step, 4));
      last_written = step;
    };
    // A checkpoint of the converged state (core/checkpoint.h).
    Timer      since_checkpoint;
    const auto save_checkpoint = [&](const solvers::BorderedVector &state) {
      TimerOutput::Scope ts(timer, "checkpoint");
      write_checkpoint(checkpoint_directory(), comm, [&](Checkpoint &cp) {
        // The state and the last step's increment (the predictors').
        std::vector<const solvers::BorderedVector *> states{&state};
        if (path.last_increment().field.size() > 0)
          states.push_back(&path.last_increment());
        model.save_checkpoint(cp, states);
        cp.put("path", path.state());
        cp.put("output/history", output.history_so_far());
        cp.put("output/last_written", last_written);
        cp.put("run/wall_seconds", wall_time());
        cp.put("run/stability",
               std::vector<double>{static_cast<double>(unstable_steps),
                                   first_unstable,
                                   last_stability.computed ? 1. : 0.,
                                   static_cast<double>(
                                     last_stability.negative)});
      });
      since_checkpoint.restart();
    };
    const auto observer = [&](const solvers::PathStep       &step,
                              const solvers::BorderedVector &state) {
      last_step = step;
      last_seen = state;
      result.history.push_back(history_row(step, state));
      collectively([&]() { output.history_row(result.history.back()); },
                   output.directory() + "/history.csv");
      if (output.write_vtu()
          && (step.step == 0
              || (output.vtu_interval() > 0
                  && step.step % output.vtu_interval() == 0)))
        write_vtu(step.step, step.time, state);
      if (step.step > 0
          && checkpoints.due(step.step, since_checkpoint.wall_time() / 60.))
        save_checkpoint(state);
    };
    // A file that cannot be written stops the run (exit 2) with a message
    // naming it; the run is never reported a success.
    std::string         write_error;
    solvers::PathResult path_result;
    try
      {
        if (form_finding.enabled() && !form_found.converged)
          {
            // The last shape is the run's state.
            path_result.state     = model.initial_state();
            path_result.exit_code = solver_failed;
            path_result.message   = form_found.message;
            observer(solvers::PathStep{}, path_result.state);
          }
        else
          path_result =
            path.run(model, pcout, wall_clock, observer, resume.get());
        // A run stopped by a signal leaves a checkpoint to continue from
        // (not an adaptive study: its cycles start again).
        if ((path_result.exit_code == 128 + SIGINT
             || path_result.exit_code == 128 + SIGTERM)
            && model.refinement_cycles() == 0)
          {
            save_checkpoint(path_result.state);
            path_result.message +=
              " A checkpoint is in " + checkpoint_directory()
              + "; continue with --restart " + checkpoint_directory();
          }
        // The eigen analysis of the final state; its modes go with the
        // state's output.
        bool with_modes = false;
        if (eigen.active() && path_result.exit_code == success)
          {
            model.current_time = path_result.final_time;
            eigen_result =
              solvers::EigenAnalysis::run(model, path_result.state, eigen);
            report_eigen();
            if (!eigen_result.computed)
              {
                path_result.exit_code = solver_failed;
                path_result.message =
                  "the eigen analysis failed: " + eigen_result.error;
              }
            else if (eigen.write_modes)
              {
                std::vector<std::string> names;
                for (unsigned int k = 0; k < eigen_result.modes.size(); ++k)
                  names.push_back("mode_" + std::to_string(k + 1));
                model.set_output_modes(names, eigen_result.modes);
                with_modes = true;
              }
          }
        // The last converged state is always written.
        if (output.write_vtu()
            && (last_written != path_result.steps || with_modes))
          write_vtu(path_result.steps,
                    path_result.final_time,
                    path_result.state);
      }
    catch (const WriteError &e)
      {
        write_error = e.what();
        if (path_result.state.field.size() == 0)
          {
            // The path stopped inside the observer: its last converged
            // state is the one the observer saw.
            path_result.state      = last_seen;
            path_result.steps      = last_step.step;
            path_result.final_time = last_step.time;
            model.current_time     = last_step.time;
          }
      }
    if (!write_error.empty())
      {
        path_result.exit_code = solver_failed;
        path_result.message   = write_error;
      }

    last_state                   = path_result.state;
    result.exit_code             = path_result.exit_code;
    result.message               = path_result.message;
    result.step_iterations       = path_result.step_iterations;
    result.last_residual_history = path_result.last_residual_history;
    result.residual_histories    = path_result.residual_histories;

    Statistics            &row    = result.summary;
    const auto             run    = StatisticsGroup::run();
    constexpr unsigned int counts = Statistics::summary;
    row.add_count(run,
                  "exit_code",
                  result.exit_code,
                  counts | Statistics::test);
    row.add_count(run, "dofs", model.n_dofs(), counts | Statistics::test);
    row.add_count(run,
                  "mpi_ranks",
                  Utilities::MPI::n_mpi_processes(comm),
                  counts);
    row.add_count(run, "steps", path_result.steps, counts);
    row.add_count(run, "cutbacks", path_result.cutbacks, counts);
    row.add_count(run,
                  "newton_iterations",
                  path_result.newton_iterations,
                  counts);
    row.add_count(run, "linear_solves", model.n_linear_solves(), counts);
    row.add_count(run,
                  "factorizations",
                  model.linear_solver().n_factorizations(),
                  counts);
    row.add_count(run,
                  "krylov_iterations",
                  model.linear_solver().n_krylov_iterations(),
                  counts);
    if (model.linear_solver().type() == "direct")
      {
        // The last factorization: LDL^T (1) or LU (0), its size and work.
        const auto &solver = model.linear_solver();
        row.add_count(run,
                      "factorization_symmetric",
                      solver.factorization() == "LDLT" ? 1. : 0.,
                      Statistics::summary);
        row.add_count(run,
                      "factor_entries",
                      solver.factor_entries(),
                      Statistics::summary);
        row.add(run,
                "factorization_gflop",
                "",
                1e-9 * solver.factorization_flops(),
                Statistics::summary);
        // Where the LDL^T's time went (MUMPS' phases on rank 0).
        const auto work = solver.symmetric_work();
        row.add_count(run, "ldlt_analyses", work.analyses, Statistics::summary);
        row.add_count(run,
                      "ldlt_orderings",
                      work.orderings,
                      Statistics::summary);
        row.add(run,
                "ldlt_analysis_seconds",
                "s",
                work.analysis_seconds,
                Statistics::summary);
        row.add(run,
                "ldlt_factorization_seconds",
                "s",
                work.factorization_seconds,
                Statistics::summary);
        row.add(run,
                "ldlt_solve_seconds",
                "s",
                work.solve_seconds,
                Statistics::summary);
      }
    row.add(
      run, "final_time", "", path_result.final_time, counts | Statistics::test);
    // Load stepping/Initial prestress: where the ramp of the prestress
    // acting at t = 0 ended, if it was ramped.
    if (path.state().ramp_end > path.state().ramp_start)
      row.add(run, "prestress_ramp_end", "", path.state().ramp_end, counts);
    if (form_finding.enabled())
      {
        row.add_count(run,
                      "form_finding_newton_iterations",
                      form_found.newton_iterations,
                      counts);
        row.add(
          run, "form_finding_last_move", "", form_found.last_change, counts);
      }
    model.add_statistics(row, path_result.state);
    // Critical points: located by the stability check, or limit points
    // where a followed path turned back.
    for (unsigned int k = 0; k < path_result.critical_points.size(); ++k)
      {
        const auto           &c = path_result.critical_points[k];
        const StatisticsGroup g{"cp", "critical_points", "point", k + 1};
        row.add(g, "time", "", c.time, counts);
        row.add(g, "bracket", "", c.bracket, counts);
        row.add_count(g, "step", c.step, counts);
        row.add_count(g, "limit_point", c.type == "limit point", counts);
        row.add_count(g, "negative_before", c.before, counts);
        row.add_count(g, "negative_after", c.after, counts);
        if (path.follows_path())
          row.add(g, "monitor", "m", c.monitor, counts);
        if (branch_switching && c.type == "bifurcation")
          {
            row.add_count(g, "switched", c.switched, counts);
            row.add(g, "switch_amplitude", "m", c.amplitude, counts);
          }
      }
    if (eigen_result.computed)
      {
        row.add_count(run,
                      "eigen_below_shift",
                      eigen_result.below_shift >= 0
                        ? eigen_result.below_shift
                        : std::numeric_limits<double>::quiet_NaN(),
                      counts);
        row.add_count(run,
                      "eigen_non_symmetric",
                      eigen_result.non_symmetric,
                      counts);
        row.add(run, "eigen_asymmetry", "", eigen_result.asymmetry, counts);
        row.add_count(run, "eigen_iterations", eigen_result.iterations, counts);
        row.add(run, "eigen_residual", "", eigen_result.residual, counts);
        row.add_count(run,
                      "eigen_substitutions",
                      eigen_result.substitutions,
                      counts);
        row.add(run,
                "eigen_factorization_seconds",
                "s",
                eigen_result.factorization_seconds,
                counts);
        row.add(run, "eigen_seconds", "s", eigen_result.seconds, counts);
        if (eigen.type == "modal")
          row.add(run, "modal_mass", "kg", eigen_result.total_mass, counts);
        for (unsigned int k = 0; k < eigen_result.values.size(); ++k)
          {
            const double          v = eigen_result.values[k];
            const StatisticsGroup g{"mode", "eigen_modes", "mode", k + 1};
            if (eigen.type == "tangent")
              row.add(g, "eigenvalue", "N/m", v, counts);
            else if (eigen.type == "modal")
              {
                row.add(g, "omega_squared", "1/s^2", v, counts);
                row.add(g,
                        "frequency",
                        "Hz",
                        solvers::EigenAnalysis::frequency(v),
                        counts);
                const auto &e = eigen_result.effective_mass[k];
                row.add(g, "effective_mass_x", "kg", e[0], counts);
                row.add(g, "effective_mass_y", "kg", e[1], counts);
                row.add(g, "effective_mass_z", "kg", e[2], counts);
              }
            else
              {
                row.add(g, "load_factor", "", v, counts);
                row.add(g, "critical_time", "", eigen_result.time + v, counts);
              }
          }
      }
    if (check_stability)
      {
        row.add_count(run, "unstable_steps", unstable_steps, counts);
        row.add(run, "first_unstable_time", "", first_unstable, counts);
        row.add_count(run,
                      "negative_eigenvalues",
                      last_stability.computed ? last_stability.negative
                                              : std::nan(""),
                      counts);
        if (unstable_steps > 0 && result.exit_code == success)
          {
            std::ostringstream m;
            m << "warning: " << unstable_steps
              << " converged state(s) are unstable, the first at t = "
              << first_unstable
              << " (negative eigenvalues of the tangent; history.csv "
                 "column negative_eigenvalues)";
            result.message = result.message.empty()
                               ? m.str()
                               : result.message + "; " + m.str();
          }
      }
    row.add(run, "wall_seconds", "s", wall_time(), counts);
    row.reduce(comm);
    try
      {
        output.summary(row, result.message, timer);
      }
    catch (const WriteError &e)
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
