#pragma once

/**
 * @file
 * The static load path: the solution strategy that drives a Model through
 * the load stages in pseudo time by load control (doc/theory.md "Load
 * stepping"). Each step is prepared (prescribed values, contact search,
 * border predictions), solved by Newton, checked (admissible state) and
 * then accepted (committed, reported) or rejected (state restored, the
 * increment cut back). Easy steps let the increment grow.
 *
 * Bergan's current stiffness parameter \f$S_p = (\Delta t/|\Delta u|) /
 * (\Delta t/|\Delta u|)_{first}\f$ (per stage) tells a failure at a limit
 * point (\f$S_p \to 0\f$) from a hard step.
 *
 * Other strategies (arc-length, explicit dynamics, an eigen analysis) use
 * the same Model and Newton.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/load_stepping.h>
#include <pneuma/solvers/newton_solver.h>

#include <functional>
#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace solvers
  {
    /// A converged state of the path, as reported to the observer.
    struct PathStep
    {
      unsigned int step       = 0; ///< 0: the reference state
      double       time       = 0.;
      unsigned int iterations = 0; ///< Newton iterations of the step
      std::string  convergence_test;
      /// Bergan's current stiffness parameter (1 in a stage's first step).
      double stiffness_parameter = 1.;
    };

    /// Where the path stands after a converged step: what a restart needs
    /// to continue as if it had not stopped (core/checkpoint.h).
    struct PathState
    {
      double                    time = 0., increment = 0.;
      unsigned int              steps = 0, cutbacks = 0, newton_iterations = 0;
      double                    stiffness_reference = 0., stiffness = 1.;
      unsigned int              stiffness_stage     = 0;
      bool                      stiffness_stage_set = false;
      std::vector<unsigned int> step_iterations;
      std::vector<double>       last_residual_history;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &time &increment &steps &cutbacks     &newton_iterations;
        ar &stiffness_reference &stiffness       &stiffness_stage;
        ar &stiffness_stage_set &step_iterations &last_residual_history;
      }
    };

    /// How the path ended.
    struct PathResult
    {
      int          exit_code = 0; ///< 0 success, 2 the solver failed
      std::string  message;
      unsigned int steps = 0, cutbacks = 0, newton_iterations = 0;
      double       final_time = 0.;
      /// Newton iterations of every converged step.
      std::vector<unsigned int> step_iterations;
      /// |r| of the last converged step's Newton iterations.
      std::vector<double> last_residual_history;
      /// The last converged state.
      BorderedVector state;
    };

    /// The load-controlled path through the stages.
    class StaticLoadPath
    {
    public:
      /// Called with every converged state (the reference state first).
      using Observer =
        std::function<void(const PathStep &, const BorderedVector &)>;

      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Run the path on @p model (set up) from its reference state, or,
       * with @p resume, from a state restored from a checkpoint (then the
       * observer first sees the next step).
       */
      PathResult
      run(Model                                      &model,
          const ConditionalOStream                   &out,
          dealii::Timer                              &wall_clock,
          const Observer                             &observer,
          const std::pair<PathState, BorderedVector> *resume = nullptr);

      /// The path's state at the last converged step (valid inside the
      /// observer and after run()).
      const PathState &
      state() const
      {
        return current;
      }

      /// Stop after converged step @p step (0: never), with exit code 0.
      void
      stop_after(const unsigned int step)
      {
        stop_step = step;
      }

      const NewtonSolver &
      newton() const
      {
        return newton_solver;
      }

    private:
      LoadStepping stepping;
      NewtonSolver newton_solver;
      PathState    current;
      unsigned int stop_step = 0;
    };
  } // namespace solvers
} // namespace pneuma
