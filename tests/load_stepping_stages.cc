// Per-stage maximum increments (Load stepping/Maximum increment with one
// value per stage, doc/theory.md §5 "Load stages"): the V1 disc under
// follower pressure 50 kPa (Q1, 768 cells) loaded in two stages, t in
// [0, 0.5] with steps of at most 0.25 and t in [0.5, 1] with steps of at
// most 0.0625. The steps are 0.25, 0.5, then 0.5625, ..., 1: the second
// stage starts with its own maximum although the first ended with a larger
// step, and no step exceeds its stage's maximum. The centre deflection
// stays the finite-strain reference 26.194 mm (within 0.5 %).

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  const pneuma::RunResult run = pneuma_test::run(
    {{"Geometry/Type", "disc"},
     {"Geometry/disc/Radius", "0.1425"},
     {"Geometry/Global refinements", "3"},
     {"Materials/Region 0/Law", "Saint Venant-Kirchhoff"},
     {"Materials/Region 0/Thickness", "1e-3"},
     {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "3.11488e8"},
     {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.34"},
     {"Loads/Pressure/Function expression", "5e4*t"},
     {"Boundary conditions/Fixed boundaries", "0: xyz"},
     {"Load stepping/Stage end times", "0.5, 1"},
     {"Load stepping/Initial increment", "0.25"},
     {"Load stepping/Maximum increment", "0.25, 0.0625"},
     {"Output/Directory", "output-stages"},
     {"Output/Monitor points", "0,0,0"}});
  ok = run.exit_code == 0 && ok;

  // The converged step times (history row 0 is the initial state).
  std::vector<double> times;
  for (unsigned int k = 1; k < run.history.size(); ++k)
    times.push_back(run.history[k].get("time"));
  std::string list;
  bool        within = !times.empty();
  double      t_old  = 0.;
  for (const double t : times)
    {
      list += " " + std::to_string(t).substr(0, 6);
      const double maximum = t <= 0.5 + 1e-12 ? 0.25 : 0.0625;
      within               = within && t - t_old <= maximum * (1. + 1e-12);
      t_old                = t;
    }
  std::printf("step times:%s (%s)\n",
              list.c_str(),
              within ? "each within its stage's maximum"
                     : "FAIL: a step exceeds its stage's maximum");
  ok = within && ok;
  ok =
    pneuma_test::check("steps in the two stages", times.size(), 10., 0.) && ok;
  ok = pneuma_test::check("first step of stage 2",
                          times.size() > 2 ? times[2] - times[1] : 0.,
                          0.0625,
                          1e-12)
       && ok;
  ok = pneuma_test::check("V1 disc, w0 at 50 kPa [m]",
                          run.summary.get_vector("m0_u")[2],
                          26.194e-3,
                          5e-3)
       && ok;
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
