#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/solvers/form_finding.h>
#include <pneuma/solvers/newton_solver.h>

#include <iomanip>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    void
    FormFinding::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Form finding");
      prm.add_parameter("Enabled",
                        on,
                        "Find the equilibrium shape of the membrane under "
                        "its regions' Prestress before the analysis "
                        "(updated reference strategy); the analysis starts "
                        "from that shape. Supports stay where the input "
                        "surface puts them; loads act only in the analysis.",
                        Patterns::Bool());
      prm.add_parameter("Homotopy factor",
                        lambda,
                        "lambda in [0, 1): the weight of the true (Cauchy) "
                        "prestress on the unknown shape against the "
                        "constant prestress on the last one (0: the force "
                        "density limit, every update one linear solve). "
                        "The found shape does not depend on it; it must be "
                        "0 for an anisotropic prestress.",
                        Patterns::Double());
      prm.add_parameter("Maximum updates",
                        max_updates,
                        "Updates of the reference surface before the form "
                        "finding gives up (exit 2, the last shape written).",
                        Patterns::Integer(1, 100000));
      prm.add_parameter("Tolerance",
                        tolerance,
                        "Converged when an update moves no node farther "
                        "than this fraction of the surface's diameter.",
                        Patterns::Double());
      prm.leave_subsection();
    }

    void
    FormFinding::parse_parameters(ParameterHandler &)
    {
      check_input(lambda >= 0. && lambda < 1.,
                  "Form finding/Homotopy factor",
                  "must be in [0, 1), got " + std::to_string(lambda));
      check_input(tolerance > 0. && tolerance < 1.,
                  "Form finding/Tolerance",
                  "must be in (0, 1), got " + std::to_string(tolerance));
    }

    void
    FormFinding::check(Model &model) const
    {
      if (!on)
        return;
      auto *membrane = model.find<membrane::MembraneSubsystem>();
      check_input(membrane != nullptr,
                  "Form finding/Enabled",
                  "the scene has no membrane (Geometry/Type is none)");
      std::string others;
      for (const auto &s : model.all())
        if (s.get() != membrane)
          others += (others.empty() ? "" : ", ") + s->name();
      check_input(others.empty(),
                  "Form finding/Enabled",
                  "form finding works on a membrane alone; this scene also "
                  "has: "
                    + others);
      membrane->begin_form_finding(lambda);
      membrane->end_form_finding();
    }

    FormFindingResult
    FormFinding::run(Model                    &model,
                     const NewtonSolver       &newton,
                     const ConditionalOStream &out) const
    {
      FormFindingResult result;
      auto             *membrane = model.find<membrane::MembraneSubsystem>();
      membrane->begin_form_finding(lambda);
      model.reconstrain();
      const double             diameter = membrane->reference_diameter();
      const ConditionalOStream quiet(std::cout, false);
      out << "form finding (updated reference, lambda = " << lambda
          << "):" << std::endl;
      for (unsigned int k = 1; k <= max_updates; ++k)
        {
          BorderedVector state     = model.initial_state();
          const auto newton_result = newton.solve(model, state, quiet, false);
          result.newton_iterations += newton_result.iterations;
          if (!newton_result.converged)
            {
              result.message = "the form finding's update " + std::to_string(k)
                               + " did not converge ("
                               + newton_result.failure_reason + ")";
              break;
            }
          result.last_change =
            membrane->move_reference(model.ghost(state.field)) / diameter;
          result.updates = k;
          if (k <= 3 || k % 10 == 0 || result.last_change <= tolerance)
            out << "  update " << std::setw(4) << k << ": largest move "
                << std::scientific << std::setprecision(2) << result.last_change
                << " of the diameter, " << newton_result.iterations
                << " Newton iteration(s)" << std::defaultfloat << std::endl;
          if (result.last_change <= tolerance)
            {
              result.converged = true;
              break;
            }
        }
      if (!result.converged && result.message.empty())
        result.message =
          "the form finding did not converge in " + std::to_string(max_updates)
          + " updates (Form finding/Maximum updates; last "
            "move "
          + std::to_string(result.last_change) + " of the diameter)";
      membrane->end_form_finding();
      model.reconstrain();
      return result;
    }
  } // namespace solvers
} // namespace pneuma
