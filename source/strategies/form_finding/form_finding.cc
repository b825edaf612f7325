#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/solvers/newton_solver.h>
#include <pneuma/strategies/form_finding/form_finding.h>
#include <pneuma/strategies/run.h>

#include <iomanip>

namespace pneuma
{
  namespace strategies
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
    FormFinding::parse_parameters(ParameterHandler &, const Stages &)
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

    Outcome
    FormFinding::run(Run &run, const Segment &, const Outcome &start)
    {
      Outcome outcome  = start;
      Model  &model    = run.model;
      auto   *membrane = model.find<membrane::MembraneSubsystem>();
      membrane->begin_form_finding(lambda);
      model.reconstrain();
      const double             diameter = membrane->reference_diameter();
      const ConditionalOStream quiet(std::cout, false);
      run.out << "form finding (updated reference, lambda = " << lambda
              << "):" << std::endl;
      newton_iterations = 0;
      bool converged    = false;
      for (unsigned int k = 1; k <= max_updates && !converged; ++k)
        {
          solvers::BorderedVector state = model.initial_state();
          const auto newton = run.newton.solve(model, state, quiet, false);
          newton_iterations += newton.iterations;
          if (!newton.converged)
            {
              outcome.message = "the form finding's update " + std::to_string(k)
                                + " did not converge (" + newton.failure_reason
                                + ")";
              break;
            }
          last_change =
            membrane->move_reference(model.ghost(state.field)) / diameter;
          converged = last_change <= tolerance;
          if (k <= 3 || k % 10 == 0 || converged)
            run.out << "  update " << std::setw(4) << k << ": largest move "
                    << std::scientific << std::setprecision(2) << last_change
                    << " of the diameter, " << newton.iterations
                    << " Newton iteration(s)" << std::defaultfloat << std::endl;
        }
      if (!converged && outcome.message.empty())
        outcome.message = "the form finding did not converge in "
                          + std::to_string(max_updates)
                          + " updates (Form finding/Maximum updates; last "
                            "move "
                          + std::to_string(last_change) + " of the diameter)";
      outcome.exit_code = converged ? 0 : 2;
      membrane->end_form_finding();
      model.reconstrain();
      return outcome;
    }

    void
    FormFinding::add_summary(Statistics &row) const
    {
      const auto             run    = StatisticsGroup::run();
      constexpr unsigned int counts = Statistics::summary;
      row.add_count(run,
                    "form_finding_newton_iterations",
                    newton_iterations,
                    counts);
      row.add(run, "form_finding_last_move", "", last_change, counts);
    }

    void
    FormFinding::save_summary(Checkpoint &checkpoint) const
    {
      checkpoint.put("form finding/newton_iterations", newton_iterations);
      checkpoint.put("form finding/last_move", last_change);
    }

    void
    FormFinding::load_summary(const Checkpoint &checkpoint)
    {
      newton_iterations =
        checkpoint.get<unsigned int>("form finding/newton_iterations");
      last_change = checkpoint.get<double>("form finding/last_move");
    }

    PNEUMA_REGISTER_STRATEGY(FormFinding,
                             "form finding",
                             Placement::before_stages,
                             "the shape of a prestressed membrane between "
                             "its supports, by updated reference");
  } // namespace strategies
} // namespace pneuma
