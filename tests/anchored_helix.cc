// Anchored helices tensioned after the inflation (doc/verification.md
// "Anchored helix"): tests/tensairity_scene.prm without its transverse
// load, the two helices (steel, r 5 mm, 120 elements, one turn over the
// 2 m tube, tied to the rims of the end plates) at 10 % of their 2 kN
// prestress while the tube is inflated to 1 bar (stage 1), then tensioned
// to the full prestress factor in stage 2 (Prestress factor 0.1 + 0.9
// min(max(t - 1, 0), 1)). Frictionless contact. Checks per cable:
//  - balance: the tie forces plus the contact resultant vanish (1e-8 of
//    the total contact force);
//  - a frictionless helix carries a constant tension: (max - min)/mean
//    within 0.5 %;
//  - the line load on the deformed tube is T sin^2(alpha)/rho: its
//    integral T sin^2(alpha) L/rho, with rho and alpha of the deformed
//    helix from its length L and the plates' distance P (L^2 = (2 pi
//    rho)^2 + P^2), against the contact force's total less the resultant
//    (the ends: the cable leaves the wall towards the ties 4.8 mm off the
//    rims, and the kinks there press with two concentrated forces that
//    make the resultant; a full turn of the line load has none), 0.5 %.
// 1 and 2 ranks print the same.

#include "test_tools.h"

#include <cmath>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string stage = "0.1 + 0.9*max(0, min(t - 1, 1))";
  const auto        s =
    pneuma_test::make(
      {{"Output/Quiet", "true"},
       {"Output/Directory", "run-output"},
       {"Output/Test output", "false"},
       {"Newton/Print convergence table", "false"},
       {"Loads/Surface load", "false"},
       {"Cables/Cable 1/Prestress factor/Function expression", stage},
       {"Cables/Cable 2/Prestress factor/Function expression", stage}},
      std::string(PNEUMA_SOURCE_DIR) + "/tests/tensairity_scene.prm")
      ->run();
  if (s.exit_code != 0)
    {
      if (root)
        std::printf("run failed (exit %d): %s\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }
  bool         ok = true;
  const double P  = 2. + s.summary.get_vector("m5_u")[0];
  for (unsigned int k = 1; k <= 2; ++k)
    {
      const std::string c     = "cable" + std::to_string(k);
      const std::string p     = "contact" + std::to_string(k);
      const std::string name  = "cable " + std::to_string(k) + ": ";
      const double      T_max = s.get(c + "_max_force"),
                   T_min      = s.get(c + "_min_force");
      const double T          = 0.5 * (T_max + T_min);
      if (root)
        std::printf("%stension %.2f N (staged prestress 2000 N, taken up "
                    "by the wall)\n",
                    name.c_str(),
                    T);
      // Balance.
      const auto f_start =
        s.summary.get_vector("tie" + std::to_string(2 * k - 1) + "_force");
      const auto f_end =
        s.summary.get_vector("tie" + std::to_string(2 * k) + "_force");
      const auto   resultant = s.summary.get_vector(p + "_force");
      const double total     = s.get(p + "_total_force");
      double       imbalance = 0., resultant_norm = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        {
          imbalance += std::pow(f_start[d] + f_end[d] + resultant[d], 2);
          resultant_norm += resultant[d] * resultant[d];
        }
      imbalance           = std::sqrt(imbalance) / total;
      resultant_norm      = std::sqrt(resultant_norm);
      const bool balanced = imbalance <= 1e-8;
      if (root)
        std::printf("%s|tie forces + contact resultant| / total contact "
                    "force %s 1e-8 %s\n",
                    name.c_str(),
                    balanced ? "<=" : ">",
                    balanced ? "PASS" : "FAIL");
      ok = ok && balanced;
      // Constant tension.
      ok = pneuma_test::check(name + "smallest tension vs largest",
                              T_min,
                              T_max,
                              5e-3)
           && ok;
      // The line load's integral on the deformed helix.
      const double L    = s.get(c + "_length");
      const double rho  = std::sqrt(L * L - P * P) / (2. * M_PI);
      const double sin2 = std::pow(2. * M_PI * rho / L, 2);
      ok                = pneuma_test::check(name
                                + "contact force (total - |resultant|) vs T "
                                                 "sin^2(alpha) L / rho [N]",
                              total - resultant_norm,
                              T * sin2 * L / rho,
                              5e-3)
           && ok;
    }
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
