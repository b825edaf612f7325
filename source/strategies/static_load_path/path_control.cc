#include <deal.II/base/utilities.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/strategies/static_load_path/path_control.h>

#include <cstdlib>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    void
    PathControl::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Path following");
      add_selection(prm,
                    "Constraint",
                    spherical,
                    {{"cylindrical", false}, {"spherical", true}},
                    "Arc-length constraint: cylindrical (Crisfield: "
                    "the displacement increment alone) or spherical "
                    "(displacement and load factor increments alike).");
      prm.add_parameter("Monitor point",
                        monitor_point,
                        "Index (from 0) into Output/Monitor points of the "
                        "point whose displacement is monitored: prescribed "
                        "under displacement control, the target below, and "
                        "reported at critical points.",
                        Patterns::Integer(0));
      prm.add_parameter("Monitor component",
                        monitor_component,
                        "Displacement component of the monitor.",
                        Patterns::Selection("x|y|z"));
      prm.add_parameter("Target monitor value",
                        target_text,
                        "The last stage, if path-controlled, ends when the "
                        "monitored displacement [m] reaches this value "
                        "(empty: when the load factor reaches the stage's "
                        "end).",
                        Patterns::Anything());
      prm.add_parameter("Maximum steps",
                        max_path_steps,
                        "A path-controlled stage that has not reached its "
                        "end in this many steps stops the run (exit 2).",
                        Patterns::Integer(1));
      prm.add_parameter("Stop at critical point",
                        stop_at_critical_point,
                        "Stop the run (exit 0) at the first critical point "
                        "of a path-controlled stage, once located.");
      prm.leave_subsection();
    }

    void
    PathControl::parse_parameters(const bool last_is_path)
    {
      const std::string entry =
        "Load stepping/Path following/Target monitor value";
      const std::string text = Utilities::trim(target_text);
      with_target            = !text.empty();
      if (!with_target)
        return;
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      check_input(end != text.c_str() && *end == '\0' && std::isfinite(value),
                  entry,
                  "must be a finite number or empty, not '" + text + "'");
      target_value = value;
      check_input(last_is_path,
                  entry,
                  "applies to the last stage, which is under load "
                  "control (set Load stepping/Control)");
    }

    void
    PathControl::check_monitor_point(const unsigned int n_points,
                                     const std::string &what) const
    {
      check_input(monitor_point < n_points,
                  "Load stepping/Path following/Monitor point",
                  what
                    + (n_points == 0
                         ? std::string(" (Output/Monitor points is empty)")
                         : ": it is " + std::to_string(monitor_point)
                             + ", but Output/Monitor points has "
                             + std::to_string(n_points)
                             + " point(s), numbered from 0"));
    }

    LA::Vector
    PathControl::monitor_functional(const Model &model) const
    {
      if (monitor_point >= model.n_monitor_points())
        return LA::Vector();
      LA::Vector         w = model.make_field();
      const unsigned int c = monitor_component[0] - 'x';
      const auto         i = model.monitor_dof(monitor_point, c);
      if (i != numbers::invalid_dof_index)
        w[i] = 1.;
      w.compress(VectorOperation::insert);
      return w;
    }
  } // namespace strategies
} // namespace pneuma
