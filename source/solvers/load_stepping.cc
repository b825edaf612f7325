#include <deal.II/base/utilities.h>

#include <pneuma/core/input_error.h>
#include <pneuma/solvers/load_stepping.h>

#include <algorithm>

namespace pneuma
{
  namespace solvers
  {
    void
    LoadStepping::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      prm.declare_entry("Stage end times",
                        "1",
                        Patterns::List(Patterns::Double(0.), 1),
                        "Pseudo times at which the load stages end, "
                        "increasing; the run ends at the last one.");
      prm.declare_entry("Initial increment",
                        "0.25",
                        Patterns::Double(0.),
                        "First pseudo-time increment; > 0.");
      prm.declare_entry("Minimum increment",
                        "1e-4",
                        Patterns::Double(0.),
                        "The run stops (exit 2) when a cut back would go "
                        "below this; > 0.");
      prm.declare_entry("Maximum increment",
                        "1",
                        Patterns::Double(0.),
                        "Largest pseudo-time increment; > 0.");
      prm.declare_entry("Growth factor",
                        "1.5",
                        Patterns::Double(1.),
                        "Increment growth after an easy step.");
      prm.declare_entry("Cut-back factor",
                        "0.5",
                        Patterns::Double(0.01, 0.99),
                        "Increment reduction after a failed step.");
      prm.declare_entry("Easy iterations",
                        "5",
                        Patterns::Integer(1),
                        "A step that converges in at most this many Newton "
                        "iterations is easy.");
      prm.leave_subsection();
    }

    void
    LoadStepping::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      stage_ends = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Stage end times")));
      initial_increment = prm.get_double("Initial increment");
      minimum_increment = prm.get_double("Minimum increment");
      maximum_increment = prm.get_double("Maximum increment");
      growth_factor     = prm.get_double("Growth factor");
      cut_back_factor   = prm.get_double("Cut-back factor");
      easy_iterations   = prm.get_integer("Easy iterations");
      prm.leave_subsection();

      const std::string p = "Load stepping/";
      check_input(stage_ends.front() > 0.
                    && std::is_sorted(stage_ends.begin(), stage_ends.end())
                    && std::adjacent_find(stage_ends.begin(), stage_ends.end())
                         == stage_ends.end(),
                  p + "Stage end times",
                  "must be positive and strictly increasing");
      check_input(initial_increment > 0.,
                  p + "Initial increment",
                  "must be > 0");
      check_input(minimum_increment > 0.
                    && minimum_increment <= initial_increment,
                  p + "Minimum increment",
                  "must be > 0 and <= Initial increment");
      check_input(maximum_increment >= initial_increment,
                  p + "Maximum increment",
                  "must be >= Initial increment");
    }

    unsigned int
    LoadStepping::stage_of(const double t) const
    {
      const double eps = 1e-12 * end_time();
      for (unsigned int s = 0; s < stage_ends.size(); ++s)
        if (t < stage_ends[s] - eps)
          return s;
      return stage_ends.size() - 1;
    }

    double
    LoadStepping::next_time(const double t, const double dt) const
    {
      const double stage_end = stage_ends[stage_of(t)];
      const double target    = t + dt;
      // Do not leave a sliver shorter than a tenth of a step.
      if (target > stage_end - 0.1 * dt)
        return stage_end;
      return target;
    }

    double
    LoadStepping::grown(const double dt, const unsigned int iterations) const
    {
      return (iterations <= easy_iterations)
               ? std::min(dt * growth_factor, maximum_increment)
               : dt;
    }

    bool
    LoadStepping::finished(const double t) const
    {
      return t >= end_time() * (1. - 1e-12);
    }
  } // namespace solvers
} // namespace pneuma
