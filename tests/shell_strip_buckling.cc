// Euler buckling of a plate strip, the Kirchhoff-Love shell
// (membrane/bending, doc/theory.md §21) through a bifurcation and into
// the post-buckling range: a cantilever strip 1 m x 0.1 m, t = 1 cm,
// E = 1 GPa, nu = 0 (EI = E b t^3/12 without anticlastic bending),
// clamped at x = -1/2 (Bending/Clamped boundaries, held in xyz), on
// 20 x 2 Q2 cells, compressed by a dead line load on its free end.
// - Linear buckling (Eigen analysis/Type = buckling) of the unloaded
//   strip under the axial load: P_cr = pi^2 EI/(4 L^2) = 20.56 N, on
//   20 x 2 and 40 x 4 cells, and the order of its error.
// - Arc length (Load stepping/Control = arc-length) with an imperfection:
//   the end load grows with the load factor to P = 1.1 P_cr along the
//   strip with a lateral Q = P/100 across it. Every converged state
//   against the elastica of the strip under the same end loads
//   (tests/elastica.h), the load factor rising, every state stable; and
//   Southwell's estimate of P_cr from the states below 0.9 P_cr (the
//   slope of w/P against w).
// The same on 2 ranks.

#include "elastica.h"
#include "shell_strip.h"

#include <cmath>
#include <cstdio>

namespace
{
  const double E = 1e9, t = 0.01, b = 0.1, L = 1.;
  const double EI   = E * b * t * t * t / 12.;
  const double P_cr = M_PI * M_PI * EI / (4. * L * L), P_end = 1.1 * P_cr;

  /// The strip clamped at boundary 0 (x = -1/2), end loads (per unit
  /// width) on boundary 1 given by @p load, its tip monitored.
  pneuma_test::Settings
  strip(const std::string &load, const unsigned int refinements = 1)
  {
    auto settings = pneuma_test::shell_strip(2, refinements);
    settings.insert(settings.end(),
                    {{"Loads/Line load boundaries", "1"},
                     {"Loads/Line load/Function expression", load}});
    return settings;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root = pneuma_test::root();
  bool                                     ok   = true;

  // Linear buckling under a reference end load of 18 N (0.9 P_cr, the
  // safe choice: the load rate's stiffness comes from finite differences
  // of tangents, whose round-off against the membrane stiffness E t grows
  // as the reference load falls; doc/verification.md), on 20 x 2 and
  // 40 x 4 cells.
  double P[2];
  for (unsigned int r = 1; r <= 2; ++r)
    {
      const double P_ref = 10.;
      auto settings = strip(pneuma_test::number(-P_ref / b) + "*t; 0; 0", r);
      settings.insert(settings.end(),
                      {{"Eigen analysis/Type", "buckling"},
                       {"Eigen analysis/Number of modes", "1"}});
      const auto s = pneuma_test::run(settings);
      if (pneuma_test::failed(s, "buckling analysis"))
        return 1;
      P[r - 1] = P_ref * s.get("mode1_critical_time");
    }
  ok = pneuma_test::check("linear buckling on 20 x 2 cells: P_cr [N]",
                          P[0],
                          P_cr,
                          2e-3)
       && ok;
  ok = pneuma_test::check("linear buckling on 40 x 4 cells: P_cr [N]",
                          P[1],
                          P_cr,
                          2e-4)
       && ok;
  const double order =
    std::log(std::abs(P[0] - P_cr) / std::abs(P[1] - P_cr)) / std::log(2.);
  if (root)
    std::printf("order of the buckling load's error from 20 x 2 to 40 x 4 "
                "cells: at least 1.9 %s\n",
                order > 1.9 ? "PASS" : "FAIL");
  ok = order > 1.9 && ok;

  // Arc length to 1.1 P_cr with a lateral imperfection Q = P/100.
  auto settings = strip(pneuma_test::number(-P_end / b) + "*t; 0; "
                        + pneuma_test::number(P_end / 100. / b) + "*t");
  settings.insert(settings.end(),
                  {{"Load stepping/Control", "arc-length"},
                   {"Load stepping/Initial increment", "0.02"},
                   {"Load stepping/Maximum increment", "0.05"},
                   {"Stability/Check inertia", "true"}});
  const auto r = pneuma_test::run(settings);
  if (pneuma_test::failed(r, "arc length"))
    return 1;
  ok = pneuma_test::check_elastica_path(
         r, pneuma_test::Elastica{EI, L}, P_end, "m0_u_x", "m0_u_z")
       && ok;
  // Southwell: w/P = w/P_cr + c, fitted over the states below 0.9 P_cr.
  double sx = 0., sy = 0., sxx = 0., sxy = 0., n = 0.;
  for (unsigned int k = 1; k < r.history.size(); ++k)
    {
      const double P = P_end * r.history[k].get("time");
      if (P < 0.9 * P_cr)
        {
          const double w = r.history[k].get("m0_u_z"), y = w / P;
          sx += w, sy += y, sxx += w * w, sxy += w * y, n += 1.;
        }
    }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  ok = pneuma_test::check("Southwell's estimate of P_cr from the path [N]",
                          1. / slope,
                          P_cr,
                          2e-2)
       && ok;
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
