#pragma once

/**
 * @file
 * What a solution strategy gets from the run it is part of
 * (strategies/solution_strategy.h): the model, the stages, the nonlinear
 * solver of the implicit strategies, the stability monitor, the counts of
 * the whole run, and the observer that records every converged state
 * (history row, VTU, checkpoint).
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/stability.h>

#include <functional>
#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace solvers
  {
    class NewtonSolver;
  }

  namespace strategies
  {
    class Stages;
    class StabilityMonitor;

    /// A converged state, as reported to the observer.
    struct StepReport
    {
      unsigned int step       = 0; ///< 0: the reference state
      double       time       = 0.;
      unsigned int iterations = 0; ///< nonlinear iterations of the step
      std::string  convergence_test;
      /// Bergan's current stiffness parameter (1 in a stage's first step).
      double stiffness_parameter = 1.;
      /// The stability of the state (computed: false if not judged).
      solvers::StabilityReport stability;
      /// The load factor within the stage, (t - t_start)/(t_end -
      /// t_start), and the arc length travelled in a path-controlled stage.
      double load_factor = 0., arc_length = 0.;
    };

    /// The counts of the whole run, over its strategies (and restarts).
    struct RunCounters
    {
      unsigned int steps = 0, cutbacks = 0, newton_iterations = 0;
      /// Nonlinear iterations of every converged step.
      std::vector<unsigned int> step_iterations;
      /// |r| of the last converged step's iterations.
      std::vector<double> last_residual_history;
      /// |r| of every converged step's iterations (this process only, not
      /// kept across a restart).
      std::vector<std::vector<double>> residual_histories;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &steps &cutbacks &newton_iterations &step_iterations
          &last_residual_history;
      }
    };

    /// The run a strategy is part of.
    class Run
    {
    public:
      using Observer = std::function<void(const StepReport &,
                                          const solvers::BorderedVector &)>;

      Run(Model                            &model,
          const Stages                     &stages,
          const solvers::NewtonSolver      &newton,
          StabilityMonitor                 *stability,
          const dealii::ConditionalOStream &out,
          const dealii::Timer              &wall_clock)
        : model(model)
        , stages(stages)
        , newton(newton)
        , stability(stability)
        , out(out)
        , wall_clock(wall_clock)
      {
      }

      /// The observer of every converged state.
      void
      set_observer(const Observer &o)
      {
        observer = o;
      }

      Model        &model;
      const Stages &stages;
      /// Newton's method with its parameters ("Newton").
      const solvers::NewtonSolver &newton;
      /// Judges converged states (nullptr: Stability/Check inertia off).
      StabilityMonitor                 *stability;
      const dealii::ConditionalOStream &out;
      /// The wall clock of this process (for the step lines).
      const dealii::Timer &wall_clock;
      RunCounters          counters;
      /// The counters at the last resumable state (mark_resumable()),
      /// which a checkpoint stores.
      RunCounters resumable;
      /// Stop the run after this converged step (0: never; Checkpoint/Stop
      /// after step).
      unsigned int stop_step = 0;

      /// Record a converged state (history row, VTU, checkpoint).
      void
      report(const StepReport &r, const solvers::BorderedVector &state) const
      {
        observer(r, state);
      }

      /// The strategy's state is resumable here (after an accepted or a
      /// cut-back step): a checkpoint stores the counters as they are.
      void
      mark_resumable()
      {
        resumable = counters;
      }

      /// Is the run to stop after the step just reported, as asked?
      bool
      stop_requested() const
      {
        return stop_step > 0 && counters.steps >= stop_step;
      }

      /// The message of a run stopped as asked.
      std::string
      stop_message() const
      {
        return "stopped after step " + std::to_string(counters.steps)
               + " as asked (Checkpoint/Stop after step); continue with "
                 "--restart";
      }

    private:
      Observer observer;
    };
  } // namespace strategies
} // namespace pneuma
