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
#include <pneuma/solvers/stability.h>

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
      /// The stability of the state (computed: false if not judged).
      StabilityReport stability;
    };

    /**
     * A change of the negative-eigenvalue count between two converged
     * states, located by bisection in pseudo time. Under load control the
     * control parameter grows through it, so it is a bifurcation point (a
     * limit point of the control cannot be passed by load control).
     */
    struct CriticalPoint
    {
      unsigned int step    = 0;           ///< the step whose state is past it
      double       time    = 0.;          ///< the middle of the final bracket
      double       bracket = 0.;          ///< width of the final bracket
      long long    before = 0, after = 0; ///< the counts on both sides
      unsigned int probes = 0;            ///< Newton solves of the bisection
      std::string  type   = "bifurcation";

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &step &time &bracket &before &after &probes &type;
      }
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
      /// The stability count of the last judged state (-1: none).
      long long negative_eigenvalues = -1;
      /// The critical points passed so far.
      std::vector<CriticalPoint> critical_points;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &time &increment &steps &cutbacks     &newton_iterations;
        ar &stiffness_reference &stiffness       &stiffness_stage;
        ar &stiffness_stage_set &step_iterations &last_residual_history;
        ar &negative_eigenvalues                 &critical_points;
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
      /// Critical points passed (located if a tolerance is set).
      std::vector<CriticalPoint> critical_points;
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

      /// Judges the stability of a converged state before it is committed.
      using Judge = std::function<StabilityReport(const BorderedVector &)>;
      /**
       * Judge every converged state with @p judge; where the count
       * changes between two steps, bisect in pseudo time until the bracket
       * is @p tolerance times the step (0: do not locate).
       */
      void
      set_judge(const Judge &judge, const double tolerance)
      {
        stability_judge  = judge;
        locate_tolerance = tolerance;
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
      Judge        stability_judge;
      double       locate_tolerance = 0.;
      /// The count of the last accepted state (for a restart too).
      StabilityReport previous_stability;

      /// Bisect [t_old, t_new] for the change of the count from
      /// @p before to @p after; Newton solves from @p last (quietly).
      CriticalPoint
      locate(Model                &model,
             const BorderedVector &last,
             const double          t_old,
             const double          t_new,
             const long long       before,
             const long long       after);
    };
  } // namespace solvers
} // namespace pneuma
