#pragma once

/**
 * @file
 * The static load path: the solution strategy that drives a Model through
 * its stages in pseudo time by Newton's method (doc/theory.md "Load
 * stepping", "Path following"), under load control, arc-length control or
 * displacement control of a monitored component. Each step is
 * - predicted (the last step's increment extrapolated, or along the
 *   path's tangent or secant) and prepared (prescribed values, contact
 *   search, border predictions),
 * - solved by Newton (bordered by the path constraint in a path-controlled
 *   stage),
 * - judged (an admissible state, a path step that went on along the path,
 *   its stability; critical points located, bifurcations left),
 * - then accepted (committed, reported) or rejected (state restored, the
 *   increment cut back). Easy steps let the increment grow.
 *
 * Bergan's current stiffness parameter \f$S_p = (\Delta t/|\Delta u|) /
 * (\Delta t/|\Delta u|)_{first}\f$ (per stage) tells a failure at a limit
 * point (\f$S_p \to 0\f$) from a hard step.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/newton_solver.h>
#include <pneuma/solvers/path_following.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/solution_strategy.h>
#include <pneuma/strategies/static_load_path/critical_points.h>
#include <pneuma/strategies/static_load_path/load_stepping.h>
#include <pneuma/strategies/static_load_path/path_control.h>

#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  namespace strategies
  {
    /// "Load stepping/Initial prestress".
    enum class InitialPrestress
    {
      automatic,
      ramped,
      full
    };

    /// Where the path stands after a converged step: what a restart needs
    /// to continue as if it had not stopped (core/checkpoint.h).
    struct PathState
    {
      double       time = 0., increment = 0.;
      double       stiffness_reference = 0., stiffness = 1.;
      unsigned int stiffness_stage     = 0;
      bool         stiffness_stage_set = false;
      /// The stability count of the last judged state (-1: none).
      long long negative_eigenvalues = -1;
      /// The critical points passed so far.
      std::vector<CriticalPoint> critical_points;
      /// The path-controlled stage.
      PathRecord path;
      /// The automatic first step: the loads acting in full at t = 0 grow
      /// over [ramp_start, ramp_end] (none while ramp_end <= ramp_start).
      double ramp_start = 0., ramp_end = 0.;
      /// The last accepted step (its increment is kept with the state):
      /// its change of pseudo time (0: none kept), |r_ref| of its Newton
      /// solve per unit of pseudo time (the reference of a predicted
      /// step), its stage, whether the next load-controlled step may
      /// extrapolate it (a load-controlled step from a stressed state, not
      /// a branch switch), and whether the step was cut back since (then
      /// taken again without extrapolation).
      double       increment_dt    = 0.;
      double       reference_rate  = 0.;
      unsigned int increment_stage = 0;
      bool         increment_load = false, cut_back = false;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &time &increment &stiffness_reference &stiffness &stiffness_stage;
        ar &stiffness_stage_set &negative_eigenvalues &critical_points &path;
        ar &ramp_start &ramp_end &increment_dt &reference_rate;
        ar &increment_stage &increment_load    &cut_back;
      }
    };

    /// The static load path through the stages that name it.
    class StaticLoadPath : public SolutionStrategy
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) override;
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const Stages             &stages) override;

      /// What the path-controlled stages need (a monitor point, no
      /// prescribed displacement changing in them).
      void
      check(Model &model) const override;

      Outcome
      run(Run &run, const Segment &segment, const Outcome &start) override;

      void
      add_history(Statistics                    &row,
                  const StepReport              &report,
                  const solvers::BorderedVector &state,
                  Run                           &run) override;
      void
      add_summary(Statistics &row) const override;

      void
      save_checkpoint(
        Checkpoint                                   &checkpoint,
        std::vector<const solvers::BorderedVector *> &vectors) const override;
      void
      load_checkpoint(const Checkpoint                     &checkpoint,
                      std::vector<solvers::BorderedVector> &vectors) override;

    private:
      /// The path while run() goes (see static_load_path.cc).
      struct Walk;
      /// One attempt of a step.
      struct Attempt;
      /// What the judgement of a converged attempt decides.
      enum class Verdict
      {
        accept,
        /// Taken again from the last converged state (the state is
        /// restored), no cut back.
        again,
        /// Newton failed or the state is not admissible: cut back.
        reject
      };

      // ---- the steps of run() (static_load_path.cc)
      void
      start(Walk &walk, const Outcome &start);
      void
      check_stages(Walk &walk) const;
      bool
      interrupted(Walk &walk) const;
      Attempt
      prepare(Walk &walk);
      void
      enter_path_stage(Walk &walk, Attempt &a);
      bool
      solve_load_step(Walk &walk, Attempt &a);
      void
      solve_path_step(Walk &walk, Attempt &a);
      /// The predictor's factor along @p direction that meets the path
      /// constraint (its size in @p a), shortened to the stage's maximum
      /// change of the load factor or to the target.
      double
      scale_predictor(Walk                          &walk,
                      Attempt                       &a,
                      const solvers::BorderedVector &direction,
                      const bool                     by_displacement);
      Verdict
      judge(Walk &walk, Attempt &a);
      Verdict
      judge_path_step(Walk &walk, Attempt &a);
      Verdict
      judge_stability(Walk &walk, Attempt &a);
      void
      locate_critical_point(Walk &walk, Attempt &a);
      void
      again(Walk &walk, const Attempt &a);
      bool
      reject(Walk &walk, Attempt &a);
      void
      accept(Walk &walk, Attempt &a);
      void
      record_path_step(Walk &walk, const Attempt &a);
      void
      end_path_stage(Walk &walk, const Attempt &a);
      void
      snapshot(const Walk &walk);

      /// Ramp the loads acting in full at t = 0 over the first stage
      /// (Model::ramp_initial_loads), record it and say so; false if the
      /// model has none.
      bool
      ramp_initial_loads(Walk &walk);
      /// May the automatic first step ramp them now (the first step of a
      /// new run, from t = 0, under load control, not ramped yet)?
      bool
      first_step_may_ramp(const Walk &walk, const Attempt &a) const;
      /// The control of stage @p stage.
      solvers::Control
      control_of(const unsigned int stage) const
      {
        return controls.size() == 1 ? controls[0] : controls[stage];
      }
      /// True if some stage is under arc-length or displacement control.
      bool
      follows_path() const;

      // ---- parameters
      LoadStepping stepping;
      PathControl  path;
      /// "Load stepping/Control", one per stage (or one for all).
      std::vector<std::string>      control_names{"load"};
      std::vector<solvers::Control> controls{solvers::Control::load};
      InitialPrestress initial_prestress = InitialPrestress::automatic;
      /// "Load stepping/Extrapolation": linear (true) or none.
      bool extrapolate = true;

      // ---- the state of the path (kept for a restart)
      PathState current;
      /// The last accepted step's increment of the state (empty if none is
      /// kept), which the predictors extrapolate.
      solvers::BorderedVector step_increment;
      /// The count of the last accepted state.
      solvers::StabilityReport previous_stability;
      /// The critical points passed so far.
      std::vector<CriticalPoint> critical_points;
      /// The path was restored from a checkpoint: run() continues it.
      bool resumed = false;
      /// Bifurcations were left (Stability/Branch switching).
      bool branch_switching = false;
    };
  } // namespace strategies
} // namespace pneuma
