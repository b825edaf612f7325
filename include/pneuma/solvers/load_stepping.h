#pragma once

/**
 * @file
 * Adaptive load stepping in pseudo time through a sequence of load stages.
 * Load curves are functions of the pseudo time t; a stage is an interval
 * [t_{k-1}, t_k] (e.g. inflate on [0,1], then load transversely on [1,2]).
 * A step whose Newton iteration fails is cut back; a step that converged in
 * few iterations lets the next one grow.
 */

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <vector>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    /// "Load stepping" subsection and the increment control.
    class LoadStepping
    {
    public:
      /// Declare the entries, bound to the members (their initial values
      /// are the defaults).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// End of the last stage.
      double
      end_time() const
      {
        return stage_ends.back();
      }
      /// Number of stages.
      unsigned int
      n_stages() const
      {
        return stage_ends.size();
      }
      /// Start and end of stage @p s.
      double
      stage_start(const unsigned int s) const
      {
        return s == 0 ? 0. : stage_ends[s - 1];
      }
      double
      stage_end(const unsigned int s) const
      {
        return stage_ends[s];
      }
      /// Index of the stage that contains (t, t + epsilon].
      unsigned int
      stage_of(const double t) const;
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
      /// True if @p t is (numerically) at or beyond the end.
      bool
      finished(const double t) const;

    private:
      std::vector<double> stage_ends{1.};
      std::vector<double> maximum_increments{1.};
      double              initial_increment = 0.25, minimum_increment = 1e-4,
             growth_factor = 1.5, cut_back_factor = 0.5;
      unsigned int easy_iterations = 5;
    };
  } // namespace solvers
} // namespace pneuma
