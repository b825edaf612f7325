// Connected chambers (issue "Chambers"): the two chambers of
// meshes/divided_cylinder.msh (a rigid tube divided by a membrane disc)
// share one gas amount: chamber 2 has Filling = connected to chamber 1.
// Chamber 2 is compressed by moving its hull and end plate (0.1 m at its
// end). Checks: one pressure in both chambers, the shared gas keeps
// p (V1 + V2)^1.4 = p_a (V1_0 + V2_0)^1.4 (1e-8), and the divider, loaded
// by equal pressures on both sides, stays flat (its centre moves less than
// 1e-9 m) while the total volume shrinks.

#include "test_paths.h"
#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               s = pneuma_test::run(
    {{"Geometry/Type", "gmsh"},
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
                                   {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "1e8"},
                                   {"Boundary conditions/Fixed regions", "0, 3"},
                                   {"Boundary conditions/Prescribed displacement regions", "1, 4"},
                                   {"Boundary conditions/Prescribed displacement/Function expression",
                                    "-0.1*t*(x-0.5)/0.5; 0; 0"},
                                   {"Load stepping/Initial increment", "0.25"},
                                   {"Newton/Residual tolerance", "1e-10"},
                                   {"Output/Monitor points", "0.5, 0, 0"},
                                   {"Chambers/Number of chambers", "2"},
                                   {"Chambers/Chamber 1/Regions", "0, 3, 2"},
                                   {"Chambers/Chamber 1/Interior point", "0.25, 0, 0"},
                                   {"Chambers/Chamber 1/Gas/Control", "gas amount"},
                                   {"Chambers/Chamber 1/Gas/Gas amount/Function expression", "1"},
                                   {"Chambers/Chamber 2/Regions", "1, 4, 2"},
                                   {"Chambers/Chamber 2/Interior point", "0.75, 0, 0"},
                                   {"Chambers/Chamber 2/Filling", "connected"},
                                   {"Chambers/Chamber 2/Connected to", "1"}});
  bool ok = s.exit_code == 0 && s.summary.has("c2_pressure");
  if (!ok)
    {
      std::printf("run failed (exit %d): %s\nFAILED\n",
                  s.exit_code,
                  s.message.c_str());
      return 1;
    }
  const double p_a          = 101325.;
  const auto   total_volume = [](const pneuma::Statistics &row) {
    return row.get("c1_volume") + row.get("c2_volume");
  };
  const double V0        = total_volume(s.history.front());
  double       worst_law = 0., worst_dp = 0.;
  for (const auto &row : s.history)
    {
      const double V = total_volume(row);
      worst_law =
        std::max(worst_law,
                 std::abs(row.get("c1_absolute_pressure") * std::pow(V, 1.4)
                            / (p_a * std::pow(V0, 1.4))
                          - 1.));
      worst_dp =
        std::max(worst_dp,
                 std::abs(row.get("c1_pressure") - row.get("c2_pressure")));
    }
  const double p_end = s.get("c1_pressure");
  std::printf("total volume %.6f -> %.6f m^3, shared gauge pressure %.1f Pa\n",
              V0,
              total_volume(s.summary),
              p_end);
  ok = pneuma_test::check("shared gas: max over steps of p (V1+V2)^1.4 / "
                          "(p_a V0^1.4)",
                          1. + worst_law,
                          1.,
                          1e-8)
       && ok;
  const bool same = worst_dp <= 1e-9 * std::abs(p_end);
  std::printf("one pressure in both chambers: max |p1 - p2| %.1e Pa %s\n",
              worst_dp < 5e-12 ? 0. : worst_dp,
              same ? "PASS" : "FAIL");
  const double w    = std::abs(s.summary.get_vector("m0_u")[0]);
  const bool   flat = w < 1e-9;
  std::printf("divider centre moves %.1e m (limit 1e-9) %s\n",
              w < 5e-13 ? 0. : w,
              flat ? "PASS" : "FAIL");
  ok = ok && same && flat && p_end > 0.;
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
