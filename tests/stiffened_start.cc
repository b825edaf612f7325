// Newton's stiffened start and predicted-update test (doc/theory.md §5) on
// the closed cylinder of benchmarks/inflated_cylinder (R = 0.23 m, L = 2 m,
// t = 1 mm, E = 7.6e9 Pa, rigid steel plates, p = 1 bar in one step) at
// 34 816 Q1 cells, where the cells are finer than the boundary layer at
// the plates (9 mm) and the bare linear first iterate kinks the tube:
//  - with the stiffened start the step converges in 4 iterations; without
//    it in 5 (a watchdog step after the first iterate, whose residual is
//    1.6 |r_ref|; 6 before the predicted-update test);
//  - without it (Newton/Stiffened start = false) the iteration is the old
//    one, and both end in the same equilibrium (dR to 1e-9);
//  - dR against the finite-strain SVK membrane's 0.5908384 mm (the plates'
//    boundary layer and the mesh leave -0.03 %);
//  - 1 and 2 ranks print the same.

#include "test_tools.h"

#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string file = std::string(PNEUMA_SOURCE_DIR)
                           + "/benchmarks/inflated_cylinder/cylinder.prm";
  bool   ok = true;
  double dR[2];
  int    iterations[2];
  for (const bool stiffened : {true, false})
    {
      const auto s =
        pneuma_test::make({{"Output/Quiet", "true"},
                           {"Output/Write VTU", "false"},
                           {"Newton/Print convergence table", "false"},
                           {"Geometry/Global refinements", "5"},
                           {"Newton/Stiffened start",
                            stiffened ? "true" : "false"}},
                          file)
          ->run();
      if (s.exit_code != 0)
        {
          if (root)
            std::printf("run failed (exit %d): %s\n",
                        s.exit_code,
                        s.message.c_str());
          return 1;
        }
      dR[stiffened ? 0 : 1]         = s.summary.get_vector("m0_u")[1];
      iterations[stiffened ? 0 : 1] = int(s.get("newton_iterations"));
    }
  if (root)
    std::printf("Newton iterations of the full-load step: %d with the "
                "stiffened start, %d without\n",
                iterations[0],
                iterations[1]);
  ok &= pneuma_test::check("iterations with the stiffened start (at most 4)",
                           iterations[0] <= 4 ? 4. : iterations[0],
                           4.,
                           0.);
  ok &= pneuma_test::check("the start saves iterations (without it: 5)",
                           iterations[1] - iterations[0] >= 1 ? 1. : 0.,
                           1.,
                           0.);
  ok &=
    pneuma_test::check("dR with and without the start [m]", dR[0], dR[1], 1e-9);
  ok &= pneuma_test::check("dR against the SVK membrane [m]",
                           dR[0],
                           0.5908384e-3,
                           5e-4);
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
