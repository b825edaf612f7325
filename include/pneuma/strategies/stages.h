#pragma once

/**
 * @file
 * The load stages of a run: intervals [t_{k-1}, t_k] of the pseudo time
 * of the load curves (inflate on [0, 1], then load on [1, 2]), each driven
 * by a named solution strategy (`Load stepping/Strategy`, one per stage or
 * one for all). Consecutive stages of the same strategy form a segment,
 * which that strategy runs in one go (strategies/solution_strategy.h).
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/strategies/solution_strategy.h>

#include <string>
#include <vector>

namespace pneuma
{
  namespace strategies
  {
    /// "Load stepping/Stage end times" and "Load stepping/Strategy".
    class Stages
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Check the times and the strategy names (registered stage
      /// strategies); throws InputError naming the entry.
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Number of stages.
      unsigned int
      n_stages() const
      {
        return ends.size();
      }
      /// End of the last stage.
      double
      end_time() const
      {
        return ends.back();
      }
      /// Start and end of stage @p s.
      double
      start(const unsigned int s) const
      {
        return s == 0 ? 0. : ends[s - 1];
      }
      double
      end(const unsigned int s) const
      {
        return ends[s];
      }
      /// Index of the stage that contains (t, t + epsilon].
      unsigned int
      stage_of(const double t) const;
      /// True if @p t is (numerically) at or beyond @p t_end (default: the
      /// end of the last stage).
      bool
      finished(const double t, const double t_end = -1.) const;

      /// The strategy of stage @p s.
      const std::string &
      strategy(const unsigned int s) const
      {
        return names.size() == 1 ? names[0] : names[s];
      }
      /// Does some stage name the strategy @p name?
      bool
      uses(const std::string &name) const;
      /// The segments: runs of consecutive stages with one strategy.
      std::vector<Segment>
      segments() const;

    private:
      std::vector<double>      ends{1.};
      std::vector<std::string> names{"static"};
    };
  } // namespace strategies
} // namespace pneuma
