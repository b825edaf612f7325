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

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace pneuma
{
  class Model;

  namespace solvers
  {
    class NewtonSolver;

    /// The outcome of a form finding.
    struct FormFindingResult
    {
      bool         converged         = false;
      unsigned int updates           = 0;
      unsigned int newton_iterations = 0;
      /// The largest displacement of the last update, relative to the
      /// diameter of the surface.
      double      last_change = 0.;
      std::string message;
    };

    /// The "Form finding" subsection and the iteration.
    class FormFinding
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      bool
      enabled() const
      {
        return on;
      }

      /// InputError naming the entry if the set-up @p model cannot be
      /// form-found (another subsystem than the membrane, no prestress,
      /// rigid plates, adaptive refinement).
      void
      check(Model &model) const;

      /// Find the shape; the membrane of @p model keeps it as its
      /// reference surface, and its own laws again.
      FormFindingResult
      run(Model                            &model,
          const NewtonSolver               &newton,
          const dealii::ConditionalOStream &out) const;

    private:
      bool         on          = false;
      double       lambda      = 0.5;
      unsigned int max_updates = 200;
      double       tolerance   = 1e-6;
    };
  } // namespace solvers
} // namespace pneuma
