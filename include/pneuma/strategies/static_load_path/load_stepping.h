#pragma once

/**
 * @file
 * Adaptive load stepping of the static load path through its stages
 * (strategies/stages.h): a step whose Newton iteration fails is cut back;
 * a step that converged in few iterations lets the next one grow.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/strategies/stages.h>

#include <algorithm>
#include <vector>

namespace pneuma
{
  namespace strategies
  {
    /// "Load stepping" increments and the increment control.
    class LoadStepping
    {
    public:
      /// Declare the entries, bound to the members (their initial values
      /// are the defaults).
      void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Check them against the run's @p stages (kept).
      void
      parse_parameters(dealii::ParameterHandler &prm, const Stages &stages);

      /// The stages (after parse_parameters()).
      const Stages &
      stages() const
      {
        return *all_stages;
      }
      /// Target of the next step from @p t with increment @p dt, never
      /// stepping over a stage end.
      double
      next_time(const double t, const double dt) const;
      /// The increment after a converged step of @p dt that took
      /// @p iterations Newton iterations: grown after an easy step, and if
      /// @p capped at most the maximum of the stage that follows time
      /// @p t (a path-controlled stage caps the load factor's change
      /// instead, not its arc length).
      double
      grown(const double       dt,
            const unsigned int iterations,
            const bool         capped,
            const double       t) const;
      /// Increment after a failed step.
      double
      cut(const double dt) const
      {
        return dt * cut_back_factor;
      }
      /// The first increment of stage @p stage: Initial increment, at most
      /// the stage's maximum.
      double
      initial(const unsigned int stage) const
      {
        return std::min(initial_increment, maximum(stage));
      }
      double
      minimum() const
      {
        return minimum_increment;
      }
      /// The largest increment of stage @p stage (Maximum increment: one
      /// value for all stages or one per stage).
      double
      maximum(const unsigned int stage) const
      {
        return maximum_increments.size() == 1 ? maximum_increments.front()
                                              : maximum_increments[stage];
      }

    private:
      const Stages       *all_stages = nullptr;
      std::vector<double> maximum_increments{1.};
      double              initial_increment = 0.25, minimum_increment = 1e-4,
             growth_factor = 1.5, cut_back_factor = 0.5;
      unsigned int easy_iterations = 5;
    };
  } // namespace strategies
} // namespace pneuma
