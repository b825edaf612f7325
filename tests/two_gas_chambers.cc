// Two gas chambers sharing a flat divider membrane
// (meshes/divided_cylinder.msh: a rigid tube, R = 0.25 m, L = 1 m, divided
// at x = 0.5 by a membrane disc, E H = 1e5 N/m). Chamber 1 (x < 0.5) is
// held; chamber 2 is compressed by moving its hull and end plate (a
// prescribed displacement, 0.1 m at its end). Both are sealed with their
// initial air (adiabatic, kappa 1.4). Checks:
//  - each chamber keeps its own p V^1.4 = p_a V_0^1.4 in every step
//    (1e-8, the gas-law identity of doc/verification.md V4);
//  - the divider carries p1 - p2: the same divider loaded by the prescribed
//    pressure difference of the last step, without chambers, deflects the
//    same (1e-6).

#include "test_paths.h"
#include "test_tools.h"

#include <cmath>

namespace
{
  pneuma_test::Settings
  scene()
  {
    return {{"Geometry/Type", "gmsh"},
            {"Geometry/gmsh/Mesh file",
             std::string(PNEUMA_SOURCE_DIR) + "/meshes/divided_cylinder.msh"},
            {"Geometry/Global refinements", "0"},
            {"Geometry/gmsh/Orientation", "outward from interior point"},
            {"Geometry/gmsh/Interior point", "0.25, 0, 0"},
            {"Materials/Region 0/Thickness", "1e-3"},
            {"Materials/Region 1/Thickness", "1e-3"},
            {"Materials/Region 3/Thickness", "1e-3"},
            {"Materials/Region 4/Thickness", "1e-3"},
            {"Materials/Region 2/Law", "Saint Venant-Kirchhoff"},
            {"Materials/Region 2/Thickness", "1e-3"},
            {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus",
             "1e8"},
            {"Boundary conditions/Fixed regions", "0, 3"},
            {"Boundary conditions/Prescribed displacement regions", "1, 4"},
            {"Boundary conditions/Prescribed displacement/Function expression",
             "-0.1*t*(x-0.5)/0.5; 0; 0"},
            {"Load stepping/Initial increment", "0.25"},
            {"Newton/Residual tolerance", "1e-10"},
            {"Output/Monitor points", "0.5, 0, 0"}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                                     s = scene();
  s.insert(s.end(),
           {{"Chambers/Number of chambers", "2"},
            {"Chambers/Chamber 1/Regions", "0, 3, 2"},
            {"Chambers/Chamber 1/Interior point", "0.25, 0, 0"},
            {"Chambers/Chamber 1/Gas/Control", "gas amount"},
            {"Chambers/Chamber 1/Gas/Gas amount/Function expression", "1"},
            {"Chambers/Chamber 2/Regions", "1, 4, 2"},
            {"Chambers/Chamber 2/Interior point", "0.75, 0, 0"},
            {"Chambers/Chamber 2/Gas/Control", "gas amount"},
            {"Chambers/Chamber 2/Gas/Gas amount/Function expression", "1"},
            {"Output/Directory", "output-two-chambers"}});
  const auto two = pneuma_test::run(s);
  bool       ok  = two.exit_code == 0;

  const double p_a      = 101325.;
  double       worst[2] = {0., 0.};
  for (const auto &row : two.history)
    for (unsigned int c = 0; c < 2; ++c)
      {
        const std::string chamber = "c" + std::to_string(c + 1) + "_";
        const double      V0      = two.history.front().get(chamber + "volume");
        worst[c] =
          std::max(worst[c],
                   std::abs(row.get(chamber + "absolute_pressure")
                              * std::pow(row.get(chamber + "volume"), 1.4)
                              / (p_a * std::pow(V0, 1.4))
                            - 1.));
      }
  for (unsigned int c = 0; c < 2; ++c)
    ok = pneuma_test::check("chamber " + std::to_string(c + 1)
                              + ": max over steps of p V^1.4 / (p_a V0^1.4)",
                            1. + worst[c],
                            1.,
                            1e-8)
         && ok;
  const double p1 = two.get("c1_pressure"), p2 = two.get("c2_pressure");
  const double dp = p1 - p2;
  std::printf("chamber 2 compressed to V/V0 = %.4f: p2 = %.1f Pa, p1 = %.1f "
              "Pa gauge\n",
              two.get("c2_volume") / two.history.front().get("c2_volume"),
              p2,
              p1);
  ok = ok && p2 > p1 && p1 > 0.;

  // The divider alone under the prescribed difference p1 - p2.
  auto alone = scene();
  char expression[64];
  std::snprintf(expression, sizeof(expression), "%.17g*t", dp);
  alone.insert(alone.end(),
               {{"Loads/Pressure/Function expression", expression},
                {"Loads/Pressure regions", "2"},
                {"Output/Directory", "output-divider-alone"}});
  const auto one = pneuma_test::run(alone);
  ok             = ok && one.exit_code == 0;
  ok = pneuma_test::check("divider centre deflection: chambers vs prescribed "
                          "p1 - p2",
                          two.summary.get_vector("m0_u")[0],
                          one.summary.get_vector("m0_u")[0],
                          1e-6)
       && ok;
  return ok ? 0 : 1;
}
