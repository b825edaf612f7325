// V5 (doc/verification.md): a rigid vertical cylinder, radius a = 0.5 m, with a
// clamped circular membrane bottom (E h = 1e6 N/m, nu = 0.3, St.
// Venant-Kirchhoff), filled with 0.5 m^3 of water (rho g = 9810 N/m^3).
// The free-surface level follows from the volume constraint. References:
// level h = 0.61148 m above the rim plane, centre deflection 48.28 mm. The
// vertical reaction at the clamped rim equals the weight of the water to
// 1e-8 relative (the rigid wall, parallel to gravity, carries none).

#include "v5_tank_scene.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto s  = pneuma_test::run(pneuma_test::v5_tank(
    {{"Chambers/Chamber 1/Liquid/Volume/Function expression", "0.5*t"}},
    "output-v5"));
  bool       ok = s.exit_code == 0;
  ok = pneuma_test::check("level h", s.get("c1_level"), 0.61148, 5e-3) && ok;
  ok = pneuma_test::check("centre deflection w0",
                          -s.summary.get_vector("m0_u")[2],
                          0.04828,
                          5e-3)
       && ok;
  ok = pneuma_test::check("liquid volume", s.get("c1_liquid_volume"), 0.5, 1e-8)
       && ok;
  ok = pneuma_test::check("vertical reaction / water weight",
                          s.summary.get_vector("reaction")[2],
                          1000. * 9.81 * 0.5,
                          1e-8)
       && ok;
  return ok ? 0 : 1;
}
