// V3 (doc/verification.md): inflated sphere, incompressible neo-Hookean,
// pressure control: p R/(mu H) = 2 (1/l - 1/l^7). The stretch l = r/R
// reached at the pressures of l = 1.1, 1.2 and 1.3 must be within 0.5 %.
// Asking for more than p_max = 1.239463 mu H/R must stop cleanly with exit
// code 2 and a message that names the limit point.

#include "test_tools.h"

#include <cmath>

namespace
{
  pneuma::RunResult
  inflate(const double p)
  {
    // R = 1, mu H = 1000 N/m. Supports that allow uniform expansion.
    return pneuma_test::run(
      {{"Geometry/Type", "sphere"},
       {"Geometry/sphere/Radius", "1"},
       {"Geometry/Global refinements", "3"},
       {"Discretisation/Polynomial degree", "2"},
       {"Materials/Region 0/Law", "neo-Hookean"},
       {"Materials/Region 0/Thickness", "1e-3"},
       {"Materials/Region 0/neo-Hookean/Shear modulus", "1e6"},
       {"Loads/Pressure/Function expression", std::to_string(p) + "*t"},
       {"Boundary conditions/Fixed points",
        "0,0,1: xy; 0,0,-1: xy; 1,0,0: yz; -1,0,0: yz"},
       {"Load stepping/Initial increment", "0.25"},
       {"Output/Directory", "output-v3"},
       {"Output/Monitor points", "1,0,0"}});
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  for (const double l : {1.1, 1.2, 1.3})
    {
      const double p = 1e3 * 2. * (1. / l - std::pow(l, -7.));
      const auto   s = inflate(p);
      ok             = ok && s.exit_code == 0;
      char name[64];
      std::snprintf(name, sizeof(name), "stretch at pR/(muH) = %.6f", p / 1e3);
      ok =
        pneuma_test::check(name, 1. + s.summary.get_vector("m0_u")[0], l, 5e-3)
        && ok;
    }
  // Past the limit point: a clean stop.
  const auto s = inflate(1.3e3);
  const bool clean =
    s.exit_code == 2 && s.message.find("limit point") != std::string::npos;
  std::printf(
    "p = 1.3 mu H/R > p_max: exit code %d, limit point reported: %s\n",
    s.exit_code,
    clean ? "yes" : "no");
  std::printf("last converged stretch %.3f (limit point at 1.383)\n",
              1. + s.summary.get_vector("m0_u")[0]);
  return (ok && clean) ? 0 : 1;
}
