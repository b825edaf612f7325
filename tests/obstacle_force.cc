// Obstacles loaded by a force (issue "Membranes that touch": a rigid body
// "loaded by a force (its position an unknown)"), Obstacles/Obstacle
// k/Control = force: one border unknown s per obstacle, its position along
// its Force direction e, with the row -(F + e . f) = 0 (f the membrane's
// contact force on it).
// 1. The tangent against central finite differences of the residual, the
//    border unknowns included (B, C, D): the square membrane of
//    tests/obstacle_contact at a smooth random state, pressed from above
//    by a force-controlled plane and from below by a force-controlled
//    sphere, on degree 1 and 2; and the plane with Coulomb friction
//    (mu = 0.3; its B and C differ), every point starting in contact
//    (0.4 % of its offset) and a random state of 2e-6 m, so that points
//    stick and slip. The obstacles must act (they change |J d| by more
//    than 1 %).
// 2. parameter_files/tube_pressed_by_force.prm: the tube of
//    tests/obstacle_contact squeezed by two plates with 600 N each.
//    (a) The force on each plate equals the load (the row's residual).
//    (b) The same equilibrium under displacement control: the plates
//        moved to where the force run left them give the force 600 N and
//        the same contact area (a unique equilibrium; to Newton's
//        tolerance).
//    (c) The closed form: the flat width is b = F / (p L), the free arcs
//        half circles of the mid-surface's height H with hoop force
//        T = p H / 2 and b = (2 pi R lambda - pi H) / 2 (lambda the hoop
//        stretch of T): the plates' distance H + t against the two
//        plates' positions (first order in the contact's edge, like the
//        force of tests/obstacle_contact).
//    (d) Stable (no negative eigenvalue of the bordered tangent, the
//        plates' positions counted as coordinates of the energy) and
//        Newton superlinear in the last step.
// The same on 2 ranks.

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{

  bool
  tangent_check(const unsigned int degree, const bool friction)
  {
    pneuma_test::Settings settings = {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "2"},
      {"Discretisation/Polynomial degree", std::to_string(degree)},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e8"},
      {"Output/Quiet", "true"}};
    // With friction every point starts in contact (0.4 % of its offset)
    // and sticks there; a small random state keeps them in contact, some
    // sticking, some slipping (as in tests/obstacle_friction).
    const double amplitude = friction ? 2e-6 : 0.02, h = friction ? 1e-9 : 1e-7;
    const auto   bare =
      pneuma_test::make(settings)->check_tangent(1., amplitude, h);
    settings.insert(settings.end(),
                    {{"Obstacles/Number of obstacles", "2"},
                     {"Obstacles/Obstacle 1/Shape", "plane"},
                     {"Obstacles/Obstacle 1/plane/Point",
                      friction ? "0, 0, 0.000498" : "0, 0, 0.01"},
                     {"Obstacles/Obstacle 1/plane/Normal", "0, 0, -1"},
                     {"Obstacles/Obstacle 1/Control", "force"},
                     {"Obstacles/Obstacle 1/Force direction", "0, 0, -1"},
                     {"Obstacles/Obstacle 1/Force/Function expression", "50"},
                     {"Obstacles/Obstacle 2/Shape", "sphere"},
                     {"Obstacles/Obstacle 2/sphere/Centre", "0.2, 0.1, -0.305"},
                     {"Obstacles/Obstacle 2/sphere/Radius", "0.3"},
                     {"Obstacles/Obstacle 2/Control", "force"},
                     {"Obstacles/Obstacle 2/Force direction", "0.2, 0, 1"},
                     {"Obstacles/Obstacle 2/Force/Function expression", "20"}});
    if (friction)
      settings.push_back({"Obstacles/Obstacle 1/Friction coefficient", "0.3"});
    const auto check =
      pneuma_test::make(settings)->check_tangent(1., amplitude, h);
    const double error  = check.first;
    const bool   active = std::abs(check.second / bare.second - 1.) > 0.01;
    const bool   pass   = error < 1e-6 && active;
    if (pneuma_test::root())
      std::printf("tangent vs finite differences, force-controlled plane%s "
                  "and sphere, degree %u: %s%s\n",
                  friction ? " with friction" : "",
                  degree,
                  error < 1e-6 ? "relative error < 1e-6" : "FAIL",
                  active ? ", |J d| changed by > 1 %"
                         : ", FAIL: obstacles not active");
    if (!pass && pneuma_test::root())
      std::printf("  relative error %.3e, |J d| %.3e against %.3e\n",
                  error,
                  check.second,
                  bare.second);
    return pass;
  }

  pneuma::RunResult
  run_file(const pneuma_test::Settings &settings)
  {
    pneuma_test::Settings all = pneuma_test::quiet();
    all.insert(all.end(), settings.begin(), settings.end());
    return pneuma_test::make(all,
                             std::string(PNEUMA_SOURCE_DIR)
                               + "/parameter_files/tube_pressed_by_force.prm")
      ->run();
  }


  bool
  tube_pressed()
  {
    const double R = 0.2, L = 0.4, t = 1e-3, E = 1e8, nu = 0.3, p = 1e4,
                 F = 600.;
    const auto s   = run_file({});
    if (pneuma_test::failed(s, "force control"))
      return false;
    bool         ok = true;
    const auto   f1 = s.summary.get_vector("obstacle1_force");
    const auto   f2 = s.summary.get_vector("obstacle2_force");
    const double z1 = s.summary.get_vector("obstacle1_displacement")[2];
    const double z2 = s.summary.get_vector("obstacle2_displacement")[2];
    ok &= pneuma_test::check("plate 1's force = its load", f1[2], F, 1e-9);
    ok &= pneuma_test::check("plate 2's force = its load", -f2[2], F, 1e-9);

    // (b) The same plates' positions under displacement control.
    const auto ramp = [](const double z) {
      return "0; 0; " + pneuma_test::number(z) + "*max(t - 1, 0)";
    };
    const auto d = run_file(
      {{"Obstacles/Obstacle 1/Control", "displacement"},
       {"Obstacles/Obstacle 1/Displacement/Function expression", ramp(z1)},
       {"Obstacles/Obstacle 2/Control", "displacement"},
       {"Obstacles/Obstacle 2/Displacement/Function expression", ramp(z2)},
       {"Newton/Residual tolerance", "1e-12"}});
    if (pneuma_test::failed(d, "displacement control"))
      return false;
    ok &= pneuma_test::check(
      "force at the plates' positions under displacement control",
      d.summary.get_vector("obstacle1_force")[2],
      F,
      1e-7);
    ok &= pneuma_test::check("contact area there",
                             d.get("obstacle1_contact_area"),
                             s.get("obstacle1_contact_area"),
                             1e-9);

    // (c) The closed form: H from b = F / (p L).
    const double b = F / (p * L), c = E * t / (1. - nu * nu);
    double       H = 0.3;
    for (unsigned int k = 0; k < 100; ++k)
      {
        // lambda of T = p H / 2, then the flat width's equation in H.
        const double T      = p * H / 2.;
        double       lambda = 1.;
        for (unsigned int i = 0; i < 50; ++i)
          lambda -= (c * lambda * (lambda * lambda - 1.) / 2. - T)
                    / (c * (3. * lambda * lambda - 1.) / 2.);
        H = (2. * M_PI * R * lambda - 2. * b) / M_PI;
      }
    const double distance = (0.205 + z1) - (-0.205 + z2);
    ok &= pneuma_test::check("plates' distance = H + t (closed form)",
                             distance,
                             H + t,
                             4e-4);

    // (d) Stable and superlinear.
    const bool stable = s.get("negative_eigenvalues") == 0.;
    if (pneuma_test::root())
      std::printf("negative eigenvalues of the bordered tangent: %s\n",
                  stable ? "none" : "FAIL");
    const double order = pneuma_test::last_step_order(s);
    if (pneuma_test::root())
      std::printf("Newton's rate in the last step: %s\n",
                  order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
    if (pneuma_test::root())
      {
        std::printf("Newton iterations per step:");
        for (const auto n : s.step_iterations)
          std::printf(" %u", n);
        std::printf("\n");
      }
    return ok && stable && order > 1.4;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  for (const unsigned int degree : {1u, 2u})
    ok = tangent_check(degree, false) && ok;
  ok = tangent_check(2, true) && ok;
  ok = tube_pressed() && ok;
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
