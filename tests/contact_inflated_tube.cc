// A cable pressed into an inflated tube (issue "Contact"): the airbeam
// tube (R = 0.23 m, t = 1 mm, E = 7.6e9 Pa, Q2, end caps held) is a gas
// chamber inflated to 1 bar and sealed; a prestressed cable spanning
// above it (R_c = 0.01 m, ends fixed 0.6 m to each side) is then pulled
// down by 5 cm at both ends and wraps onto the tube. Checks: equilibrium
// of the cable (support reactions + contact force = 0), equilibrium of
// membrane and gas (the reactions at the caps equal the contact force
// passed through the membrane), the sealed gas keeps p V^1.4, and the
// Newton iterations per step while contact points slide across cells.
// (The cable runs at x = 1.03, off the cells' vertex line x = 1: on a
// vertex the C0 master's normal is discontinuous, see doc/theory.md §10.)

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  const auto                               s  = pneuma_test::run(
    {{"Geometry/Type", "closed cylinder"},
                                    {"Geometry/closed cylinder/Radius", "0.23"},
                                    {"Geometry/closed cylinder/Length", "2"},
                                    {"Geometry/Global refinements", "2"},
                                    {"Discretisation/Polynomial degree", "2"},
                                    {"Materials/Region 0/Thickness", "1e-3"},
                                    {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
                                    {"Materials/Region 1/Thickness", "1e-2"},
                                    {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
                                    {"Materials/Region 2/Thickness", "1e-2"},
                                    {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
                                    {"Boundary conditions/Fixed regions", "1, 2"},
                                    {"Chambers/Number of chambers", "1"},
                                    {"Chambers/Chamber 1/Regions", "0, 1, 2"},
                                    {"Chambers/Chamber 1/Filling", "gas"},
                                    {"Chambers/Chamber 1/Gas/Control", "pressure"},
                                    {"Chambers/Chamber 1/Gas/Seal time", "1"},
                                    {"Chambers/Chamber 1/Gas/Pressure/Function expression", "1e5*min(t, 1)"},
                                    {"Cables/Number of cables", "1"},
                                    {"Cables/Cable 1/polyline/Points", "1.03, -0.6, 0.241; 1.03, 0.6, 0.241"},
                                    {"Cables/Cable 1/Number of elements", "48"},
                                    {"Cables/Cable 1/Section semi-axes", "0.01"},
                                    {"Cables/Cable 1/Prestress force", "500"},
                                    {"Cables/Cable 1/Start support", "fixed"},
                                    {"Cables/Cable 1/End support", "fixed"},
                                    {"Cables/Cable 1/Start displacement/Function expression",
                                     "0; 0; -0.05*max(t-1, 0)"},
                                    {"Cables/Cable 1/End displacement/Function expression",
                                     "0; 0; -0.05*max(t-1, 0)"},
                                    {"Contact/Number of pairs", "1"},
                                    {"Contact/Pair 1/Membrane regions", "0"},
                                    {"Contact/Pair 1/Penalty", "1e7"},
                                    {"Load stepping/Stage end times", "1, 2"},
                                    {"Load stepping/Initial increment", "0.1"},
                                    {"Load stepping/Maximum increment", "0.1"}});
  if (s.exit_code != 0 || !s.summary.has("contact1_points")
      || !s.summary.has("cable1_max_force") || !s.summary.has("c1_pressure"))
    {
      std::printf("run failed (exit %d): %s\nFAILED\n",
                  s.exit_code,
                  s.message.c_str());
      return 1;
    }
  const auto   force          = s.summary.get_vector("contact1_force");
  const auto   start_reaction = s.summary.get_vector("cable1_start_reaction");
  const auto   end_reaction   = s.summary.get_vector("cable1_end_reaction");
  const auto   reaction       = s.summary.get_vector("reaction");
  const double active_points  = s.get("contact1_active_points");
  std::printf("contact: %u/%u points active, resultant on the cable %.2f N "
              "(z), penetration %.2e m; cable force %.0f N; gas %.1f Pa\n",
              static_cast<unsigned int>(active_points),
              static_cast<unsigned int>(s.get("contact1_points")),
              force[2],
              s.get("contact1_max_penetration"),
              s.get("cable1_max_force"),
              s.get("c1_pressure"));
  ok &= active_points > 0;
  // Cable: reactions + contact force = 0 (z and x).
  for (const unsigned int d : {0u, 2u})
    ok &= pneuma_test::check(std::string("cable equilibrium, ") + "xyz"[d]
                               + ": -(reactions) = contact force",
                             -(start_reaction[d] + end_reaction[d]),
                             force[d],
                             1e-6);
  // Membrane + gas: the caps carry what the cable pushes in.
  for (const unsigned int d : {0u, 2u})
    ok &= pneuma_test::check(std::string("membrane equilibrium, ") + "xyz"[d]
                               + ": cap reactions = contact force",
                             reaction[d],
                             force[d],
                             1e-6);
  // Sealed gas: p V^1.4 at the seal and at the end. The history rows hold
  // the absolute pressure and the gas volume (pv_kappa is a summary value).
  double pv_seal = 0.;
  for (const auto &row : s.history)
    if (std::abs(row.get("time") - 1.) < 1e-12)
      pv_seal = row.get("c1_absolute_pressure")
                * std::pow(row.get("c1_gas_volume"), 1.4);
  ok &= pneuma_test::check("gas law p V^1.4 after sealing",
                           s.get("c1_pv_kappa"),
                           pv_seal,
                           1e-8);
  ok &= pneuma_test::check("gas compressed by the cable: p > 1 bar",
                           s.get("c1_pressure") > 1e5 ? 1. : 0.,
                           1.,
                           0.);
  std::printf("Newton iterations per step:");
  for (const auto n : s.step_iterations)
    std::printf(" %u", n);
  std::printf("\n%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
