#include <deal.II/base/utilities.h>

#include <pneuma/core/input_error.h>
#include <pneuma/strategies/static_load_path/load_stepping.h>

#include <algorithm>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    void
    LoadStepping::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      prm.add_parameter("Initial increment",
                        initial_increment,
                        "First pseudo-time increment; > 0.",
                        Patterns::Double(0.));
      prm.add_parameter("Minimum increment",
                        minimum_increment,
                        "The run stops (exit 2) when a cut back would go "
                        "below this; > 0.",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Maximum increment",
        maximum_increments,
        "Largest pseudo-time increment; > 0. One value for all stages, "
        "or one per stage (e.g. large steps through a filling that "
        "converges easily, smaller ones where a curve is wanted). In a "
        "path-controlled stage: the largest change of the load factor "
        "per step (the arc length grows freely). A stage starts with at "
        "most its maximum.",
        Patterns::List(Patterns::Double(0.), 1));
      prm.add_parameter("Growth factor",
                        growth_factor,
                        "Increment growth after an easy step.",
                        Patterns::Double(1.));
      prm.add_parameter("Cut-back factor",
                        cut_back_factor,
                        "Increment reduction after a failed step.",
                        Patterns::Double(0.01, 0.99));
      prm.add_parameter("Easy iterations",
                        easy_iterations,
                        "A step that converges in at most this many Newton "
                        "iterations is easy.",
                        Patterns::Integer(1));
      prm.leave_subsection();
    }

    void
    LoadStepping::parse_parameters(ParameterHandler &, const Stages &stages)
    {
      all_stages          = &stages;
      const std::string p = "Load stepping/";
      check_input(initial_increment > 0.,
                  p + "Initial increment",
                  "must be > 0");
      check_input(minimum_increment > 0.
                    && minimum_increment <= initial_increment,
                  p + "Minimum increment",
                  "must be > 0 and <= Initial increment");
      check_input(maximum_increments.size() == 1
                    || maximum_increments.size() == stages.n_stages(),
                  p + "Maximum increment",
                  "needs one value, or one per stage ("
                    + std::to_string(stages.n_stages())
                    + " stages in Stage end times), not "
                    + std::to_string(maximum_increments.size()));
      check_input(maximum_increments.front() >= initial_increment,
                  p + "Maximum increment",
                  "must be >= Initial increment (the first stage's)");
      check_input(*std::min_element(maximum_increments.begin(),
                                    maximum_increments.end())
                    >= minimum_increment,
                  p + "Maximum increment",
                  "must be >= Minimum increment in every stage");
    }

    double
    LoadStepping::next_time(const double t, const double dt) const
    {
      const double stage_end = all_stages->end(all_stages->stage_of(t));
      const double target    = t + dt;
      // Do not leave a sliver shorter than a tenth of a step.
      if (target > stage_end - 0.1 * dt)
        return stage_end;
      return target;
    }

    double
    LoadStepping::grown(const double       dt,
                        const unsigned int iterations,
                        const bool         capped,
                        const double       t) const
    {
      const double next =
        iterations > easy_iterations ? dt : dt * growth_factor;
      return capped ? std::min(next, maximum(all_stages->stage_of(t))) : next;
    }

  } // namespace strategies
} // namespace pneuma
