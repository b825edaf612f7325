// Post-buckling of a column by arc length (Load stepping/Control =
// arc-length; doc/verification.md "Elastica"): a cantilever (solid beam,
// radius 5 mm, E = 200 GPa, nu = 0, L = 1 m, clamped at x = 0; Euler load
// P_cr = pi^2 E I/(4 L^2) = 242.2 N) under an end force that grows with
// the load factor t to P = 1.1 P_cr along the axis, with a lateral
// imperfection Q = P/100, on 64 elements (the bending strain stays below
// 0.8 %, where the element's hyperelastic section bends linearly; 32
// elements are 2.9e-3 and 6.8e-3 off). The path rises through the buckling
// load, every state stable, and the tip follows the elastica of an
// inextensible, shear-rigid rod under the inclined end load: EI theta'' = -Q
// cos(theta) - P sin(theta), theta(0) = 0, theta'(L) = 0, solved here by
// shooting (RK4, 2000 steps) for every converged state. Checked: the tip
// displacements within 0.5 % of the largest (the state at P = 1.1 P_cr:
// tip rotation 52 degrees, lateral deflection 0.53 L), the load factor
// rising along the path, no unstable state.

#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  const double E = 2e11, a = 0.005, L = 1., I = M_PI * a * a * a * a / 4.;
  const double P_cr = M_PI * M_PI * E * I / (4. * L * L), P_end = 1.1 * P_cr;

  struct Tip
  {
    double slope = 0., u_x = 0., u_y = 0.;
  };

  /// theta'(L) and the tip displacement for theta'(0) = @p w0.
  Tip
  shoot(const double w0, const double P, const double Q)
  {
    const unsigned int n  = 2000;
    const double       h  = L / n;
    double             th = 0., w = w0, x = 0., y = 0.;
    const auto         f = [&](const double t) {
      return (-Q * std::cos(t) - P * std::sin(t)) / (E * I);
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

  /// The elastica's tip under P, Q: the first root of theta'(L) in
  /// theta'(0) > 0 (the branch of the imperfection).
  Tip
  elastica(const double P, const double Q)
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
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const auto r  = pneuma_test::run({
     {"Geometry/Type", "none"},
     {"Cables/Number of cables", "1"},
     {"Cables/Cable 1/Element", "solid beam"},
     {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
     {"Cables/Cable 1/Number of elements", "64"},
     {"Cables/Cable 1/Section semi-axes",
      pneuma_test::number(a) + ", " + pneuma_test::number(a)},
     {"Cables/Cable 1/solid beam/Section axis", "0, 0, 1"},
     {"Cables/Cable 1/Young's modulus", pneuma_test::number(E)},
     {"Cables/Cable 1/solid beam/Poisson's ratio", "0"},
     {"Cables/Cable 1/Start support", "fixed"},
     {"Cables/Cable 1/End forces", "true"},
     {"Cables/Cable 1/End force/Function expression",
      pneuma_test::number(-P_end) + " * t; " + pneuma_test::number(P_end / 100.)
        + " * t; 0"},
     {"Load stepping/Control", "arc-length"},
     {"Load stepping/Initial increment", "0.02"},
     {"Load stepping/Maximum increment", "0.05"},
     {"Stability/Check inertia", "true"},
  });
  bool       ok = r.exit_code == 0;

  // Every state against the elastica at its own load.
  double       worst = 0., worst_t = 0., last_t = -1.;
  unsigned int states = 0, falling = 0, unstable = 0;
  for (unsigned int k = 1; k < r.history.size(); ++k)
    {
      const auto  &row = r.history[k];
      const double t   = row.get("time");
      const Tip    e   = elastica(P_end * t, P_end * t / 100.);
      const double d   = std::hypot(row.get("cable1_end_u_x") - e.u_x,
                                  row.get("cable1_end_u_y") - e.u_y);
      if (d > worst)
        worst = d, worst_t = t;
      falling += t <= last_t;
      unstable += row.get("negative_eigenvalues") != 0.;
      last_t = t;
      ++states;
    }
  const Tip    end   = elastica(P_end, P_end / 100.);
  const double scale = std::hypot(end.u_x, end.u_y);
  if (root)
    std::printf("%u states to P = 1.1 P_cr; the load factor falls at %u, "
                "unstable states %u (reference 0, 0) %s\n",
                states,
                falling,
                unstable,
                falling + unstable == 0 ? "PASS" : "FAIL");
  ok = ok && falling + unstable == 0 && states > 5;
  if (root)
    std::printf("tip against the elastica: worst distance %.2e of the final "
                "%.4f m, at P = %.3f P_cr "
                "(tolerance 5.0e-03) %s\n",
                worst / scale,
                scale,
                1.1 * worst_t,
                worst / scale < 5e-3 ? "PASS" : "FAIL");
  ok = ok && worst / scale < 5e-3;
  ok = pneuma_test::check("final lateral tip deflection [m]",
                          r.get("cable1_end_u_y"),
                          end.u_y,
                          5e-3)
       && ok;
  ok = pneuma_test::check("final axial tip displacement [m]",
                          r.get("cable1_end_u_x"),
                          end.u_x,
                          5e-3)
       && ok;
  return ok ? 0 : 1;
}
