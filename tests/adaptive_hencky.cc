// Adaptive refinement on V1 (doc/verification.md): the clamped Hencky membrane
// at 10 kPa (w0 = 15.247 mm), Q1, from the 192-cell disc, three cycles of
// Kelly refinement (30 % of the cells each). Checks:
//  - every cycle converges and the mesh grows (hanging nodes, p4est);
//  - the last cycle's w0 is within 0.1 % of the reference (Kelly's
//    indicator does not aim at w0: the error is not monotone over the
//    cycles, and the uniform 768-cell mesh of V1 is as close);
//  - support reactions balance the pressure load (1e-6): the forces of
//    hanging nodes reach their parents;
//  - the tangent on the adapted mesh (hanging nodes) matches central finite
//    differences (1e-6).

#include "test_tools.h"

#include <pneuma/simulator/simulator.h>

#include <cmath>
#include <cstdio>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const pneuma_test::Settings              settings = {
                 {"Geometry/Type", "disc"},
                 {"Geometry/disc/Radius", "0.1425"},
                 {"Geometry/Global refinements", "2"},
                 {"Materials/Region 0/Law", "Saint Venant-Kirchhoff"},
                 {"Materials/Region 0/Thickness", "1e-3"},
                 {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "3.11488e8"},
                 {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.34"},
                 {"Loads/Pressure/Function expression", "1e4*t"},
                 {"Boundary conditions/Fixed boundaries", "0: xyz"},
                 {"Load stepping/Initial increment", "0.25"},
                 {"Adaptive refinement/Cycles", "3"},
                 {"Adaptive refinement/Refine fraction", "0.3"},
                 {"Output/Directory", "output-adaptive"},
                 {"Output/Quiet", "true"},
                 {"Output/Write VTU", "false"},
                 {"Output/Monitor points", "0,0,0"}};
  const auto simulator = pneuma_test::make(settings);
  const auto s         = simulator->run();

  bool ok = s.exit_code == 0 && s.cycles.size() == 4;
  for (unsigned int k = 0; k < s.cycles.size(); ++k)
    {
      const auto &cycle = s.cycles[k];
      ok                = ok && cycle.get("exit_code") == 0
           && (k == 0 || cycle.get("cells") > s.cycles[k - 1].get("cells"));
      std::printf("cycle %u: %u cells, w0 relative error %s 1e-3\n",
                  k,
                  static_cast<unsigned int>(cycle.get("cells")),
                  std::abs(cycle.get_vector("m0_u")[2] / 15.247e-3 - 1.) < 1e-3
                    ? "<"
                    : ">=");
    }
  ok = pneuma_test::check("w0 after 3 cycles [m]",
                          s.cycles.back().get_vector("m0_u")[2],
                          15.247e-3,
                          1e-3)
       && ok;

  const double imbalance = pneuma_test::load_imbalance(s);
  std::printf("|reactions + applied loads| / |applied load| %s 1e-6\n",
              imbalance < 1e-6 ? "<" : ">=");
  ok = ok && imbalance < 1e-6;

  const double tangent_error = simulator->check_tangent(1., 1e-3, 1e-7).first;
  std::printf("tangent on the adapted mesh vs finite differences: %s\n",
              tangent_error < 1e-6 ? "relative error < 1e-6" : "FAIL");
  if (tangent_error >= 1e-6)
    std::printf("  relative error %.3e\n", tangent_error);
  ok = ok && tangent_error < 1e-6;
  return ok ? 0 : 1;
}
