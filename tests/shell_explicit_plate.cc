// Shells with bending in explicit dynamics (membrane/bending,
// strategies/explicit_dynamics; doc/theory.md §18 and §21): a simply
// supported square plate (side a = 1 m, t = 5 cm, E = 1 GPa, nu = 0.3,
// rho = 1000 kg/m^3, edges held in xyz, Q2 on 4 x 4 cells) is bent by a
// pressure of 1 kPa (static stage to t = 1), released at t = 1 and left
// to vibrate for 0.21 s (explicit stage, central differences with the
// lumped mass; about ten periods). The centre's period (a straight line
// through the zero crossings of its motion) against
// - the modal analysis of the unloaded plate on the same mesh (the
//   consistent mass; 0.5 %): the explicit strategy integrates the same
//   shell;
// - Kirchhoff's f_11 = pi/2 (1 + 1)/a^2 sqrt(D/(rho t)) with D = E t^3/(12
//   (1 - nu^2)) (2 %: the mesh's own error, +1.3 % on 4 x 4 cells, +0.35 %
//   on 8 x 8, doc/verification.md);
// and the energy balance T + W = 0 (W the work of the residual forces)
// within 5e-3 of the largest energy at every row. And dynamic relaxation
// (Load stepping/Strategy = relaxation, kinetic damping, without Newton's
// finish, to |r| = 1e-8 |r_ref|) of the plate under the pressure: the
// centre's deflection against Newton's static answer (1e-6).
// The same on 2 ranks.

#include "test_tools.h"
#include "vibration.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
  const double E = 1e9, nu = 0.3, t = 0.05, rho = 1000.;
  const double D = E * t * t * t / (12. * (1. - nu * nu));

  pneuma_test::Settings
  plate()
  {
    return {{"Geometry/Type", "square"},
            {"Geometry/square/Side length", "1"},
            {"Geometry/Global refinements", "2"},
            {"Discretisation/Polynomial degree", "2"},
            {"Materials/Region 0/Thickness", pneuma_test::number(t)},
            {"Materials/Region 0/Density", pneuma_test::number(rho)},
            {"Materials/Region 0/Bending", "shell"},
            {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
             pneuma_test::number(E)},
            {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio",
             pneuma_test::number(nu)},
            {"Boundary conditions/Fixed boundaries",
             "0: xyz; 1: xyz; 2: xyz; 3: xyz"},
            {"Output/Monitor points", "0, 0, 0"}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root = pneuma_test::root();
  bool                                     ok   = true;

  // The explicit run.
  auto settings = plate();
  settings.insert(settings.end(),
                  {{"Loads/Pressure/Function expression",
                    "if(t <= 1, 1000*t, 0)"},
                   {"Load stepping/Stage end times", "1, 1.21"},
                   {"Load stepping/Strategy", "static, explicit"},
                   {"Explicit dynamics/Output interval", "0.0005"}});
  const auto s = pneuma_test::run(settings);
  if (pneuma_test::failed(s, "explicit run"))
    return 1;
  double worst = 0., largest = 0.;
  for (const auto &row : s.history)
    if (row.get("time") > 1.)
      {
        worst   = std::max(worst,
                         std::abs(row.get("kinetic_energy")
                                  + row.get("residual_work")));
        largest = std::max(largest, row.get("kinetic_energy"));
      }
  const auto   z = pneuma_test::crossings(s, "m0_u_z", 0., 1.);
  const double f = z.size() >= 2 ? 1. / pneuma_test::period(z) : 0.;
  if (root)
    std::printf("%s zero crossings in the explicit stage (at least 18) %s\n",
                z.size() >= 18 ? "enough" : "too few",
                z.size() >= 18 ? "PASS" : "FAIL");
  ok = z.size() >= 18 && ok;

  // The modal analysis of the unloaded plate.
  settings = plate();
  settings.insert(settings.end(),
                  {{"Eigen analysis/Type", "modal"},
                   {"Eigen analysis/Number of modes", "1"}});
  const auto m = pneuma_test::run(settings);
  if (pneuma_test::failed(m, "modal analysis"))
    return 1;
  ok = pneuma_test::check("explicit frequency against the modal analysis [Hz]",
                          f,
                          m.get("mode1_frequency"),
                          5e-3)
       && ok;
  ok = pneuma_test::check("explicit frequency against Kirchhoff's f_11 [Hz]",
                          f,
                          M_PI * std::sqrt(D / (rho * t)),
                          2e-2)
       && ok;
  if (root)
    std::printf("energy balance |T + W| within 5e-3 of the largest kinetic "
                "energy at every row: %s\n",
                worst < 5e-3 * largest ? "PASS" : "FAIL");
  ok = worst < 5e-3 * largest && ok;

  // Dynamic relaxation against Newton.
  double w[2];
  for (const std::string strategy : {"static", "relaxation"})
    {
      settings = plate();
      settings.insert(settings.end(),
                      {{"Loads/Pressure/Function expression", "1000*t"},
                       {"Load stepping/Strategy", strategy},
                       {"Dynamic relaxation/Finish with Newton", "false"},
                       {"Dynamic relaxation/Residual tolerance", "1e-8"}});
      const auto r = pneuma_test::run(settings);
      if (pneuma_test::failed(r, strategy))
        return 1;
      w[strategy == "relaxation"] = r.get("m0_u_z");
    }
  const double gap = std::abs(w[1] - w[0]) / std::abs(w[0]);
  if (root)
    std::printf("relaxed centre deflection within 1e-6 of Newton's: %s\n",
                gap < 1e-6 ? "PASS" : "FAIL");
  ok = gap < 1e-6 && ok;
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
