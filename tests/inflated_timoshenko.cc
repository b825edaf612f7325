// The inflated Timoshenko beam (doc/verification.md "Inflated beam in
// shear"): a cantilever tube of coated fabric whose shear modulus G12 is
// small, R = 0.1 m, L = 1 m, H = 0.5 mm, warp along the axis, E1 = E2 =
// 1 GPa, nu12 = 0.3, at p = 10 kPa, the root plate following the free
// radial expansion of the tube, a rigid tip plate under a small dead
// vertical force F = 2 N (a tenth of the wrinkling load). Fichter's and
// Le van & Wielgosz's inflated beam: the tip deflection
//   v = F L^3 / (3 (E I + P I / S)) + F L / (P + k G S),
// P = p pi R^2 (the pressure's axial resultant), S = 2 pi R H,
// I = pi R^3 H, k = 1/2 (thin circular tube). Two runs, G12 = E/100 and
// E/1000, the shear term 72 % and 90 % of v:
// - v of each against the formula (within 2 %: plane sections are assumed
//   by the beam, the membrane tube ovalizes a little near the plates);
// - their difference, in which the bending term cancels, against
//   F L (1/(P + k G_b S) - 1/(P + k G_a S)): the P + k G S term alone.

#include "test_tools.h"

#include <cmath>

namespace
{
  const double R = 0.1, L = 1., H = 5e-4, E = 1e9, nu = 0.3, p = 1e4, F = 2.;

  /// Tip deflection under F after inflation, for shear modulus @p G.
  double
  tip_deflection(const double G)
  {
    // The hull's free radial strain under p (small strain).
    const double                c        = p * R / (E * H) * (1. - 0.5 * nu);
    auto                        settings = pneuma_test::quiet();
    const pneuma_test::Settings scene    = {
         {"Geometry/Type", "closed cylinder"},
         {"Geometry/Global refinements", "3"},
         {"Geometry/closed cylinder/Radius", pneuma_test::number(R)},
         {"Geometry/closed cylinder/Length", pneuma_test::number(L)},
         {"Materials/Region 0/Thickness", pneuma_test::number(H)},
         {"Materials/Region 0/Law", "orthotropic"},
         {"Materials/Region 0/Warp direction", "1, 0, 0"},
         {"Materials/Region 0/orthotropic/Warp modulus", pneuma_test::number(E)},
         {"Materials/Region 0/orthotropic/Fill modulus", pneuma_test::number(E)},
         {"Materials/Region 0/orthotropic/Poisson's ratio",
          pneuma_test::number(nu)},
         {"Materials/Region 0/orthotropic/Shear modulus", pneuma_test::number(G)},
         {"Materials/Region 1/Thickness", "1e-2"},
         {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "2e11"},
         {"Materials/Region 2/Thickness", "1e-2"},
         {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "2e11"},
         {"Loads/Pressure/Function constants", "p0=" + pneuma_test::number(p)},
         {"Loads/Pressure/Function expression", "p0*min(t, 1)"},
         {"Loads/Surface load", "true"},
         {"Loads/Surface traction/Function constants",
          "F=" + pneuma_test::number(F) + ", R=" + pneuma_test::number(R)
            + ", L=" + pneuma_test::number(L)},
         {"Loads/Surface traction/Function expression",
          "0; 0; if(t > 1 && x > L*(1-1e-9), -(t-1)*F/(pi*R^2), 0)"},
         {"Boundary conditions/Prescribed displacement regions", "1"},
         {"Boundary conditions/Prescribed displacement/Function constants",
          "c=" + pneuma_test::number(c)},
         {"Boundary conditions/Prescribed displacement/Function expression",
          "0; c*y*min(t,1); c*z*min(t,1)"},
         {"Boundary conditions/Rigid regions", "2"},
         {"Load stepping/Stage end times", "1, 2"},
         {"Load stepping/Initial increment", "0.25"},
         {"Load stepping/Maximum increment", "0.5"},
         {"Output/Monitor points", "1,0,0"}};
    settings.insert(settings.end(), scene.begin(), scene.end());
    const auto s = pneuma_test::run(settings);
    if (s.exit_code != 0)
      return std::numeric_limits<double>::quiet_NaN();
    double w1 = 0.;
    for (const auto &row : s.history)
      if (std::abs(row.get("time") - 1.) < 1e-12)
        w1 = row.get("m0_u_z");
    return -(s.get("m0_u_z") - w1);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double P = p * M_PI * R * R, S = 2. * M_PI * R * H,
               I = M_PI * R * R * R * H, k = 0.5;
  const auto beam = [&](const double G) {
    return F * L * L * L / (3. * (E * I + P * I / S)) + F * L / (P + k * G * S);
  };
  const double Ga = E / 100., Gb = E / 1000.;
  const double va = tip_deflection(Ga), vb = tip_deflection(Gb);
  bool         ok = true;
  ok = pneuma_test::check("tip deflection, G12 = E/100 [m]", va, beam(Ga), 0.02)
       && ok;
  ok =
    pneuma_test::check("tip deflection, G12 = E/1000 [m]", vb, beam(Gb), 0.02)
    && ok;
  ok =
    pneuma_test::check("shear term F L (1/(P + k Gb S) - 1/(P + k Ga S)) [m]",
                       vb - va,
                       beam(Gb) - beam(Ga),
                       0.02)
    && ok;
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
