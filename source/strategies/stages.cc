#include <deal.II/base/utilities.h>

#include <pneuma/core/input_error.h>
#include <pneuma/strategies/stages.h>

#include <algorithm>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    void
    Stages::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      prm.add_parameter("Stage end times",
                        ends,
                        "Pseudo times at which the load stages end, "
                        "increasing; the run ends at the last one.",
                        Patterns::List(Patterns::Double(0.), 1));
      prm.add_parameter(
        "Strategy",
        names,
        "The solution strategy of each stage, one entry per stage (or one "
        "for all): "
          + strategy_names(Placement::stage, ", ")
          + ". Consecutive stages of one strategy run as one segment; the "
            "next segment starts from the state the last one reached.",
        Patterns::List(Patterns::Anything(), 1));
      prm.leave_subsection();
    }

    void
    Stages::parse_parameters(ParameterHandler &)
    {
      const std::string p = "Load stepping/";
      check_input(ends.front() > 0. && std::is_sorted(ends.begin(), ends.end())
                    && std::adjacent_find(ends.begin(), ends.end())
                         == ends.end(),
                  p + "Stage end times",
                  "must be positive and strictly increasing");
      check_input(names.size() == 1 || names.size() == ends.size(),
                  p + "Strategy",
                  "needs one entry, or one per stage ("
                    + std::to_string(ends.size()) + " stages in Stage end "
                    + "times), not " + std::to_string(names.size()));
      for (auto &name : names)
        {
          name       = Utilities::trim(name);
          bool known = false;
          for (const auto &e : strategy_entries())
            known |= e.placement == Placement::stage && e.name == name;
          check_input(known,
                      p + "Strategy",
                      "unknown '" + name + "'; valid: "
                        + strategy_names(Placement::stage, ", "));
        }
    }

    unsigned int
    Stages::stage_of(const double t) const
    {
      const double eps = 1e-12 * end_time();
      for (unsigned int s = 0; s < ends.size(); ++s)
        if (t < ends[s] - eps)
          return s;
      return ends.size() - 1;
    }

    bool
    Stages::finished(const double t, const double t_end) const
    {
      return t >= (t_end < 0. ? end_time() : t_end) * (1. - 1e-12);
    }

    bool
    Stages::uses(const std::string &name) const
    {
      return std::find(names.begin(), names.end(), name) != names.end();
    }

    std::vector<Segment>
    Stages::segments() const
    {
      std::vector<Segment> all;
      for (unsigned int s = 0; s < n_stages(); ++s)
        if (all.empty() || strategy(s) != strategy(all.back().last))
          all.push_back({s, s, static_cast<unsigned int>(all.size())});
        else
          all.back().last = s;
      return all;
    }
  } // namespace strategies
} // namespace pneuma
