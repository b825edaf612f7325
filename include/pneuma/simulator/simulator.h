#pragma once

/**
 * @file
 * The Simulator: one pneuma run. It reads the parameters of the Model (the
 * coupled subsystems), of the stages and their solution strategies
 * (strategies/solution_strategy.h) and of the outputs, runs the strategies
 * over the model in turn, and writes history.csv, summary.json, the VTU
 * files, checkpoints and the regression-test output from one statistics
 * table (doc/architecture.md "Data flow"). The header is light so that
 * tests and the main program compile fast.
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/input_layout.h>
#include <pneuma/core/parse_input.h>
#include <pneuma/core/statistics.h>

#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class Model;
  namespace solvers
  {
    struct BorderedVector;
  }

  /// Exit codes of a run (README, doc/user-guide.md).
  enum ExitCode : int
  {
    success       = 0,
    bad_input     = 1,
    solver_failed = 2
  };

  /// What a finished run reports.
  struct RunResult
  {
    int         exit_code = success;
    std::string message;
    /// The row of summary.json (the last converged state and the counts).
    Statistics summary{true};
    /// One row per converged step (the reference state first), as in
    /// history.csv.
    std::vector<Statistics> history;
    /// Newton iterations of every converged step, and |r| of the last
    /// step's iterations.
    std::vector<unsigned int> step_iterations;
    std::vector<double>       last_residual_history;
    /// |r| of every converged step's Newton iterations.
    std::vector<std::vector<double>> residual_histories;
    /// Adaptive refinement: the summary row of every cycle.
    std::vector<Statistics> cycles;

    /// A value of the summary ("c1_pressure", "m0_u_x", "steps").
    double
    get(const std::string &column) const
    {
      return summary.get(column);
    }
  };

  /// One pneuma run, configured by a ParameterHandler.
  class Simulator
  {
  public:
    /// The run that @p layout describes (its subsystems are made here).
    Simulator(const MPI_Comm comm, const InputLayout &layout);
    ~Simulator();

    /// Declare the parameters of this run, bound to its components.
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Check and derive after the input is read; throws InputError.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * Continue the run saved in the checkpoint directory @p directory
     * (called after parse_parameters(), before setup()); throws InputError
     * naming it if it cannot be read or belongs to another scene.
     */
    void
    restart_from(const std::string &directory);

    /// Build the meshes, check them against the input, set up the system.
    void
    setup();

    /// Run the stages' strategies; returns the result (and writes the
    /// outputs).
    RunResult
    run();

    /**
     * Compare the assembled tangent at a smooth perturbation of size
     * @p amplitude with central finite differences of the residual (step
     * @p h), at pseudo time @p t; returns {relative error, |K d|}. With
     * @p path_constraint, the Jacobian bordered by the arc-length
     * constraint with the load factor as unknown.
     */
    std::pair<double, double>
    check_tangent(const double t,
                  const double amplitude,
                  const double h,
                  const bool   path_constraint = false);

    /// The coupled model (set up by setup()), for tests and tools.
    Model &
    model();
    /// The last converged state of the last run().
    const solvers::BorderedVector &
    final_state() const;

  private:
    class Impl;
    std::unique_ptr<Impl> impl;
  };

} // namespace pneuma
