#pragma once

/**
 * @file
 * The stability of every converged state of a run (the "Stability"
 * subsection): the judge that strategies ask before they commit a state
 * (solvers/stability.h counts the negative eigenvalues of the tangent with
 * the chamber terms), the warnings for unstable states, and what the run
 * reports of them (history columns, summary entries, checkpoint).
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/statistics.h>
#include <pneuma/solvers/stability.h>

#include <limits>
#include <memory>

namespace pneuma
{
  class Checkpoint;
  class Model;

  namespace strategies
  {
    struct StepReport;

    /// Judges converged states and keeps the run's record of them.
    class StabilityMonitor
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Is every converged state judged (Stability/Check inertia)?
      bool
      enabled() const
      {
        return check;
      }
      /// Bracket of the bisection of a critical point, relative to the
      /// step (0: do not locate).
      double
      locate_tolerance() const
      {
        return tolerance;
      }
      /// Leave the primary path at the first located bifurcation.
      bool
      branch_switching() const
      {
        return switching;
      }

      /**
       * The stability of the converged @p state of @p model at pseudo time
       * @p t. @p exact: factorize the state's own tangent rather than count
       * on Newton's last factorization. A factorization that fails leaves
       * the state unjudged (the report says why), never the run stopped.
       */
      solvers::StabilityReport
      judge(Model                         &model,
            const solvers::BorderedVector &state,
            const double                   t,
            const bool                     exact);

      /// Record the report of converged step @p r (warnings for unstable
      /// states) and add its columns to the history @p row.
      void
      add_history(Statistics                       &row,
                  const StepReport                 &r,
                  const dealii::ConditionalOStream &out);

      /// The run's record: unstable steps, the first of them, the last
      /// count.
      void
      add_summary(Statistics &row) const;

      /// The warning of a run that passed unstable states (empty: none).
      std::string
      warning() const;

      void
      save_checkpoint(Checkpoint &checkpoint) const;
      void
      load_checkpoint(const Checkpoint &checkpoint);

    private:
      bool                                     check     = true;
      double                                   tolerance = 1e-2;
      bool                                     switching = false;
      std::unique_ptr<solvers::StabilityCheck> stability;
      /// The last judged state in energy form, and the unstable ones.
      solvers::StabilityReport last;
      unsigned int             unstable_steps = 0;
      double first_unstable = std::numeric_limits<double>::quiet_NaN();
    };
  } // namespace strategies
} // namespace pneuma
