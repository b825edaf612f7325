#pragma once

// The period of a free vibration from an explicit run's history, shared by
// tests/explicit_waves, explicit_dynamics and shell_explicit_plate.

#include "test_tools.h"

#include <string>
#include <vector>

namespace pneuma_test
{
  /// The times at which @p column crosses @p level after @p from (linear
  /// between rows).
  inline std::vector<double>
  crossings(const pneuma::RunResult &s,
            const std::string       &column,
            const double             level,
            const double             from)
  {
    std::vector<double> z;
    double              t0 = 0., u0 = 0.;
    bool                first = true;
    for (const auto &row : s.history)
      {
        const double t = row.get("time"), u = row.get(column) - level;
        if (t <= from)
          continue;
        if (!first && (u0 < 0.) != (u < 0.))
          z.push_back(t0 + (t - t0) * u0 / (u0 - u));
        t0    = t;
        u0    = u;
        first = false;
      }
    return z;
  }

  /// The period of a signal crossing its level twice per period: the
  /// slope of a least-squares line through the crossings.
  inline double
  period(const std::vector<double> &z)
  {
    const double n = z.size(), k_mean = 0.5 * (n - 1.);
    double       z_mean = 0., skz = 0., skk = 0.;
    for (const double zk : z)
      z_mean += zk / n;
    for (unsigned int k = 0; k < z.size(); ++k)
      {
        skz += (k - k_mean) * (z[k] - z_mean);
        skk += (k - k_mean) * (k - k_mean);
      }
    return 2. * skz / skk;
  }

} // namespace pneuma_test
