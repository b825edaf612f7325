// The Gent law (source/membrane/laws/gent.cc) on the inflated sphere,
// through its limit point by volume control (V/V0 = l^3, the pressure is
// the chamber's Lagrange multiplier). Equibiaxial stretch l,
// I1 = 2 l^2 + l^-4, W = -(mu Jm/2) ln(1 - (I1-3)/Jm):
//   p R/(mu H) = 2 (1/l - 1/l^7) Jm / (Jm - (2 l^2 + l^-4 - 3))
// (doc/theory.md "Membrane laws"). For Jm = 10 and 30 at three stretches
// each (for Jm = 30 before, through and past its limit point), the stretch
// and pR/(muH) must be within 0.5 %. Also: the law's stress and tangent against
// finite differences of its energy, and the assembled tangent of a Gent sphere
// against finite differences of the residual.

#include <deal.II/base/symmetric_tensor.h>

#include <pneuma/membrane/constitutive_law.h>

#include "test_tools.h"

#include <cmath>

namespace
{
  pneuma_test::Settings
  sphere(const double Jm)
  {
    return {{"Geometry/Type", "sphere"},
            {"Geometry/sphere/Radius", "1"},
            {"Geometry/Global refinements", "3"},
            {"Discretisation/Polynomial degree", "2"},
            {"Materials/Region 0/Law", "Gent"},
            {"Materials/Region 0/Thickness", "1e-3"},
            {"Materials/Region 0/Gent/Shear modulus", "1e6"},
            {"Materials/Region 0/Gent/Limiting extensibility",
             std::to_string(Jm)},
            {"Boundary conditions/Fixed points",
             "0,0,1: xy; 0,0,-1: xy; 1,0,0: yz; -1,0,0: yz"}};
  }

  double
  reference(const double l, const double Jm)
  {
    const double I1 = 2. * l * l + std::pow(l, -4.);
    return 2. * (1. / l - std::pow(l, -7.)) * Jm / (Jm - (I1 - 3.));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // 1. The law: S = dW/dE and D = dS/dE against central differences.
  {
    dealii::ParameterHandler prm;
    auto laws = pneuma::membrane::LawRegistry::instance().declare_all(prm);
    prm.enter_subsection("Gent");
    prm.set("Limiting extensibility", "5");
    prm.leave_subsection();
    const auto law = pneuma::membrane::LawRegistry::instance().take(
      laws, prm, "Gent", "Law", "Gent test");
    dealii::SymmetricTensor<2, 2> C;
    C[0][0] = 1.9, C[1][1] = 1.4, C[0][1] = 0.3;
    dealii::SymmetricTensor<2, 2> S, S_p, S_m;
    dealii::SymmetricTensor<4, 2> D, D_p, D_m;
    law->evaluate(C, S, D);
    const double h     = 1e-6;
    double       err_S = 0., err_D = 0., norm_S = S.norm(), norm_D = D.norm();
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = i; j < 2; ++j)
        {
          // dE_ij = h (dC_ij = 2h); a shear entry perturbs E_ij and E_ji.
          dealii::SymmetricTensor<2, 2> dC;
          dC[i][j]         = 2. * h;
          const double W_p = law->strain_energy(C + dC);
          const double W_m = law->strain_energy(C - dC);
          const double dW  = (W_p - W_m) / (2. * h) / (i == j ? 1. : 2.);
          err_S            = std::max(err_S, std::abs(dW - S[i][j]));
          law->evaluate(C + dC, S_p, D_p);
          law->evaluate(C - dC, S_m, D_m);
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = k; l < 2; ++l)
              {
                const double dS =
                  (S_p[k][l] - S_m[k][l]) / (2. * h) / (i == j ? 1. : 2.);
                err_D = std::max(err_D, std::abs(dS - D[k][l][i][j]));
              }
        }
    std::printf("Gent law: |S - dW/dE|/|S| %s, |D - dS/dE|/|D| %s\n",
                err_S / norm_S < 1e-7 ? "< 1e-7" : "FAIL",
                err_D / norm_D < 1e-7 ? "< 1e-7" : "FAIL");
    ok = ok && err_S / norm_S < 1e-7 && err_D / norm_D < 1e-7;
  }

  // 2. The assembled tangent of a pressurised Gent sphere.
  {
    auto settings = sphere(10.);
    settings[2]   = {"Geometry/Global refinements", "1"};
    settings.push_back({"Loads/Pressure/Function expression", "800*t"});
    settings.push_back({"Output/Quiet", "true"});
    const auto   simulator = pneuma_test::make(settings);
    const double error     = simulator->check_tangent(1., 0.05, 1e-6).first;
    std::printf("Gent sphere: tangent vs finite differences %s\n",
                error < 1e-6 ? "< 1e-6" : "FAIL");
    ok = ok && error < 1e-6;
  }

  // 3. By volume control, l = 1 + a t: for Jm = 10 (below the critical
  //    Jm = 18.2 the curve has no limit point) at l = 1.2, 1.6, 2.2; for
  //    Jm = 30 before its limit point (l = 1.445, pR/(muH) = 1.2926), on
  //    the falling branch, and past the minimum (l = 2.318) where the
  //    chains stiffen: l = 1.2, 2.0, 3.5.
  struct Case
  {
    double              Jm, a;
    std::vector<double> stretches;
  };
  for (const Case &c :
       {Case{10., 1.2, {1.2, 1.6, 2.2}}, Case{30., 2.5, {1.2, 2.0, 3.5}}})
    {
      std::string ends;
      for (const double l : c.stretches)
        {
          char t[32];
          std::snprintf(t, sizeof(t), "%.15g", (l - 1.) / c.a);
          ends += (ends.empty() ? "" : ", ") + std::string(t);
        }
      auto settings = sphere(c.Jm);
      settings.insert(settings.end(),
                      {{"Chambers/Number of chambers", "1"},
                       {"Chambers/Chamber 1/Regions", "0"},
                       {"Chambers/Chamber 1/Gas/Control", "volume"},
                       {"Chambers/Chamber 1/Gas/Volume/Function expression",
                        "(1+" + std::to_string(c.a) + "*t)^3"},
                       {"Load stepping/Stage end times", ends},
                       {"Load stepping/Initial increment", "0.04"},
                       {"Load stepping/Maximum increment", "0.08"},
                       {"Output/Directory", "output-gent"}});
      const auto s = pneuma_test::run(settings);
      ok           = ok && s.exit_code == 0;
      std::printf("Jm = %.0f: exit code %d, %u steps\n",
                  c.Jm,
                  s.exit_code,
                  static_cast<unsigned int>(s.get("steps")));
      const double V0 = s.history.front().get("c1_volume");
      for (const auto &row : s.history)
        for (const double l_target : c.stretches)
          if (std::abs(row.get("time") - (l_target - 1.) / c.a) < 1e-9)
            {
              const double l = std::cbrt(row.get("c1_volume") / V0);
              char         name[96];
              std::snprintf(name,
                            sizeof(name),
                            "Jm = %.0f, l = %.1f: stretch",
                            c.Jm,
                            l_target);
              ok = pneuma_test::check(name, l, l_target, 5e-3) && ok;
              std::snprintf(name,
                            sizeof(name),
                            "Jm = %.0f, l = %.1f: pR/(muH)",
                            c.Jm,
                            l_target);
              ok = pneuma_test::check(name,
                                      row.get("c1_pressure") / 1e3,
                                      reference(l_target, c.Jm),
                                      5e-3)
                   && ok;
            }
    }
  return ok ? 0 : 1;
}
