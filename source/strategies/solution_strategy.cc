#include <pneuma/strategies/solution_strategy.h>

#include <algorithm>

namespace pneuma
{
  namespace strategies
  {
    namespace
    {
      std::vector<StrategyEntry> &
      registry()
      {
        static std::vector<StrategyEntry> entries;
        return entries;
      }
    } // namespace

    bool
    register_strategy(const StrategyEntry &entry)
    {
      // By placement, then by name: the order does not depend on the
      // order in which the linker runs the registrations.
      auto &entries = registry();
      entries.push_back(entry);
      std::sort(entries.begin(),
                entries.end(),
                [](const StrategyEntry &a, const StrategyEntry &b) {
                  return a.placement != b.placement ? a.placement < b.placement
                                                    : a.name < b.name;
                });
      return true;
    }

    const std::vector<StrategyEntry> &
    strategy_entries()
    {
      return registry();
    }

    std::string
    strategy_names(const Placement p, const std::string &separator)
    {
      std::string s;
      for (const auto &e : registry())
        if (e.placement == p)
          s += (s.empty() ? "" : separator) + e.name;
      return s;
    }
  } // namespace strategies
} // namespace pneuma
