// Orthotropic fabric and prestress (doc/theory.md §2, "Orthotropic St.
// Venant-Kirchhoff" and "Prestress"):
// (a) a closed cylinder (R = 0.23 m, L = 2 m, H = 1 mm, rigid end plates)
//     of warp E1 = 1 GPa along its axis and fill E2 = 0.5 GPa around it,
//     nu12 = 0.3, G12 = E1/100, under p = 1 kPa: the axial and hoop
//     strains at mid-length against eps_x = (N_x - nu12 N_t)/(E1 H),
//     eps_t = (N_t - nu21 N_x)/(E2 H), N_x = pR/2, N_t = pR;
// (b) the same with the warp around it (Warp direction 0,1,0 would be
//     normal to the wall at y = +-R): an input error naming the entry;
// (c) a clamped disc (a = 0.1425 m) prestressed to n0 = 1 kN/m under
//     p = 10 Pa: the centre deflection against p a^2/(4 n0);
// (d) an unequal prestress without a warp direction: an input error.

#include "test_tools.h"

#include <pneuma/core/input_error.h>

#include <cmath>

namespace
{
  /// Set up and run; return the run, or print the input error.
  bool
  input_error(const pneuma_test::Settings &settings, const std::string &entry)
  {
    try
      {
        pneuma_test::make(settings);
      }
    catch (const pneuma::InputError &e)
      {
        const std::string what = e.what();
        const bool        ok   = what.find(entry) != std::string::npos;
        if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::printf("input error names '%s': %s\n",
                      entry.c_str(),
                      ok ? "yes" : ("no (FAIL): " + what).c_str());
        return ok;
      }
    std::printf("no input error for '%s' (FAIL)\n", entry.c_str());
    return false;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // (a) orthotropic cylinder, warp along the axis.
  const double R = 0.23, H = 1e-3, E1 = 1e9, E2 = 5e8, nu12 = 0.3, p = 1e3;
  auto         cylinder             = pneuma_test::quiet();
  const pneuma_test::Settings scene = {
    {"Geometry/Type", "closed cylinder"},
    {"Geometry/closed cylinder/Radius", "0.23"},
    {"Geometry/closed cylinder/Length", "2"},
    {"Geometry/Global refinements", "4"},
    {"Materials/Region 0/Law", "orthotropic"},
    {"Materials/Region 0/Thickness", "1e-3"},
    {"Materials/Region 0/Warp direction", "1, 0, 0"},
    {"Materials/Region 0/orthotropic/Warp modulus", pneuma_test::number(E1)},
    {"Materials/Region 0/orthotropic/Fill modulus", pneuma_test::number(E2)},
    {"Materials/Region 0/orthotropic/Poisson's ratio", "0.3"},
    {"Materials/Region 0/orthotropic/Shear modulus", "1e7"},
    {"Materials/Region 1/Thickness", "1e-2"},
    {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
    {"Materials/Region 2/Thickness", "1e-2"},
    {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
    {"Boundary conditions/Rigid regions", "1, 2"},
    {"Boundary conditions/Fixed points",
     "0,0,0: xyz; 2,0,0: yz; 0.05,0,0.23: y"},
    {"Loads/Pressure/Function expression", pneuma_test::number(p) + "*t"},
    {"Output/Monitor points", "1,0.23,0; 0.9,0,0.23; 1.1,0,0.23"}};
  cylinder.insert(cylinder.end(), scene.begin(), scene.end());
  {
    const auto s = pneuma_test::run(cylinder);
    ok           = ok && s.exit_code == 0;
    const auto u = [&](const unsigned int m) {
      return s.summary.get_vector("m" + std::to_string(m) + "_u");
    };
    const auto x = [&](const unsigned int m) {
      return s.summary.get_vector("m" + std::to_string(m) + "_position");
    };
    const double nu21 = nu12 * E2 / E1, Nx = p * R / 2., Nt = p * R;
    ok = pneuma_test::check("axial strain",
                            (u(2)[0] - u(1)[0]) / (x(2)[0] - x(1)[0]),
                            (Nx - nu12 * Nt) / (E1 * H),
                            5e-3)
         && ok;
    ok = pneuma_test::check("hoop strain",
                            u(0)[1] / R,
                            (Nt - nu21 * Nx) / (E2 * H),
                            5e-3)
         && ok;
  }

  // (b) a warp direction along the wall's normal somewhere.
  {
    auto bad = cylinder;
    bad.push_back({"Materials/Region 0/Warp direction", "0, 1, 0"});
    ok = input_error(bad, "Materials/Region 0/Warp direction") && ok;
  }

  // (c) prestressed clamped disc under a small pressure.
  const double                a = 0.1425, n0 = 1e3, q = 10.;
  auto                        disc       = pneuma_test::quiet();
  const pneuma_test::Settings disc_scene = {
    {"Geometry/Type", "disc"},
    {"Geometry/disc/Radius", pneuma_test::number(a)},
    {"Geometry/Global refinements", "3"},
    {"Discretisation/Polynomial degree", "2"},
    {"Materials/Region 0/Thickness", "1e-3"},
    {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e7"},
    {"Materials/Region 0/Prestress", pneuma_test::number(n0)},
    {"Boundary conditions/Fixed boundaries", "0: xyz"},
    {"Loads/Pressure/Function expression", pneuma_test::number(q) + "*t"},
    {"Output/Monitor points", "0,0,0"}};
  disc.insert(disc.end(), disc_scene.begin(), disc_scene.end());
  {
    const auto s = pneuma_test::run(disc);
    ok           = ok && s.exit_code == 0;
    ok           = pneuma_test::check("prestressed disc, centre deflection",
                            s.summary.get_vector("m0_u")[2],
                            q * a * a / (4. * n0),
                            5e-3)
         && ok;
  }

  // (d) an unequal prestress needs a warp direction.
  {
    auto bad = disc;
    bad.push_back({"Materials/Region 0/Prestress", "1000, 500"});
    ok = input_error(bad, "Materials/Region 0/Prestress") && ok;
  }
  return ok ? 0 : 1;
}
