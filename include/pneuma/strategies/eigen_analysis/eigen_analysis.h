#pragma once

/**
 * @file
 * The eigen analysis as a strategy of the run ("Eigen analysis"; doc/
 * theory.md "Eigen analysis"): after the stages, the lowest eigenvalues
 * and modes of the final converged state (tangent), its natural
 * frequencies (modal) or its linear buckling loads (buckling), by
 * solvers::EigenAnalysis; optionally also at every converged step, as
 * columns of history.csv. The modes go to the final state's VTU.
 */

#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/strategies/solution_strategy.h>

namespace pneuma
{
  namespace strategies
  {
    /// "Eigen analysis": placed after the stages.
    class EigenAnalysisStrategy : public SolutionStrategy
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) override;
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const Stages             &stages) override;
      bool
      enabled() const override
      {
        return parameters.type != solvers::EigenProblem::none;
      }
      /// The problem has enough free unknowns for the modes asked.
      void
      check(Model &model) const override;
      /// The analysis of the final state @p start.
      Outcome
      run(Run &run, const Segment &segment, const Outcome &start) override;
      /// Every step: the lowest values of each converged state.
      void
      add_history(Statistics                    &row,
                  const StepReport              &report,
                  const solvers::BorderedVector &state,
                  Run                           &run) override;
      void
      add_summary(Statistics &row) const override;

    private:
      /// Print the outcome of the final analysis.
      void
      print(const dealii::ConditionalOStream &out) const;
      /// The unit of the eigenvalues, for the step lines.
      std::string
      unit() const;

      solvers::EigenParameters parameters;
      bool                     write_modes = true;
      bool                     every_step  = false;
      /// The analysis of the final state.
      solvers::EigenResult result;
    };
  } // namespace strategies
} // namespace pneuma
