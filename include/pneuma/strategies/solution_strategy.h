#pragma once

/**
 * @file
 * Solution strategies: how a run drives the Model (doc/architecture.md
 * "Stages and strategies").
 *
 * A run is a sequence of load stages (strategies/stages.h). Each stage
 * names the strategy that drives the model through it (`Load
 * stepping/Strategy`); consecutive stages of one strategy form a segment,
 * which one call of run() goes through, starting from the state the
 * segment before it handed over. Strategies that act once, before the
 * stages (form finding: the shape the analysis starts from) or after them
 * (an eigen analysis of the final state), are switched on by their own
 * input and placed there.
 *
 * A strategy is one folder under strategies/ plus one registration:
 * @code
 * PNEUMA_REGISTER_STRATEGY(StaticLoadPath, "static", Placement::stage,
 *                          "Newton with load stepping, arc length or "
 *                          "displacement control");
 * @endcode
 * It declares and parses its own parameters, drives the model through the
 * Model's step protocol (begin_step, a solve, check_state, commit_step or
 * reject_step), reports every converged state to the run's observer, adds
 * its own columns to history.csv and its own entries to summary.json, and
 * saves what a restart needs in its own checkpoint section.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/statistics.h>
#include <pneuma/solvers/bordered_vector.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class Checkpoint;
  class Model;

  namespace strategies
  {
    class Run;
    class Stages;
    struct StepReport;

    /// Where a strategy acts in a run.
    enum class Placement
    {
      /// Once, before the first stage (form finding).
      before_stages,
      /// Through the stages that name it (the static load path).
      stage,
      /// Once, at the final state of the stages (an eigen analysis).
      after_stages
    };

    /// Stages [first, last] (from 0) that one strategy drives in a row.
    struct Segment
    {
      unsigned int first = 0, last = 0;
      /// The index of the segment in the run (checkpoints record it).
      unsigned int index = 0;
    };

    /// A state handed from one strategy to the next, and how a part of
    /// the run ended.
    struct Outcome
    {
      /// 0 success, 2 the solver failed, 128 + signal interrupted.
      int         exit_code = 0;
      std::string message;
      /// The last converged state (empty field: none yet, the next
      /// strategy starts from the model's reference state).
      solvers::BorderedVector state;
      /// Its pseudo time.
      double time = 0.;
      /// The run ends here, successfully (a target reached, a critical
      /// point or a step it was asked to stop at): no later segment runs.
      bool stop = false;
      /// An after-stage strategy added fields to the final state's output
      /// (mode shapes): it is written again.
      bool output_changed = false;
    };

    /// One solution strategy (see the file's description).
    class SolutionStrategy
    {
    public:
      virtual ~SolutionStrategy() = default;

      /// Declare its entries (at their own paths), bound to members.
      virtual void
      declare_parameters(dealii::ParameterHandler &prm) = 0;
      /// Check and derive after the input is read; @p stages are parsed.
      /// Throws InputError naming the entry.
      virtual void
      parse_parameters(dealii::ParameterHandler &prm, const Stages &stages) = 0;

      /// For strategies placed before or after the stages: does this run
      /// use it (its own switch)? Stage strategies are used by the stages
      /// that name them.
      virtual bool
      enabled() const
      {
        return false;
      }

      /// Does the strategy, when the run uses it, assemble a tangent? A run
      /// whose strategies all answer no sets the model up without a matrix
      /// (Model::set_matrix_free()).
      virtual bool
      needs_tangent() const
      {
        return true;
      }

      /// After the model's setup: the input errors the set-up model shows
      /// (throws InputError naming the entry).
      virtual void
      check(Model &model) const
      {
        (void)model;
      }

      /**
       * Drive the model through @p segment (a stage strategy) or act once
       * (before or after the stages), from the state @p start (an empty
       * field: the model's reference state, which a stage strategy that
       * starts a run reports as step 0). Returns how its part ended;
       * failures of the solver are returned, input errors thrown.
       */
      virtual Outcome
      run(Run &run, const Segment &segment, const Outcome &start) = 0;

      /// Columns of every history row (all strategies of the run add
      /// theirs, whichever reported the state; the same columns in every
      /// row).
      virtual void
      add_history(Statistics                    &row,
                  const StepReport              &report,
                  const solvers::BorderedVector &state,
                  Run                           &run)
      {
        (void)row;
        (void)report;
        (void)state;
        (void)run;
      }

      /// Entries of summary.json at the end of the run.
      virtual void
      add_summary(Statistics &row) const
      {
        (void)row;
      }

      // ---- checkpoint and restart (core/checkpoint.h)
      /**
       * Store what a restart of the running segment needs in the
       * checkpoint (sections under this strategy's name) and add the
       * whole-model vectors it keeps besides the converged state (the
       * static load path's last increment) to @p vectors.
       */
      virtual void
      save_checkpoint(
        Checkpoint                                   &checkpoint,
        std::vector<const solvers::BorderedVector *> &vectors) const
      {
        (void)checkpoint;
        (void)vectors;
      }
      /**
       * What its summary entries count so far (add_summary()), stored in
       * every checkpoint whichever segment runs, so that a restart reports
       * the counts of strategies that ran before it (the relaxation's
       * iterations, the form finding's). Restored by load_summary().
       */
      virtual void
      save_summary(Checkpoint &checkpoint) const
      {
        (void)checkpoint;
      }
      virtual void
      load_summary(const Checkpoint &checkpoint)
      {
        (void)checkpoint;
      }
      /// Restore it before run() continues the segment; @p vectors are the
      /// ones saved (restored by the model), in the same order.
      virtual void
      load_checkpoint(const Checkpoint                     &checkpoint,
                      std::vector<solvers::BorderedVector> &vectors)
      {
        (void)checkpoint;
        (void)vectors;
      }
    };

    /// How to make one strategy (see PNEUMA_REGISTER_STRATEGY).
    struct StrategyEntry
    {
      std::string name, description;
      Placement   placement = Placement::stage;
      std::function<std::unique_ptr<SolutionStrategy>()> create;
    };

    /// The registered strategies, in registration order within each
    /// placement (before the stages, stages, after them).
    const std::vector<StrategyEntry> &
    strategy_entries();

    /// "a|b" of the names of the strategies of placement @p p.
    std::string
    strategy_names(const Placement p, const std::string &separator = "|");

    /// Register a strategy (used by PNEUMA_REGISTER_STRATEGY).
    bool
    register_strategy(const StrategyEntry &entry);
  } // namespace strategies
} // namespace pneuma

#define PNEUMA_STRATEGY_CONCAT_IMPL(a, b) a##b
#define PNEUMA_STRATEGY_CONCAT(a, b) PNEUMA_STRATEGY_CONCAT_IMPL(a, b)

/**
 * Register the strategy class @p Class (default constructible) under
 * @p name, acting at @p placement (a strategies::Placement), with a
 * one-line @p description. Use once, at namespace scope, in the
 * strategy's own .cc file.
 */
#define PNEUMA_REGISTER_STRATEGY(Class, name, placement, description)          \
  namespace                                                                    \
  {                                                                            \
    const bool PNEUMA_STRATEGY_CONCAT(pneuma_registered_strategy_, __LINE__) = \
      ::pneuma::strategies::register_strategy(                                 \
        {name, description, placement, []() {                                  \
           return std::unique_ptr<::pneuma::strategies::SolutionStrategy>(     \
             std::make_unique<Class>());                                       \
         }});                                                                  \
  }
