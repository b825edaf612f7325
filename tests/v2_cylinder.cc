// V2 (doc/verification.md): closed thin cylinder under internal pressure, the
// paper's geometry (R = 0.23 m, L = 2 m, t = 1 mm, E = 7.6e9 Pa, nu = 0.3)
// with rigid steel end plates, measured at mid-length.
//  (a) linear theory, checked at p = 1e4 Pa where finite-strain effects are
//      below 0.02 %: dR = pR^2/(Et)(1 - nu/2), dL/L = pR/(Et)(1/2 - nu),
//      dV/V = pR/(Et)(5/2 - 2 nu);
//  (b) p = 1e5 Pa against the exact homogeneous finite-strain St.
//      Venant-Kirchhoff membrane state (doc/theory.md, "Verification"),
//      which differs from (a) by -0.14 % in dR and +1.0 % in dL/L;
//  (c) incompressible neo-Hookean hull (mu H = 1000 N/m) at the pressure
//      p R/(mu H) = N_theta/(mu H l_theta) of the homogeneous state with
//      l_theta = 1.2, where N_i = mu H (l_i^2 - l_3^2)/(l_theta l_z),
//      N_theta = 2 N_z: the computed hoop stretch must be 1.2.

#include "test_tools.h"

#include <cmath>

namespace
{
  const double R = 0.23, L = 2., t = 1e-3, E = 7.6e9, nu = 0.3;

  pneuma::RunResult
  run_cylinder(const std::string &law,
               const double       pressure,
               const unsigned int refinement)
  {
    return pneuma_test::run(
      {{"Geometry/Type", "closed cylinder"},
       {"Geometry/closed cylinder/Radius", std::to_string(R)},
       {"Geometry/closed cylinder/Length", std::to_string(L)},
       {"Geometry/Global refinements", std::to_string(refinement)},
       {"Materials/Region 0/Law", law},
       {"Materials/Region 0/Thickness", "1e-3"},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"},
       {"Materials/Region 0/neo-Hookean/Shear modulus", "1e6"},
       {"Materials/Region 1/Thickness", "1e-2"},
       {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
       {"Materials/Region 2/Thickness", "1e-2"},
       {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
       {"Boundary conditions/Rigid regions", "1, 2"},
       {"Boundary conditions/Fixed points",
        "0,0,0: xyz; 2,0,0: yz; 0.05,0,0.23: y"},
       {"Loads/Pressure/Function expression", std::to_string(pressure) + "*t"},
       {"Load stepping/Initial increment", law == "neo-Hookean" ? "0.25" : "1"},
       {"Output/Directory", "output-v2"},
       {"Output/Monitor points", "1,0.23,0; 0.9,0,0.23; 1.1,0,0.23"}});
  }

  struct MidLength
  {
    double dR, strain_z;
  };

  MidLength
  measure(const pneuma::RunResult &s)
  {
    const auto u = [&](const unsigned int m) {
      return s.summary.get_vector("m" + std::to_string(m) + "_u");
    };
    const auto x = [&](const unsigned int m) {
      return s.summary.get_vector("m" + std::to_string(m) + "_position");
    };
    return {u(0)[1], (u(2)[0] - u(1)[0]) / (x(2)[0] - x(1)[0])};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // (a) linear
  {
    const double p  = 1e4;
    const auto   s  = run_cylinder("Saint Venant-Kirchhoff", p, 4);
    const auto   m  = measure(s);
    const double dR = p * R * R / (E * t) * (1. - nu / 2.);
    const double eL = p * R / (E * t) * (0.5 - nu);
    const double eV = p * R / (E * t) * (2.5 - 2. * nu);
    ok              = ok && s.exit_code == 0;
    ok              = pneuma_test::check("linear dR", m.dR, dR, 5e-3) && ok;
    ok = pneuma_test::check("linear dL/L", m.strain_z, eL, 5e-3) && ok;
    ok = pneuma_test::check("linear dV/V", 2. * m.dR / R + m.strain_z, eV, 5e-3)
         && ok;
  }
  // (b) finite strain, homogeneous exact state (fixed point on the two
  //     stretches, converged to machine precision).
  {
    const double p  = 1e5;
    double       lt = 1., lz = 1.;
    for (unsigned int it = 0; it < 200; ++it)
      {
        const double St = p * R * lt * lz / (t * lt);
        const double Sz = p * R * lt / 2. * lt / (t * lz);
        const double Et = (St - nu * Sz) / E, Ez = (Sz - nu * St) / E;
        lt = std::sqrt(1. + 2. * Et);
        lz = std::sqrt(1. + 2. * Ez);
      }
    const auto s = run_cylinder("Saint Venant-Kirchhoff", p, 4);
    const auto m = measure(s);
    ok           = ok && s.exit_code == 0;
    ok =
      pneuma_test::check("finite-strain dR", m.dR, R * (lt - 1.), 5e-3) && ok;
    ok =
      pneuma_test::check("finite-strain dL/L", m.strain_z, lz - 1., 5e-3) && ok;
  }
  // (c) neo-Hookean homogeneous state at l_theta = 1.2.
  {
    const double lt = 1.2;
    double       lo = 0.5, hi = 3.;
    const auto   f = [&](const double lz) {
      return lt * lt - 2. * lz * lz + 1. / (lt * lt * lz * lz);
    };
    for (unsigned int it = 0; it < 200; ++it)
      {
        const double mid                 = 0.5 * (lo + hi);
        (f(lo) * f(mid) <= 0. ? hi : lo) = mid;
      }
    const double lz   = 0.5 * (lo + hi);
    const double l3sq = 1. / (lt * lt * lz * lz);
    const double muH  = 1e6 * 1e-3;
    const double p    = muH * (lt * lt - l3sq) / (lt * lz) / (R * lt);
    std::printf("neo-Hookean: l_theta = 1.2, l_z = %.5f, p = %.4e Pa\n", lz, p);
    const auto s = run_cylinder("neo-Hookean", p, 4);
    ok           = ok && s.exit_code == 0;
    ok           = pneuma_test::check("neo-Hookean hoop stretch",
                            1. + measure(s).dR / R,
                            lt,
                            5e-3)
         && ok;
  }
  return ok ? 0 : 1;
}
