// The solid-beam element of the source paper (section 3.1) on a cantilever
// of length L = 1 m, E = 2e11 Pa, clamped at x = 0 (doc/verification.md
// "Cables"):
//  - axial stretch, St. Venant-Kirchhoff, nu = 0: the end force F gives the
//    exact stretch of F = EA lambda (lambda^2 - 1)/2;
//  - small-deflection tip force, circular (a = 0.02 m) and elliptic
//    (a = 0.02, b = 0.01) sections, about both axes: the Timoshenko value
//    P L^3/(3 E I) + P L/(G A) (the section field is plane: shear factor
//    1), and the observed order over 4..32 elements;
//  - a tip moment M = pi E I / L rolls the beam into a half circle: the end
//    section turns by M L/(E I) = pi and the tip comes to (0, 2L/pi);
//  - torsion of a circular bar, nu = 0.3: twist T L/(G J), J = pi a^4/2.
// Bending uses nu = 0: a section field linear in the section coordinates
// cannot contract anticlastically (Poisson thickness locking, see the
// solid_beam_section test).

#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  const double E = 2e11, L = 1.;

  pneuma_test::Settings
  cantilever(const unsigned int n,
             const double       a,
             const double       b,
             const double       nu)
  {
    return {
      {"Geometry/Type", "none"},
      {"Cables/Number of cables", "1"},
      {"Cables/Cable 1/Element", "solid beam"},
      {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
      {"Cables/Cable 1/Number of elements", std::to_string(n)},
      {"Cables/Cable 1/Section semi-axes",
       std::to_string(a) + ", " + std::to_string(b)},
      {"Cables/Cable 1/solid beam/Section axis", "0, 0, 1"},
      {"Cables/Cable 1/Young's modulus", "2e11"},
      {"Cables/Cable 1/solid beam/Poisson's ratio", std::to_string(nu)},
      {"Cables/Cable 1/Start support", "fixed"},
    };
  }

  pneuma_test::Settings
  with(pneuma_test::Settings s, const pneuma_test::Settings &more)
  {
    s.insert(s.end(), more.begin(), more.end());
    return s;
  }

  std::string
  number(const double x)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.15g", x);
    return buffer;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // Axial stretch: F = 0.01 EA.
  {
    const double a = 0.02, A = M_PI * a * a, F = 0.01 * E * A;
    double       lambda = 1.01;
    for (unsigned int k = 0; k < 50; ++k) // Newton on lambda^3 - lambda - 2F/EA
      lambda -= (lambda * lambda * lambda - lambda - 2. * F / (E * A))
                / (3. * lambda * lambda - 1.);
    const auto s =
      pneuma_test::run(with(cantilever(4, a, a, 0.),
                            {{"Cables/Cable 1/End forces", "true"},
                             {"Cables/Cable 1/End force/Function expression",
                              number(F) + " * t; 0; 0"}}));
    ok &= pneuma_test::check("axial stretch: end displacement",
                             s.summary.has("cable1_end_u")
                               ? s.summary.get_vector("cable1_end_u")[0]
                               : NAN,
                             (lambda - 1.) * L,
                             1e-8);
  }

  // Small-deflection tip force P along y (bending with I_z = pi a b^3/4,
  // b the semi-axis along y) and along z (I_y = pi b a^3/4).
  const auto tip_deflection =
    [](const unsigned int n, const double a, const double b, const int dir) {
      const double P = 1.;
      const auto   s =
        pneuma_test::run(with(cantilever(n, a, b, 0.),
                              {{"Cables/Cable 1/End forces", "true"},
                               {"Cables/Cable 1/End force/Function expression",
                                dir == 1 ? "0; t; 0" : "0; 0; t"}}));
      const double I =
        dir == 1 ? M_PI * a * b * b * b / 4. : M_PI * b * a * a * a / 4.;
      const double G = E / 2., A = M_PI * a * b;
      const double reference = P * L * L * L / (3. * E * I) + P * L / (G * A);
      const double value     = s.summary.has("cable1_end_u")
                                 ? s.summary.get_vector("cable1_end_u")[dir]
                                 : NAN;
      return std::make_pair(value, reference);
    };
  std::vector<double> errors;
  for (const unsigned int n : {4u, 8u, 16u, 32u})
    {
      const auto [v, r] = tip_deflection(n, 0.02, 0.02, 1);
      errors.push_back(std::abs(v - r) / r);
      std::printf("cantilever, circular, %2u elements: tip deflection %.6e "
                  "(reference %.6e, error %.2e)\n",
                  n,
                  v,
                  r,
                  errors.back());
    }
  for (unsigned int k = 1; k < errors.size(); ++k)
    {
      const double order = std::log2(errors[k - 1] / errors[k]);
      std::printf("observed order, %u -> %u elements: %.2f\n",
                  4u << (k - 1),
                  4u << k,
                  order);
      ok &= order > 1.8 && order < 2.2;
    }
  {
    const auto [v, r] = tip_deflection(32, 0.02, 0.02, 1);
    ok &= pneuma_test::check("cantilever, circular, 32 elements", v, r, 5e-3);
  }
  for (const int dir : {1, 2})
    {
      const auto [v, r] = tip_deflection(32, 0.02, 0.01, dir);
      ok &=
        pneuma_test::check(std::string("cantilever, elliptic, force along ")
                             + (dir == 1 ? "the short axis" : "the long axis"),
                           v,
                           r,
                           5e-3);
    }

  // Roll-up: tip moment M = pi E I / L about z.
  {
    const double a = 0.02, I = M_PI * a * a * a * a / 4.;
    const double M = M_PI * E * I / L;
    const auto   s =
      pneuma_test::run(with(cantilever(32, a, a, 0.),
                            {{"Cables/Cable 1/End moment/Function expression",
                              "0; 0; " + number(M) + " * t"},
                             {"Load stepping/Initial increment", "0.1"}}));
    const bool done = s.summary.has("cable1_end_u") && s.exit_code == 0;
    ok &= pneuma_test::check("tip moment: end rotation M L/(E I)",
                             done ? s.get("cable1_end_rotation") : NAN,
                             M_PI,
                             5e-3);
    ok &=
      pneuma_test::check("tip moment: tip height 2L/pi",
                         done ? s.summary.get_vector("cable1_end_u")[1] : NAN,
                         2. * L / M_PI,
                         5e-3);
    const double x_tip =
      done ? L + s.summary.get_vector("cable1_end_u")[0] : NAN;
    const bool pass = std::abs(x_tip) < 5e-3 * L;
    std::printf("tip moment: tip x %.2e L (reference 0) %s\n",
                x_tip / L,
                pass ? "PASS" : "FAIL");
    ok &= pass;
  }

  // Torsion of a circular bar, nu = 0.3.
  {
    const double a = 0.02, nu = 0.3, G = E / (2. * (1. + nu));
    const double J = M_PI * a * a * a * a / 2., T = 1e-4 * G * J / L;
    const auto   s =
      pneuma_test::run(with(cantilever(8, a, a, nu),
                            {{"Cables/Cable 1/End moment/Function expression",
                              number(T) + " * t; 0; 0"}}));
    ok &= pneuma_test::check("torsion: twist T L/(G J)",
                             s.summary.has("cable1_end_rotation")
                               ? s.get("cable1_end_rotation")
                               : NAN,
                             T * L / (G * J),
                             5e-3);
  }

  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
