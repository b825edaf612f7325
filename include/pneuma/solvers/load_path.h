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
#include <pneuma/solvers/path_following.h>
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
      /// The load factor within the stage, (t - t_start)/(t_end - t_start),
      /// and the arc length travelled in a path-controlled stage.
      double load_factor = 0., arc_length = 0.;
    };

    /**
     * A critical point: a change of the negative-eigenvalue count between
     * two converged states, located by bisection in pseudo time (load
     * control) or in the arc length (path following). Under load control
     * the load grows through it, so it is a bifurcation point (a limit
     * point cannot be passed by load control); on a followed path it is a
     * limit point where the load factor has an extremum there, a
     * bifurcation point where it has not. A limit point found only by the
     * load factor turning back (no stability check) is not located: its
     * bracket is the step.
     */
    struct CriticalPoint
    {
      unsigned int step    = 0;           ///< the step whose state is past it
      double       time    = 0.;          ///< the middle of the final bracket
      double       bracket = 0.;          ///< width of the final bracket
      long long    before = 0, after = 0; ///< the counts on both sides
      unsigned int probes = 0;            ///< Newton solves of the bisection
      std::string  type   = "bifurcation";
      /// The monitored component (Load stepping/Path following) there; NaN
      /// without a monitor.
      double monitor = 0.;
      /// Branch switching (Stability/Branch switching): the path left the
      /// bifurcation on the secondary branch, at the mode amplitude
      /// @p amplitude (|u - u_primary|) with this count of negative
      /// eigenvalues.
      bool      switched           = false;
      double    amplitude          = 0.;
      long long negative_secondary = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &step &time &bracket &before &after &probes &type &monitor &switched
          &amplitude &negative_secondary;
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
      /// Path following: in a path-controlled stage (and which), its
      /// scales (|du/dtau|, |dR/dtau|, the monitor's rate at the stage's
      /// start), the arc length travelled, its steps, the last change of
      /// the load factor, and whether a limit point was reported since the
      /// load factor last turned.
      bool         path_active = false;
      unsigned int path_stage  = 0;
      double       u_scale = 1., force_scale = 1., monitor_rate = 1.;
      double       arc_length = 0., last_dtau = 0.;
      unsigned int path_steps         = 0;
      bool         limit_since_return = false;
      /// The automatic first step: the loads acting in full at t = 0 grow
      /// over [ramp_start, ramp_end] (none while ramp_end <= ramp_start).
      double ramp_start = 0., ramp_end = 0.;
      /// The last accepted step (StaticLoadPath::last_increment()): its
      /// change of pseudo time (0: none kept), its stage, whether the next
      /// load-controlled step may extrapolate it (a load-controlled step
      /// from a stressed state, not a branch switch), and whether it is the
      /// path's secant predictor;
      /// whether the step was cut back since (then taken again without
      /// extrapolation).
      double increment_dt = 0.;
      /// |r_ref| of its Newton solve per unit of pseudo time (the
      /// reference of a predicted step, NewtonSolver::solve()).
      double       reference_rate  = 0.;
      unsigned int increment_stage = 0;
      bool         increment_load = false, secant = false, cut_back = false;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &time &increment &steps &cutbacks     &newton_iterations;
        ar &stiffness_reference &stiffness       &stiffness_stage;
        ar &stiffness_stage_set &step_iterations &last_residual_history;
        ar &negative_eigenvalues                 &critical_points;
        ar &path_active &path_stage &u_scale &force_scale &monitor_rate;
        ar &arc_length &last_dtau &path_steps             &limit_since_return;
        ar &ramp_start                                    &ramp_end;
        ar &increment_dt &reference_rate &increment_stage &increment_load;
        ar &secant                                        &cut_back;
      }
    };

    /// What a restart continues from (core/checkpoint.h).
    struct PathResume
    {
      PathState      path;
      BorderedVector state;
      /// The last accepted step's increment (PathState::increment_dt).
      BorderedVector increment;
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
      /// |r| of every converged step's Newton iterations (this run, not
      /// kept across a restart).
      std::vector<std::vector<double>> residual_histories;
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
      run(Model                    &model,
          const ConditionalOStream &out,
          dealii::Timer            &wall_clock,
          const Observer           &observer,
          const PathResume         *resume = nullptr);

      /// The path's state at the last converged step (valid inside the
      /// observer and after run()).
      const PathState &
      state() const
      {
        return current;
      }

      /// The last accepted step's increment of the state (empty if none
      /// is kept), which the predictors extrapolate; with state() what a
      /// checkpoint stores.
      const BorderedVector &
      last_increment() const
      {
        return step_increment;
      }

      /// Stop after converged step @p step (0: never), with exit code 0.
      void
      stop_after(const unsigned int step)
      {
        stop_step = step;
      }

      /// Judges the stability of a converged state before it is committed.
      /// @p exact: factorize the state's own tangent (the probes that
      /// locate a critical point) rather than count on Newton's last
      /// factorization.
      using Judge =
        std::function<StabilityReport(const BorderedVector &, bool exact)>;
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

      /// At the first located bifurcation point, leave the primary path
      /// for the secondary branch (see switch_branch()).
      void
      set_branch_switching(const bool on)
      {
        branch_switching = on;
      }

      const NewtonSolver &
      newton() const
      {
        return newton_solver;
      }

      /// True if some stage is under arc-length or displacement control.
      bool
      follows_path() const;

    private:
      /// Ramp the loads acting in full at t = 0 over the first stage
      /// (Model::ramp_initial_loads), record it and say so; false if the
      /// model has none.
      bool
      ramp_initial_loads(Model &model, const ConditionalOStream &out);
      /// May the automatic first step ramp them now (the first step of a
      /// new run, from t = 0, under load control, not ramped yet)?
      bool
      first_step_may_ramp(const unsigned int steps,
                          const double       t_old,
                          const Control      control) const;

      LoadStepping stepping;
      NewtonSolver newton_solver;
      /// "Load stepping/Control", one per stage (or one for all), and
      /// "Load stepping/Path following".
      std::vector<std::string> control_names{"load"};
      std::vector<Control>     controls{Control::load};
      /// "Load stepping/Initial prestress": automatic, ramped or full.
      std::string  initial_prestress = "automatic";
      std::string  constraint_name   = "cylindrical";
      unsigned int monitor_point     = 0;
      std::string  monitor_component = "z";
      std::string  target_text;
      double       target           = 0.;
      bool         has_target       = false;
      unsigned int max_path_steps   = 200;
      bool         stop_at_critical = false;
      /// "Load stepping/Extrapolation": linear or none.
      std::string extrapolation_name = "linear";
      bool        extrapolate        = true;
      /// See last_increment().
      BorderedVector step_increment;

      Control
      control_of(const unsigned int stage) const
      {
        return controls.size() == 1 ? controls[0] : controls[stage];
      }
      /// The monitor functional w (w . u is the monitored component), or
      /// an empty vector without a monitor point.
      LA::Vector
                   monitor_functional(const Model &model) const;
      PathState    current;
      unsigned int stop_step = 0;
      Judge        stability_judge;
      double       locate_tolerance = 0.;
      bool         branch_switching = false;
      /// The count of the last accepted state (for a restart too).
      StabilityReport previous_stability;

      /**
       * Branch switching at a located bifurcation: the converged @p state
       * at pseudo time @p t, just past it on the primary path with
       * @p negative negative eigenvalues, is perturbed along the critical
       * mode phi (the eigenvector of the negative eigenvalue nearest zero
       * of the tangent with its chamber terms, solvers/eigen_analysis.h;
       * unit l2 norm) by amplitudes xi = @p amplitude, 3 xi, 9 xi, 27 xi,
       * each solved by Newton at the same load; the first solution with
       * fewer negative eigenvalues is on the secondary branch and replaces
       * @p state (with its report @p stability). Returns whether it did;
       * @p c records it.
       */
      bool
      switch_branch(Model                    &model,
                    BorderedVector           &state,
                    const double              t,
                    const double              amplitude,
                    StabilityReport          &stability,
                    CriticalPoint            &c,
                    const ConditionalOStream &out);

      /// Bisect [t_old, t_new] for the change of the count from
      /// @p before to @p after; Newton solves from @p last (quietly).
      CriticalPoint
      locate(Model                &model,
             const BorderedVector &last,
             const double          t_old,
             const double          t_new,
             const long long       before,
             const long long       after);

      /**
       * Bisect the path-controlled step from the converged @p last
       * (extended) along @p increment (the accepted step, of constraint
       * size @p size: arc length, or the monitor's change) for the change
       * of the count from @p before to @p after; a limit point where the
       * load factor has its extremum in the final bracket.
       */
      CriticalPoint
      locate_on_path(Model                 &model,
                     PathConstraintProblem &problem,
                     const BorderedVector  &last,
                     const BorderedVector  &increment,
                     const double           size,
                     const LA::Vector      &w,
                     const long long        before,
                     const long long        after);
    };
  } // namespace solvers
} // namespace pneuma
