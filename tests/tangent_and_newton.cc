// Consistency of the linearisation: the assembled tangent (material,
// geometric and follower-pressure parts) against central finite
// differences of the residual at a perturbed state, for every membrane law
// and both element degrees; and Newton's quadratic rate near the solution
// (Hencky membrane, last load step).

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // The tangent of a pressurised sphere at a rough random state; with
  // wrinkling (tension field theory) that state puts quadrature points in
  // all three states (taut, wrinkled, slack).
  const auto check = [&](const std::string &law,
                         const unsigned int degree,
                         const bool         wrinkling,
                         const double       smoothing = 0.) {
    const auto simulator = pneuma_test::make(
      {{"Geometry/Type", "sphere"},
       {"Geometry/sphere/Radius", "1"},
       {"Geometry/Global refinements", "1"},
       {"Discretisation/Polynomial degree", std::to_string(degree)},
       {"Materials/Region 0/Law", law},
       {"Materials/Region 0/Wrinkling", wrinkling ? "tension field" : "none"},
       {"Materials/Region 0/Wrinkling smoothing",
        pneuma_test::number(smoothing)},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e6"},
       {"Materials/Region 0/neo-Hookean/Shear modulus", "1e6"},
       {"Materials/Region 0/Mooney-Rivlin/C10", "3e5"},
       {"Materials/Region 0/Mooney-Rivlin/C01", "2e5"},
       {"Materials/Region 0/Gent/Shear modulus", "1e6"},
       {"Materials/Region 0/Gent/Limiting extensibility", "30"},
       {"Loads/Pressure/Function expression", "800*t"},
       {"Output/Quiet", "true"}});
    const double error = simulator->check_tangent(1., 0.05, 1e-6).first;
    const bool   pass  = error < 1e-6;
    std::printf("tangent vs finite differences, %s%s, degree %u: %s\n",
                law.c_str(),
                !wrinkling       ? ""
                : smoothing > 0. ? " with smoothed wrinkling"
                                 : " with wrinkling",
                degree,
                pass ? "relative error < 1e-6" : "FAIL");
    if (!pass)
      std::printf("  relative error %.3e\n", error);
    ok = ok && pass;
  };
  for (const std::string law :
       {"Saint Venant-Kirchhoff", "neo-Hookean", "Mooney-Rivlin"})
    for (const unsigned int degree : {1u, 2u})
      check(law, degree, false);
  for (const std::string law :
       {"Saint Venant-Kirchhoff", "neo-Hookean", "Mooney-Rivlin", "Gent"})
    for (const unsigned int degree : {1u, 2u})
      check(law, degree, true);
  // The smoothed relaxed energy (doc/theory.md 2.1), over a strain of 1e-3.
  for (const std::string law : {"Saint Venant-Kirchhoff", "neo-Hookean"})
    for (const unsigned int degree : {1u, 2u})
      check(law, degree, true, 1e-3);

  // Quadratic rate: order log(r_{k+1})/log(r_k) (residuals relative to the
  // first of the step) of the last iteration above round-off.
  const auto s = pneuma_test::run(
    {{"Geometry/Type", "disc"},
     {"Geometry/disc/Radius", "0.1425"},
     {"Geometry/Global refinements", "3"},
     {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "3.11488e8"},
     {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.34"},
     {"Loads/Pressure/Function expression", "1e4*t"},
     {"Boundary conditions/Fixed boundaries", "0: xyz"},
     {"Load stepping/Initial increment", "0.25"},
     {"Newton/Residual tolerance", "1e-12"},
     {"Output/Directory", "output-newton"}});
  const auto &r     = s.last_residual_history;
  double      order = 0.;
  for (unsigned int k = 1; k + 1 < r.size(); ++k)
    if (r[k + 1] / r[0] > 1e-11 && r[k] / r[0] < 1e-1)
      order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
  std::printf("Newton iterations in the last step: %u, observed order %s\n",
              static_cast<unsigned int>(r.size() - 1),
              order >= 1.8 ? ">= 1.8" : "< 1.8 (FAIL)");
  ok = ok && s.exit_code == 0 && order >= 1.8;
  return ok ? 0 : 1;
}
