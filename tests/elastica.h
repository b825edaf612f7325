#pragma once

// The elastica of a cantilever (inextensible, shear-rigid, clamped at
// s = 0) under dead end loads: an axial compression P and a lateral force
// Q, EI theta'' = -Q cos(theta) - P sin(theta), theta(0) = 0,
// theta'(L) = 0, solved by shooting (RK4, 2000 steps) on theta'(0). Used
// by tests/elastica_column (a solid beam) and tests/shell_strip_buckling
// (a shell strip).

#include "test_tools.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace pneuma_test
{
  struct Elastica
  {
    double EI, L;

    struct Tip
    {
      double slope = 0., u_x = 0., u_y = 0.;
    };

    /// theta'(L) and the tip displacement for theta'(0) = @p w0.
    Tip
    shoot(const double w0, const double P, const double Q) const
    {
      const unsigned int n  = 2000;
      const double       h  = L / n;
      double             th = 0., w = w0, x = 0., y = 0.;
      const auto         f = [&](const double t) {
        return (-Q * std::cos(t) - P * std::sin(t)) / EI;
      };
      for (unsigned int i = 0; i < n; ++i)
        {
          const double k1t = w, k1w = f(th);
          const double k2t = w + 0.5 * h * k1w, k2w = f(th + 0.5 * h * k1t);
          const double k3t = w + 0.5 * h * k2w, k3w = f(th + 0.5 * h * k2t);
          const double k4t = w + h * k3w, k4w = f(th + h * k3t);
          const double th_new = th + h / 6. * (k1t + 2. * k2t + 2. * k3t + k4t);
          const double mid    = th + 0.5 * h * k1t + h * h / 8. * k1w;
          x += h / 6. * (std::cos(th) + 4. * std::cos(mid) + std::cos(th_new));
          y += h / 6. * (std::sin(th) + 4. * std::sin(mid) + std::sin(th_new));
          w += h / 6. * (k1w + 2. * k2w + 2. * k3w + k4w);
          th = th_new;
        }
      return {w, x - L, y};
    }

    /// The tip under P, Q: the first root of theta'(L) in theta'(0) > 0
    /// (the branch of the imperfection).
    Tip
    operator()(const double P, const double Q) const
    {
      double lo = 0., f_lo = shoot(0., P, Q).slope;
      for (double w0 = 0.01; w0 < 10.; w0 += 0.01)
        {
          const double f_w = shoot(w0, P, Q).slope;
          if (f_lo * f_w <= 0.)
            {
              double hi = w0;
              for (unsigned int k = 0; k < 60; ++k)
                {
                  const double mid   = 0.5 * (lo + hi),
                               f_mid = shoot(mid, P, Q).slope;
                  if (f_lo * f_mid <= 0.)
                    hi = mid;
                  else
                    lo = mid, f_lo = f_mid;
                }
              return shoot(0.5 * (lo + hi), P, Q);
            }
          lo = w0, f_lo = f_w;
        }
      return {};
    }
  };

  /**
   * Every converged state of the arc-length run @p r against @p elastica
   * at its own end loads P = P_end t, Q = P/100 (the tip's displacement
   * in the history columns @p ux and @p uy): prints the states, where the
   * load factor falls and the unstable ones (none expected), the worst
   * distance from the elastica against the final tip's (tolerance 5e-3),
   * and checks the final tip; true if all pass.
   */
  inline bool
  check_elastica_path(const pneuma::RunResult &r,
                      const Elastica          &elastica,
                      const double             P_end,
                      const std::string       &ux,
                      const std::string       &uy)
  {
    double       worst = 0., worst_t = 0., last_t = -1.;
    unsigned int states = 0, falling = 0, unstable = 0;
    for (unsigned int k = 1; k < r.history.size(); ++k)
      {
        const auto  &row = r.history[k];
        const double t   = row.get("time");
        const auto   e   = elastica(P_end * t, P_end * t / 100.);
        const double d   = std::hypot(row.get(ux) - e.u_x, row.get(uy) - e.u_y);
        if (d > worst)
          worst = d, worst_t = t;
        falling += t <= last_t;
        unstable += row.get("negative_eigenvalues") != 0.;
        last_t = t;
        ++states;
      }
    const auto   end   = elastica(P_end, P_end / 100.);
    const double scale = std::hypot(end.u_x, end.u_y);
    if (root())
      std::printf("%u states to P = 1.1 P_cr; the load factor falls at %u, "
                  "unstable states %u (reference 0, 0) %s\n",
                  states,
                  falling,
                  unstable,
                  falling + unstable == 0 ? "PASS" : "FAIL");
    bool ok = r.exit_code == 0 && falling + unstable == 0 && states > 5;
    if (root())
      std::printf("tip against the elastica: worst distance %.2e of the "
                  "final %.4f m, at P = %.3f P_cr (tolerance 5.0e-03) %s\n",
                  worst / scale,
                  scale,
                  1.1 * worst_t,
                  worst / scale < 5e-3 ? "PASS" : "FAIL");
    ok = ok && worst / scale < 5e-3;
    ok =
      check("final lateral tip deflection [m]", r.get(uy), end.u_y, 5e-3) && ok;
    ok =
      check("final axial tip displacement [m]", r.get(ux), end.u_x, 5e-3) && ok;
    return ok;
  }
} // namespace pneuma_test
