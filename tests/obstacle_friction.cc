// Coulomb friction between the membrane and rigid obstacles (issue
// "Membranes that touch": "Frictionless and Coulomb friction (stick/slip
// like the cable contact)"; doc/theory.md §19, "Friction").
// 1. The tangent against central finite differences of the residual at a
//    random state near the reference, where every point starts in
//    contact and sticks where it is (its anchor): a flat sheet on the
//    ground (a plane 0.5 % of the offset into it) and a sphere in a
//    spherical cup (a curved obstacle: the anchor's projection turns with
//    the normal), each with mu = 0.3 (most points slip under the
//    perturbation) and mu = 1000 (all stick); Q1 and Q2 on the sheet.
// 2. A sheet (1 m x 0.5 m, Q2, E t = 1e6 N/m) pressed onto the ground by
//    1 kPa, then dragged by one edge 1 mm along x: once every point
//    slips, the friction force is mu times the normal force (mu = 0.3),
//    the dragged edge's reaction balances it, and every point in contact
//    is at Coulomb's limit; Newton's rate in the last step. The same on
//    2 ranks.

#include "test_tools.h"

#include <cmath>
#include <cstdio>

namespace
{

  pneuma_test::Settings
  sheet(const unsigned int degree, const std::string &ground)
  {
    return {
      {"Geometry/Type", "rectangle"},
      {"Geometry/rectangle/Length", "1"},
      {"Geometry/rectangle/Width", "0.5"},
      {"Geometry/Global refinements", "2"},
      {"Discretisation/Polynomial degree", std::to_string(degree)},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"},
      {"Obstacles/Number of obstacles", "1"},
      {"Obstacles/Obstacle 1/plane/Point", "0, 0, " + ground},
      {"Obstacles/Obstacle 1/plane/Normal", "0, 0, 1"}};
  }

  bool
  tangent_check(const std::string &name, pneuma_test::Settings settings)
  {
    settings.push_back({"Output/Quiet", "true"});
    const auto check =
      pneuma_test::make(settings)->check_tangent(1., 2e-6, 1e-9);
    // The same state without friction: the friction terms must change
    // the tangent's action (they are active).
    settings.push_back({"Obstacles/Obstacle 1/Friction coefficient", "0"});
    const auto bare =
      pneuma_test::make(settings)->check_tangent(1., 2e-6, 1e-9);
    const double change = std::abs(check.second / bare.second - 1.);
    const bool   pass   = check.first < 1e-6 && change > 1e-2;
    if (pneuma_test::root())
      std::printf("tangent vs finite differences, %s: %s%s\n",
                  name.c_str(),
                  check.first < 1e-6 ? "relative error < 1e-6" : "FAIL",
                  change > 1e-2 ? ", friction changes |K d| by > 1 %"
                                : ", FAIL: friction not active");
    if (!pass && pneuma_test::root())
      std::printf("  relative error %.3e, |K d| %.3e, without friction "
                  "%.3e\n",
                  check.first,
                  check.second,
                  bare.second);
    return pass;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // 1. Tangents: every point starts 0.5 % of its offset inside.
  for (const std::string mu : {"0.3", "1000"})
    {
      for (const unsigned int degree : {1u, 2u})
        {
          auto s = sheet(degree, "-0.0004975");
          s.push_back({"Obstacles/Obstacle 1/Friction coefficient", mu});
          ok &= tangent_check("sheet on the ground, Q" + std::to_string(degree)
                                + ", mu = " + mu,
                              s);
        }
      pneuma_test::Settings cup = {
        {"Geometry/Type", "sphere"},
        {"Geometry/sphere/Radius", "1"},
        {"Geometry/Global refinements", "1"},
        {"Discretisation/Polynomial degree", "2"},
        {"Materials/Region 0/Thickness", "1e-3"},
        {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
        {"Obstacles/Number of obstacles", "1"},
        {"Obstacles/Obstacle 1/Shape", "sphere"},
        {"Obstacles/Obstacle 1/sphere/Radius", "1.0004975"},
        {"Obstacles/Obstacle 1/sphere/Side", "inside"},
        {"Obstacles/Obstacle 1/Friction coefficient", mu}};
      ok &= tangent_check("sphere in a spherical cup, Q2, mu = " + mu, cup);
    }

  // 2. The sheet pressed and dragged.
  const double mu       = 0.3;
  auto         settings = sheet(2, "-0.0005");
  settings.insert(
    settings.end(),
    {{"Obstacles/Obstacle 1/Friction coefficient", pneuma_test::number(mu)},
     {"Loads/Pressure/Function expression", "-1000*min(t, 1)"},
     {"Boundary conditions/Prescribed displacement boundaries", "1"},
     {"Boundary conditions/Prescribed displacement/Function expression",
      "0.001*max(t - 1, 0); 0; 0"},
     {"Load stepping/Stage end times", "1, 2"},
     {"Load stepping/Initial increment", "0.25"},
     {"Load stepping/Maximum increment", "0.25"},
     {"Load stepping/Extrapolation", "none"},
     {"Newton/Residual tolerance", "1e-12"}});
  const auto s = pneuma_test::run(settings);
  if (s.exit_code != 0 || !s.summary.has("obstacle1_friction_force"))
    {
      if (pneuma_test::root())
        std::printf("run failed (exit %d): %s\nFAILED\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }
  const auto   force    = s.summary.get_vector("obstacle1_force");
  const double normal   = -force[2];
  const double friction = s.get("obstacle1_friction_force");
  ok &= pneuma_test::check("friction force = mu x normal force (all slip)",
                           friction,
                           mu * normal,
                           1e-9);
  ok &= pneuma_test::check("the obstacle's force along the drag = friction",
                           force[0],
                           friction,
                           1e-9);
  ok &= pneuma_test::check("the dragged edge's reaction = friction",
                           s.summary.get_vector("boundary_1_reaction")[0],
                           friction,
                           1e-5);
  ok &= pneuma_test::check("points at Coulomb's limit / points in contact",
                           s.get("obstacle1_slip_points"),
                           s.get("obstacle1_contact_points"),
                           0.);
  const double order = pneuma_test::last_step_order(s);
  if (pneuma_test::root())
    {
      std::printf("Newton's rate in the last step: %s\n",
                  order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
      std::printf("Newton iterations per step:");
      for (const auto n : s.step_iterations)
        std::printf(" %u", n);
      std::printf("\n");
    }
  ok &= order > 1.4;
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
