// Shells with bending in the eigen analyses (membrane/bending,
// doc/theory.md §21): a simply supported square plate (side a = 1 m,
// t = 1 cm, E = 1 GPa, nu = 0.3, Q2 on 16 x 16 cells).
// - Modal analysis (density 1000 kg/m^3): the lowest four natural
//   frequencies against Kirchhoff's f_mn = pi/2 (m^2 + n^2)/a^2
//   sqrt(D/(rho t)), D = E t^3/(12 (1 - nu^2)): the bending modes (1,1),
//   (1,2), (2,1), (2,2), far below the in-plane ones.
// - Linear buckling under uniaxial compression: a dead line load N_ref t
//   pushes edge x+ towards edge x- (held in x; the edges y+- free in the
//   plane), so the plate is in uniform compression N_ref t; the buckling
//   analysis at t = 1 against N_cr = 4 pi^2 D/a^2 (k = 4 of a square plate
//   in mode (1,1)).
// The same on 2 ranks.

#include "test_tools.h"

#include <cmath>
#include <cstdio>

namespace
{
  pneuma_test::Settings
  square_plate()
  {
    return {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "4"},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Thickness", "0.01"},
      {"Materials/Region 0/Density", "1000"},
      {"Materials/Region 0/Bending", "shell"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  const double                             D = 1e9 * 1e-6 / (12. * (1. - 0.09));

  // Natural frequencies.
  {
    auto settings = square_plate();
    settings.insert(settings.end(),
                    {{"Boundary conditions/Fixed boundaries",
                      "0: xyz; 1: xyz; 2: xyz; 3: xyz"},
                     {"Eigen analysis/Type", "modal"},
                     {"Eigen analysis/Number of modes", "4"}});
    const auto s = pneuma_test::run(settings);
    if (pneuma_test::failed(s, "modal analysis"))
      return 1;
    const double       f0      = M_PI / 2. * std::sqrt(D / (1000. * 0.01));
    const unsigned int m2n2[4] = {2, 5, 5, 8};
    for (unsigned int k = 1; k <= 4; ++k)
      ok =
        pneuma_test::check("frequency of mode " + std::to_string(k) + " [Hz]",
                           s.get("mode" + std::to_string(k) + "_frequency"),
                           f0 * m2n2[k - 1],
                           5e-3)
        && ok;
  }

  // Linear buckling under uniaxial compression.
  {
    const double N        = 1000.;
    auto         settings = square_plate();
    settings.insert(settings.end(),
                    {{"Boundary conditions/Fixed boundaries",
                      "0: xz; 1: z; 2: z; 3: z"},
                     {"Boundary conditions/Fixed points", "-0.5, 0, 0: y"},
                     {"Loads/Line load boundaries", "1"},
                     {"Loads/Line load/Function expression",
                      pneuma_test::number(-N) + "*t; 0; 0"},
                     {"Eigen analysis/Type", "buckling"},
                     {"Eigen analysis/Number of modes", "1"}});
    const auto s = pneuma_test::run(settings);
    if (pneuma_test::failed(s, "buckling analysis"))
      return 1;
    ok = pneuma_test::check("critical compression [N/m]",
                            N * s.get("mode1_critical_time"),
                            4. * M_PI * M_PI * D,
                            2e-3)
         && ok;
  }
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
