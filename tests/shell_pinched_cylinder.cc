// Membrane locking of the Q2 shell (membrane/bending, doc/theory.md §21)
// on the pinched cylinder with rigid end diaphragms of MacNeal & Harder's
// shell obstacle course (parameter_files/pinched_cylinder.prm: R = 300,
// L = 600, t = 3, E = 3e6, nu = 0.3, an eighth with its three symmetry
// edges, P = 1000 so that the point moves 0.6 % of the thickness).
// Reference: the loaded point moves 1.8248e-5 P. With the assumed
// membrane strains of a Q2 shell (MITC9 tying) it converges from above
// (with the displacement's strains, from below: 0.990, 0.994, 0.999 on
// 8, 16, 32 cells per side): a coarse mesh is too soft under the point
// load, 1.097 of the reference on 8 x 8, 1.013 on 16 x 16, within 1e-3
// on 32 x 32. Its strain energy, membrane and bending (38 % and 62 %), is half
// the work of the load (Clapeyron).

#include "obstacle_course.h"

#include <cstdio>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok        = true;
  const double                             reference = 1.8248e-5 * 1000.;
  double                                   w[3];
  for (unsigned int r = 1; r <= 3; ++r)
    {
      const auto s = pneuma_test::run_course("pinched_cylinder", r);
      if (pneuma_test::failed(s, "pinched cylinder"))
        return 1;
      w[r - 1] = -s.get("m0_u_z");
      // Clapeyron: the linear shell's strain energy is half the load's
      // work, here split between membrane and bending.
      if (r == 3)
        ok = pneuma_test::check(
               "pinched cylinder on 32 x 32 Q2 cells: membrane + bending "
               "energy against half the load's work [J]",
               s.get("membrane_energy") + s.get("bending_energy"),
               0.5 * 250. * w[2],
               2e-3)
             && ok;
    }
  if (pneuma_test::root())
    std::printf("pinched cylinder on 8 x 8, 16 x 16 and 32 x 32 Q2 cells per "
                "eighth: %.3f, %.3f and %.3f of the reference\n",
                w[0] / reference,
                w[1] / reference,
                w[2] / reference);
  ok = w[0] > w[1] && w[1] > w[2] && ok;
  ok = pneuma_test::check(
         "pinched cylinder on 32 x 32 Q2 cells: the loaded point [m]",
         w[2],
         reference,
         2e-3)
       && ok;
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
