// Kirchhoff-Love shells on the membrane's surface (membrane/bending,
// doc/theory.md §21): the bending energy in the cells and the C0 interior
// penalty on the edges, geometrically exact.
// - The tangent of a disc with bending, clamped at its rim (Q2 and Q1), at
//   a smooth perturbation of 0.1 m against central differences of the
//   residual.
// - Small deflection (w/t < 1e-3): a circular plate (R = 1 m, t = 1 cm,
//   E = 1 GPa, nu = 0.3, Q2) under a uniform load q, clamped and simply
//   supported, on three meshes: the centre's deflection against
//   Kirchhoff's w = q R^4/(64 D) and q R^4 (5 + nu)/(64 D (1 + nu)),
//   D = E t^3/(12 (1 - nu^2)), and the observed order of its error.
// - Square plates (side a = 1 m, the same plate) clamped and simply
//   supported under q on 8 x 8 to 32 x 32 cells (simply supported: 4 x 4
//   to 16 x 16): the centre's deflection
//   against Timoshenko & Woinowsky-Krieger's alpha q a^4/D (0.00126532,
//   0.00406235) and the observed order of its error (clamped: 1.76 there
//   and 1.9 on to 64 x 64, where the error is -7.9e-4: the weakly clamped
//   corners converge later than the disc's rim).
// - Large rotation: a cantilever strip (1 m x 0.1 m, t = 1 cm, nu = 0)
//   clamped at one end, a dead load P = 2 EI/L^2 across its free end: the
//   tip's displacement against the elastica (theta'' = -P L^2/EI cos theta
//   by Runge-Kutta shooting) and its bending energy against EI/2 int
//   theta'^2 ds, and Newton's rate in the last step; on Q1 cells (the
//   bending in the kinks between cells, gamma = 1) its first-order
//   convergence; with an orthotropic law whose fill (E2 = E1/2) runs
//   along the strip, the elastica of P L^2/(E2 I) = 4.
// The same on 2 ranks.

#include "shell_strip.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace
{
  /// The disc plate (bending shell, rim held in xyz) under q [Pa].
  pneuma_test::Settings
  plate(const unsigned int refinements, const bool clamped, const double q)
  {
    return {
      {"Geometry/Type", "disc"},
      {"Geometry/disc/Radius", "1"},
      {"Geometry/Global refinements", std::to_string(refinements)},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Thickness", "0.01"},
      {"Materials/Region 0/Bending", "shell"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"},
      {"Bending/Clamped boundaries", clamped ? "0" : ""},
      {"Boundary conditions/Fixed boundaries", "0: xyz"},
      {"Loads/Surface load", "true"},
      {"Loads/Surface traction/Function expression",
       "0; 0; " + pneuma_test::number(q) + "*t"},
      {"Output/Monitor points", "0, 0, 0"}};
  }

  /// The square plate (side 1 m, t = 1 cm, E = 1 GPa, nu = 0.3, Q2; all
  /// four edges held in xyz, clamped or simply supported) under q [Pa].
  pneuma_test::Settings
  square_plate(const unsigned int refinements,
               const bool         clamped,
               const double       q)
  {
    pneuma_test::Settings s = plate(refinements, clamped, q);
    s[0]                    = {"Geometry/Type", "square"};
    s[1]                    = {"Geometry/square/Side length", "1"};
    for (auto &[entry, value] : s)
      if (entry == "Bending/Clamped boundaries")
        value = clamped ? "0, 1, 2, 3" : "";
      else if (entry == "Boundary conditions/Fixed boundaries")
        value = "0: xyz; 1: xyz; 2: xyz; 3: xyz";
    return s;
  }

  /// The cantilever strip (1 m x 0.1 m, t = 1 cm, E = 1 GPa, nu = 0),
  /// clamped at x = -1/2, a dead load @p P across its end x = 1/2.
  pneuma_test::Settings
  cantilever(const unsigned int degree,
             const unsigned int refinements,
             const double       P)
  {
    auto settings = pneuma_test::shell_strip(degree, refinements);
    settings.insert(settings.end(),
                    {{"Loads/Line load boundaries", "1"},
                     {"Loads/Line load/Function expression",
                      "0; 0; " + pneuma_test::number(P / 0.1) + "*t"}});
    return settings;
  }

  /// The elastica of a cantilever under a dead tip load P L^2/EI = a2
  /// across it: the tip's (x, z)/L and int theta'^2 ds L (the bending
  /// energy over EI/2).
  std::array<double, 3>
  elastica(const double a2)
  {
    using State = std::array<double, 5>;
    // y = (theta, theta', x, z, int theta'^2) along s in [0, 1].
    const auto shoot = [a2](const double k0) {
      State              y{{0., k0, 0., 0., 0.}};
      const unsigned int n = 4000;
      const double       h = 1. / n;
      const auto         f = [a2](const State &v) {
        return State{{v[1],
                      -a2 * std::cos(v[0]),
                      std::cos(v[0]),
                      std::sin(v[0]),
                      v[1] * v[1]}};
      };
      for (unsigned int i = 0; i < n; ++i)
        {
          State k[4], t;
          k[0] = f(y);
          for (unsigned int j = 0; j < 5; ++j)
            t[j] = y[j] + h / 2 * k[0][j];
          k[1] = f(t);
          for (unsigned int j = 0; j < 5; ++j)
            t[j] = y[j] + h / 2 * k[1][j];
          k[2] = f(t);
          for (unsigned int j = 0; j < 5; ++j)
            t[j] = y[j] + h * k[2][j];
          k[3] = f(t);
          for (unsigned int j = 0; j < 5; ++j)
            y[j] += h / 6 * (k[0][j] + 2 * k[1][j] + 2 * k[2][j] + k[3][j]);
        }
      return y;
    };
    // theta'(1) = 0 by bisection on theta'(0) in (0, a2].
    double lo = 0., hi = a2;
    for (unsigned int it = 0; it < 100; ++it)
      {
        const double mid               = 0.5 * (lo + hi);
        (shoot(mid)[1] > 0. ? hi : lo) = mid;
      }
    const auto y = shoot(0.5 * (lo + hi));
    return {{y[2], y[3], y[4]}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // Tangent against finite differences.
  for (const unsigned int degree : {2u, 1u})
    {
      auto settings = pneuma_test::quiet();
      for (const auto &s : plate(1, true, 1.))
        settings.push_back(s);
      settings.push_back(
        {"Discretisation/Polynomial degree", std::to_string(degree)});
      auto         sim   = pneuma_test::make(settings);
      const double error = sim->check_tangent(1., 0.1, 1e-7).first;
      if (pneuma_test::root())
        std::printf("Q%u tangent with bending vs finite differences: %s\n",
                    degree,
                    error < 1e-6 ? "relative error < 1e-6" : "FAIL");
      if (error >= 1e-6 && pneuma_test::root())
        std::printf("  relative error %.3e\n", error);
      ok = error < 1e-6 && ok;
    }

  // Circular plates, small deflection.
  const double q = 0.01, D = 1e9 * 1e-6 / (12. * (1. - 0.09));
  for (const bool clamped : {true, false})
    {
      const double reference =
        clamped ? q / (64. * D) : q * 5.3 / (64. * D * 1.3);
      double error[3];
      for (unsigned int r = 1; r <= 3; ++r)
        {
          const auto s = pneuma_test::run(plate(r, clamped, q));
          if (pneuma_test::failed(s, "plate"))
            return 1;
          const double w = s.get("m0_u_z");
          error[r - 1]   = std::abs(w - reference) / reference;
          ok             = pneuma_test::check(std::string(clamped ? "clamped"
                                                      : "simply supported")
                                    + " plate, refinement " + std::to_string(r)
                                    + ": centre [m]",
                                  w,
                                  reference,
                                  r == 3 ? 3e-3 : 4e-2)
               && ok;
        }
      const double order = std::log2(error[1] / error[2]);
      if (pneuma_test::root())
        std::printf("  observed order of the error: %.2f (%s)\n",
                    order,
                    order > 1.8 ? "second order" : "FAIL");
      ok = order > 1.8 && ok;
    }

  // Square plates: Timoshenko & Woinowsky-Krieger's centre deflection
  // w = alpha q a^4/D, alpha = 0.00126532 clamped, 0.00406235 simply
  // supported (nu = 0.3).
  for (const bool clamped : {true, false})
    {
      const double reference = (clamped ? 0.00126532 : 0.00406235) * q / D;
      double       error[3];
      // (the simply supported plate one refinement lower: it converges
      // from the start)
      const unsigned int first = clamped ? 3 : 2;
      for (unsigned int r = first; r <= first + 2; ++r)
        {
          const auto s = pneuma_test::run(square_plate(r, clamped, q));
          if (pneuma_test::failed(s, "square plate"))
            return 1;
          const double w   = s.get("m0_u_z");
          error[r - first] = std::abs(w - reference) / reference;
          ok               = pneuma_test::check(std::string(clamped ? "clamped"
                                                      : "simply supported")
                                    + " square plate, " + std::to_string(1 << r)
                                    + " x " + std::to_string(1 << r)
                                    + " cells: centre [m]",
                                  w,
                                  reference,
                                  r == first + 2 ? 4e-3 : 4e-2)
               && ok;
        }
      const double order = std::log2(error[1] / error[2]);
      if (pneuma_test::root())
        std::printf("  observed order of the error: %.2f (%s)\n",
                    order,
                    order > 1.7 ? "second order" : "FAIL");
      ok = order > 1.7 && ok;
    }

  // Cantilever elastica, P L^2/EI = 2.
  const double EI = 1e9 * 0.1 * 1e-6 / 12., P = 2. * EI;
  const auto   tip = elastica(2.);
  {
    const auto s = pneuma_test::run(cantilever(2, 2, P));
    if (pneuma_test::failed(s, "cantilever"))
      return 1;
    ok = pneuma_test::check("cantilever tip, along the strip [m]",
                            s.get("m0_u_x"),
                            tip[0] - 1.,
                            1e-3)
         && ok;
    ok = pneuma_test::check("cantilever tip, across [m]",
                            s.get("m0_u_z"),
                            tip[1],
                            1e-3)
         && ok;
    ok = pneuma_test::check("cantilever bending energy [J]",
                            s.get("bending_energy"),
                            0.5 * EI * tip[2],
                            2e-3)
         && ok;
    const double order = pneuma_test::last_step_order(s);
    if (pneuma_test::root())
      std::printf("Newton's rate in the last step: %s\n",
                  order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
    ok = order > 1.4 && ok;
  }
  // The same on Q1 cells: the kinks carry the bending (gamma = 1), first
  // order.
  {
    double error[2];
    for (unsigned int r = 2; r <= 3; ++r)
      {
        const auto s = pneuma_test::run(cantilever(1, r, P));
        if (pneuma_test::failed(s, "Q1 cantilever"))
          return 1;
        error[r - 2] = std::abs(s.get("m0_u_z") - tip[1]) / tip[1];
        ok = pneuma_test::check("Q1 cantilever, refinement " + std::to_string(r)
                                  + ": tip across [m]",
                                s.get("m0_u_z"),
                                tip[1],
                                r == 3 ? 2e-2 : 4e-2)
             && ok;
      }
    const double order = std::log2(error[0] / error[1]);
    if (pneuma_test::root())
      std::printf("  observed order of the error: %.1f (%s)\n",
                  order,
                  order > 0.8 ? "first order" : "FAIL");
    ok = order > 0.8 && ok;
  }
  // Orthotropic bending: the fill (E2 = E1/2) along the strip, so
  // P L^2/(E2 I) = 4.
  {
    auto settings = cantilever(2, 1, P);
    settings.insert(settings.end(),
                    {{"Materials/Region 0/Law", "orthotropic"},
                     {"Materials/Region 0/Warp direction", "0, 1, 0"},
                     {"Materials/Region 0/orthotropic/Warp modulus", "1e9"},
                     {"Materials/Region 0/orthotropic/Fill modulus", "5e8"},
                     {"Materials/Region 0/orthotropic/Poisson's ratio", "0"},
                     {"Materials/Region 0/orthotropic/Shear modulus", "1e8"}});
    const auto s = pneuma_test::run(settings);
    if (pneuma_test::failed(s, "orthotropic cantilever"))
      return 1;
    ok = pneuma_test::check(
           "orthotropic cantilever (fill along it), 20 x 2 cells: tip "
           "across [m]",
           s.get("m0_u_z"),
           elastica(4.)[1],
           5e-3)
         && ok;
  }
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
