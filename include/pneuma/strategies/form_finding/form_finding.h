#pragma once

/**
 * @file
 * Form finding by the updated reference strategy (Bletzinger & Ramm 1999;
 * doc/theory.md "Form finding", doc/user-guide.md "Form finding").
 *
 * Given the supports (the input's boundary conditions, held where the
 * input surface puts them) and the prestress of every region, the shape
 * of a membrane in equilibrium under that prestress alone is found as the
 * fixed point of a sequence of static solves: solve k finds the shape x_k
 * that carries the homotopy of the Cauchy prestress on x_k and the second
 * Piola-Kirchhoff prestress on x_{k-1} (membrane/form_finding_law.h), and
 * x_k becomes the reference of solve k+1. The iteration stops when one
 * update moves no point farther than Tolerance times the diameter of the
 * surface. The analysis then starts from the found shape, carrying the
 * prestress in it.
 */

#include <pneuma/strategies/solution_strategy.h>

#include <string>

namespace pneuma
{
  namespace strategies
  {
    /// "Form finding": placed before the stages.
    class FormFinding : public SolutionStrategy
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
        return on;
      }

      /// InputError naming the entry if the set-up @p model cannot be
      /// form-found (another subsystem than the membrane, no prestress,
      /// rigid plates, adaptive refinement).
      void
      check(Model &model) const override;

      /// Find the shape; the membrane keeps it as its reference surface,
      /// and its own laws again. Fails (exit 2) if the updates do not
      /// converge.
      Outcome
      run(Run &run, const Segment &segment, const Outcome &start) override;

      /// The Newton iterations of the updates and the last move.
      void
      add_summary(Statistics &row) const override;
      /// Those two, for a restart after the form finding.
      void
      save_summary(Checkpoint &checkpoint) const override;
      void
      load_summary(const Checkpoint &checkpoint) override;

    private:
      bool         on          = false;
      double       lambda      = 0.5;
      unsigned int max_updates = 200;
      double       tolerance   = 1e-6;
      /// The outcome: Newton iterations of all updates, the largest move
      /// of the last update relative to the surface's diameter.
      unsigned int newton_iterations = 0;
      double       last_change       = 0.;
    };
  } // namespace strategies
} // namespace pneuma
