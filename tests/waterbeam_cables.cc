// The paper's Figure 11 scene (parameter_files/waterbeam_cables.prm,
// doc/scenes.md "Waterbeam with spiral cables"): the waterbeam with two
// spiral solid-beam cables around both chambers, tied to the end plates, in
// contact with the three hulls, through the inflation (stage 1) and the
// water filling of chamber 2 with the turnbuckle tensioning the cables
// (stage 2); weightless cables here, so that their balance is exact.
// Checks:
//  - each cable's two plate ties and its contact resultant balance
//    (1e-8 of its contact force);
//  - the support reactions carry the applied load (walls, plates, the
//    chambers' pressures with the water's weight), x, y, z (1e-8);
//  - the liquid volume is the prescribed 5 litres (1e-9);
//  - chamber 1's gas keeps p_abs V^1.4 from its seal at t = 1 (1e-9);
//  - the mirror-image cables carry the same tension (1e-6);
//  - the inflation tensions the cables and the turnbuckle adds to it;
//  - the wrapped, filled waterbeam is stable (no negative eigenvalue);
//  - 1 and 2 ranks print the same.

#include "scene_history.h"
#include "test_tools.h"

#include <cmath>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const auto s =
    pneuma_test::make(
      {{"Output/Quiet", "true"},
       {"Output/Write VTU", "false"},
       {"Newton/Print convergence table", "false"},
       {"Geometry/gmsh/Mesh file",
        std::string(PNEUMA_SOURCE_DIR) + "/meshes/waterbeam.msh"},
       {"Cables/Cable 1/Density", "0"},
       {"Cables/Cable 2/Density", "0"},
       {"Load stepping/Stage end times", "1, 2"},
       {"Load stepping/Control", "load, load"},
       {"Load stepping/Maximum increment", "0.5"},
       {"Load stepping/Path following/Target monitor value", ""}},
      std::string(PNEUMA_SOURCE_DIR) + "/parameter_files/waterbeam_cables.prm")
      ->run();
  if (s.exit_code != 0)
    {
      if (root)
        std::printf("run failed (exit %d): %s\nFAILED\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }
  bool       ok     = true;
  const auto report = [&](const std::string &name, const bool pass) {
    if (root)
      std::printf("%s: %s\n", name.c_str(), pass ? "PASS" : "FAIL");
    ok = ok && pass;
  };

  for (unsigned int k = 1; k <= 2; ++k)
    {
      const std::string c = std::to_string(k);
      const auto        t1 =
        s.summary.get_vector("tie" + std::to_string(2 * k - 1) + "_force");
      const auto t2 =
        s.summary.get_vector("tie" + std::to_string(2 * k) + "_force");
      const auto f   = s.summary.get_vector("contact" + c + "_force");
      double     sum = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        sum = std::hypot(sum, t1[d] + t2[d] + f[d]);
      report("cable " + c
               + ": |plate ties + contact resultant| <= 1e-8 of "
                 "its contact force",
             sum <= 1e-8 * s.get("contact" + c + "_total_force"));
    }
  const auto reaction = s.summary.get_vector("reaction");
  const auto applied  = s.summary.get_vector("applied_load");
  bool       balanced = true;
  for (unsigned int d = 0; d < 3; ++d)
    balanced =
      balanced
      && std::abs(reaction[d] + applied[d]) <= 1e-8 * std::abs(applied[2]);
  report("reactions + applied load = 0 in x, y, z (1e-8 of the vertical "
         "load)",
         balanced);
  // The same at every converged state, from history.csv's columns (the
  // force a load-deflection curve plots, scripts/plot_bending.py).
  bool steps_balanced = s.history.size() > 2;
  for (unsigned int k = 1; k < s.history.size(); ++k)
    for (const char *c : {"_x", "_y", "_z"})
      steps_balanced =
        steps_balanced
        && std::abs(s.history[k].get(std::string("reaction") + c)
                    + s.history[k].get(std::string("applied_load") + c))
             <= 1e-8 * std::abs(applied[2]);
  report("reactions + applied load = 0 at each of the "
           + std::to_string(s.history.size() - 1)
           + " converged states (history)",
         steps_balanced);
  ok = pneuma_test::check("liquid volume in chamber 2 [m^3]",
                          s.get("c3_liquid_volume"),
                          0.005,
                          1e-9)
       && ok;
  ok = pneuma_test::check("cable 2 vs cable 1, largest tension (mirror "
                          "images)",
                          s.get("cable2_max_force"),
                          s.get("cable1_max_force"),
                          1e-6)
       && ok;

  const double gas_change = pneuma_test::sealed_gas_change(s, 1, 1.);
  const double inflated   = pneuma_test::at_time(s, 1., [](const auto &row) {
    return row.get("cable1_min_force");
  });
  report("chamber 1: p_abs V^1.4 at the end vs the seal, relative change "
         "<= 1e-9",
         gas_change <= 1e-9);
  if (root)
    std::printf("cable 1: least tension %.0f N inflated, %.0f N filled and "
                "tensioned\n",
                inflated,
                s.get("cable1_min_force"));
  report("the inflation tensions the cables (least tension > 100 N) and the "
         "turnbuckle adds to it",
         inflated > 100. && s.get("cable1_min_force") > inflated);
  report("filled: no negative eigenvalue of the tangent",
         s.get("negative_eigenvalues") == 0.);
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
