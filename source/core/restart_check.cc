#include <pneuma/core/input_error.h>
#include <pneuma/core/restart_check.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <vector>

namespace pneuma
{
  namespace
  {
    /// Entries a restart may change: a trailing '/' matches everything
    /// below, '*' one subsection name; an entry name alone (no '/')
    /// matches that entry in any subsection. The list of restart_check.h.
    const std::vector<std::string> may_change = {
      // Load curves.
      "Function expression",
      "Function constants",
      "Variable names",
      // Stepping and solution control.
      "Load stepping/",
      "Newton/",
      "Linear solver/",
      "Stability/",
      "Eigen analysis/",
      // Output and checkpoints (not the monitor and probe points: they
      // make history.csv's columns).
      "Output/Directory",
      "Output/Quiet",
      "Output/Test output",
      "Output/VTU interval",
      "Output/Write VTU",
      "Checkpoint/",
      // Contact normals (doc/user-guide.md "Checkpoint and restart").
      "Contact/*/Master normal",
      "Contact/*/Smoothed normal from",
    };

    /// Does @p entry ("A/B/C") match @p pattern?
    bool
    matches(const std::string &entry, const std::string &pattern)
    {
      if (pattern.find('/') == std::string::npos)
        {
          const auto slash = entry.rfind('/');
          return entry.substr(slash == std::string::npos ? 0 : slash + 1)
                 == pattern;
        }
      std::size_t e = 0;
      for (std::size_t p = 0; p < pattern.size(); ++p)
        {
          if (pattern[p] == '*')
            {
              // One subsection name: everything up to the next '/'.
              e = entry.find('/', e);
              if (e == std::string::npos)
                return false;
              continue;
            }
          if (e >= entry.size() || entry[e] != pattern[p])
            return false;
          ++e;
        }
      return e == entry.size() || pattern.back() == '/';
    }

    bool
    may_change_entry(const std::string &entry)
    {
      return std::any_of(may_change.begin(),
                         may_change.end(),
                         [&](const std::string &p) {
                           return matches(entry, p);
                         });
    }

    /// The same value: as text without blanks, or as numbers.
    bool
    same_value(const std::string &a, const std::string &b)
    {
      const auto compact = [](std::string s) {
        s.erase(std::remove_if(s.begin(),
                               s.end(),
                               [](const unsigned char c) {
                                 return std::isspace(c);
                               }),
                s.end());
        return s;
      };
      if (compact(a) == compact(b))
        return true;
      char        *end_a = nullptr, *end_b = nullptr;
      const double x = std::strtod(a.c_str(), &end_a);
      const double y = std::strtod(b.c_str(), &end_b);
      return end_a != a.c_str() && end_b != b.c_str() && compact(end_a).empty()
             && compact(end_b).empty() && x == y;
    }

    std::string
    quoted(const std::string &value)
    {
      return "'" + value + "'";
    }
  } // namespace

  void
  check_restart_parameters(const Checkpoint                         &checkpoint,
                           const std::map<std::string, std::string> &current)
  {
    const auto saved =
      checkpoint.get<std::map<std::string, std::string>>("run/parameters");
    const std::string why =
      "; a restart continues the checkpoint's discrete problem and may "
      "change only load curves, stepping, solver, output and checkpoint "
      "entries (doc/user-guide.md \"Checkpoint and restart\"; --restart "
      + checkpoint.directory() + ")";
    // Entries of both first (a changed count names the count, not the
    // instances it adds or removes), then those of one only.
    for (const auto &[entry, value] : current)
      {
        const auto it = saved.find(entry);
        if (it != saved.end() && !may_change_entry(entry))
          check_input(same_value(value, it->second),
                      entry,
                      "is " + quoted(value) + " here but was "
                        + quoted(it->second) + " in the checkpoint's run"
                        + why);
      }
    for (const auto &[entry, value] : current)
      check_input(saved.count(entry) > 0 || may_change_entry(entry),
                  entry,
                  "is not an entry of the checkpoint's run" + why);
    for (const auto &[entry, value] : saved)
      check_input(current.count(entry) > 0 || may_change_entry(entry),
                  entry,
                  "was " + quoted(value)
                    + " in the checkpoint's run but is not declared here"
                    + why);
  }
} // namespace pneuma
