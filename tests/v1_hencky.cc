// V1 (doc/verification.md): clamped circular membrane under follower pressure,
// finite-strain St. Venant-Kirchhoff, started from the flat, unstressed
// state. a = 0.1425 m, E h = 311488 N/m, nu = 0.34. Reference centre
// deflection (exact solution of the finite-strain membrane equations):
// w0 = 15.247 mm at 10 kPa and 26.194 mm at 50 kPa. Checks the finest mesh
// within 0.5 % and prints the observed convergence order over three meshes
// (self-convergence, expected 2 for Q1 point values).

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  for (const double q : {1e4, 5e4})
    {
      const double        reference = (q == 1e4) ? 15.247e-3 : 26.194e-3;
      std::vector<double> w;
      for (const unsigned int refinement : {2u, 3u, 4u})
        {
          const auto summary = pneuma_test::run(
            {{"Geometry/Type", "disc"},
             {"Geometry/disc/Radius", "0.1425"},
             {"Geometry/Global refinements", std::to_string(refinement)},
             {"Materials/Region 0/Law", "Saint Venant-Kirchhoff"},
             {"Materials/Region 0/Thickness", "1e-3"},
             {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
              "3.11488e8"},
             {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio",
              "0.34"},
             {"Loads/Pressure/Function expression", std::to_string(q) + "*t"},
             {"Boundary conditions/Fixed boundaries", "0: xyz"},
             {"Load stepping/Initial increment", "0.25"},
             {"Output/Directory", "output-v1"},
             {"Output/Monitor points", "0,0,0"}});
          ok = ok && summary.exit_code == 0;
          w.push_back(summary.summary.get_vector("m0_u")[2]);
        }
      const double order =
        std::log(std::abs(w[0] - w[1]) / std::abs(w[1] - w[2])) / std::log(2.);
      std::printf("q = %.0f Pa: w0 on 192, 768, 3072 cells: %.4e %.4e %.4e m\n",
                  q,
                  w[0],
                  w[1],
                  w[2]);
      std::printf("observed order %.1f\n", order);
      ok = pneuma_test::check("w0 at " + std::to_string(int(q)) + " Pa",
                              w[2],
                              reference,
                              5e-3)
           && ok;
      ok = ok && order > 1.5;
    }
  return ok ? 0 : 1;
}
