// Rigid obstacles (issue "Membranes that touch"): the penalty contact of
// the membrane with planes, spheres and cylinders.
// 1. The tangent against central finite differences of the residual: a
//    square membrane (side 1 m) at a smooth random state, pressed by a
//    plane from above, a sphere from below and held inside a cylinder
//    (the concave side), on degree 1 and 2.
// 2. A tube squeezed between two plates in plane strain (R = 0.2 m, a
//    0.4 m slice with its ends held in x, E t = 1e5 N/m, nu = 0.3, Q2 on
//    256 cells, follower pressure 10 kPa; the plates start 5 mm clear of
//    the inflated tube and close in by 5 cm each). Without bending the
//    free arcs are half circles of the mid-surface's height H, the hoop
//    force is T = p H / 2 and the flat width on each plate
//    b = (2 pi R lambda - pi H)/2 with lambda the hoop stretch of T: the
//    plate's force is p b L. Checks that closed form, the contact area of
//    the points in contact against b L and the force against p times it
//    (these two are first order at the contact's edge: a row of points
//    in or out), the symmetry of the two plates' forces, the equilibrium
//    of reactions and applied loads (pressure and obstacles), the
//    penetration against p J / penalty, and Newton's rate in the last
//    step (superlinear: points at the tangential edge of the contact
//    switch in the last iterations). The same on 2 ranks.

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{

  bool
  tangent_check(const unsigned int degree)
  {
    const pneuma_test::Settings settings = {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "2"},
      {"Discretisation/Polynomial degree", std::to_string(degree)},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e8"},
      {"Obstacles/Number of obstacles", "3"},
      {"Obstacles/Obstacle 1/Shape", "plane"},
      {"Obstacles/Obstacle 1/plane/Point", "0, 0, 0.01"},
      {"Obstacles/Obstacle 1/plane/Normal", "0, 0, -1"},
      {"Obstacles/Obstacle 2/Shape", "sphere"},
      {"Obstacles/Obstacle 2/sphere/Centre", "0.2, 0.1, -0.28"},
      {"Obstacles/Obstacle 2/sphere/Radius", "0.3"},
      {"Obstacles/Obstacle 3/Shape", "cylinder"},
      {"Obstacles/Obstacle 3/cylinder/Point", "0, 0, 0.5"},
      {"Obstacles/Obstacle 3/cylinder/Axis", "1, 0, 0"},
      {"Obstacles/Obstacle 3/cylinder/Radius", "0.49"},
      {"Obstacles/Obstacle 3/cylinder/Side", "inside"},
      {"Output/Quiet", "true"}};
    const double error =
      pneuma_test::make(settings)->check_tangent(1., 0.02, 1e-7).first;
    const bool pass = error < 1e-6;
    if (pneuma_test::root())
      std::printf("tangent vs finite differences, plane, sphere and cylinder, "
                  "degree %u: %s\n",
                  degree,
                  pass ? "relative error < 1e-6" : "FAIL");
    if (!pass && pneuma_test::root())
      std::printf("  relative error %.3e\n", error);
    return pass;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  for (const unsigned int degree : {1u, 2u})
    ok = tangent_check(degree) && ok;

  // The plane-strain tube: the ends held in x, the rigid motions left in
  // the cross-section held at points on its symmetry planes.
  const double R = 0.2, L = 0.4, t = 1e-3, E = 1e8, nu = 0.3, p = 1e4;
  const double D = 0.31; // the plates' final distance
  const auto   s = pneuma_test::run(
    {{"Geometry/Type", "open cylinder"},
       {"Geometry/open cylinder/Radius", pneuma_test::number(R)},
       {"Geometry/open cylinder/Length", pneuma_test::number(L)},
       {"Geometry/Global refinements", "3"},
       {"Discretisation/Polynomial degree", "2"},
       {"Materials/Region 0/Thickness", pneuma_test::number(t)},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
        pneuma_test::number(E)},
       {"Boundary conditions/Fixed boundaries", "0: x; 1: x"},
       {"Boundary conditions/Fixed points",
        "0, 0.2, 0: z; 0, -0.2, 0: z; 0, 0, 0.2: y; 0.4, 0.2, 0: z; "
          "0.4, -0.2, 0: z; 0.4, 0, 0.2: y"},
       {"Loads/Pressure/Function expression",
        pneuma_test::number(p) + "*min(t, 1)"},
       {"Obstacles/Number of obstacles", "2"},
       {"Obstacles/Obstacle 1/plane/Point", "0, 0, 0.205"},
       {"Obstacles/Obstacle 1/plane/Normal", "0, 0, -1"},
       {"Obstacles/Obstacle 1/Displacement/Function expression",
        "0; 0; -0.05*max(t - 1, 0)"},
       {"Obstacles/Obstacle 2/plane/Point", "0, 0, -0.205"},
       {"Obstacles/Obstacle 2/plane/Normal", "0, 0, 1"},
       {"Obstacles/Obstacle 2/Displacement/Function expression",
        "0; 0; 0.05*max(t - 1, 0)"},
       {"Load stepping/Stage end times", "1, 2"},
       {"Load stepping/Initial increment", "0.1"},
       {"Load stepping/Maximum increment", "0.1"},
       {"Newton/Residual tolerance", "1e-12"},
       {"Load stepping/Extrapolation", "none"}});
  if (s.exit_code != 0 || !s.summary.has("obstacle1_contact_area"))
    {
      if (pneuma_test::root())
        std::printf("run failed (exit %d): %s\nFAILED\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }
  // The reference: the free arcs are half circles of the mid-surface's
  // height H = D - t between the plates, so the hoop force is T = p H / 2
  // = lambda S t with S = E/(1 - nu^2) (lambda^2 - 1)/2 (plane strain);
  // the flat width on each plate is b = (2 pi R lambda - pi H)/2.
  const double H = D - t, T = p * H / 2.;
  double       lambda = 1.;
  for (unsigned int k = 0; k < 50; ++k)
    {
      const double c = E * t / (1. - nu * nu);
      const double f = c * lambda * (lambda * lambda - 1.) / 2. - T;
      lambda -= f / (c * (3. * lambda * lambda - 1.) / 2.);
    }
  const double b  = (2. * M_PI * R * lambda - M_PI * H) / 2.;
  const auto   f1 = s.summary.get_vector("obstacle1_force");
  const auto   f2 = s.summary.get_vector("obstacle2_force");
  const double a1 = s.get("obstacle1_contact_area");
  ok &= pneuma_test::check("plate force = p b L (plane strain, closed form)",
                           f1[2],
                           p * b * L,
                           2e-3);
  ok &= pneuma_test::check(
    "contact area of the points in contact = b L", a1, b * L, 0.06, 2);
  ok &= pneuma_test::check(
    "plate force = p x contact area of the points", f1[2], p * a1, 0.06, 2);
  ok &=
    pneuma_test::check("plates' forces: -F_2 = F_1 (z)", -f2[2], f1[2], 1e-8);
  // The penetration on the flat part is p J / eps (the nominal pressure
  // p J on the penalty, uniform on this mesh); the pressure peaks near the
  // edges of the contact.
  const double eps = s.get("obstacle1_penalty_min");
  ok &= pneuma_test::check("penalty uniform on this mesh: largest / smallest",
                           s.get("obstacle1_penalty_max") / eps,
                           1.,
                           1e-12);
  ok &= pneuma_test::check("largest penetration / (p J / penalty), in [1, 1.3]",
                           s.get("obstacle1_penetration") / (p * lambda / eps),
                           1.15,
                           0.13,
                           2);
  const auto reaction = s.summary.get_vector("reaction");
  const auto applied  = s.summary.get_vector("applied_load");
  // Reactions + applied loads = 0, relative to the plates' force.
  double imbalance = 0.;
  for (unsigned int d = 0; d < 3; ++d)
    imbalance = std::max(imbalance, std::abs(reaction[d] + applied[d]));
  imbalance /= std::abs(f1[2]);
  if (pneuma_test::root())
    std::printf("equilibrium: |reaction + applied loads| / plate force %s\n",
                imbalance < 1e-8 ? "< 1e-8" : "FAIL");
  ok &= imbalance < 1e-8;
  // Newton's rate in the last step.
  const auto &r     = s.last_residual_history;
  double      order = 0.;
  for (unsigned int k = 1; k + 1 < r.size(); ++k)
    if (r[k + 1] / r[0] > 1e-12 && r[k] / r[0] < 1e-1)
      order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
  // Superlinear, not quadratic: where the free arc leaves the plate
  // tangentially, points at g ~ 0 switch in and out of contact in the last
  // iterations, and the penalty's stiffness jumps there (1.5 here).
  if (pneuma_test::root())
    std::printf("Newton's rate in the last step: %s\n",
                order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
  ok &= order > 1.4;
  if (pneuma_test::root())
    {
      std::printf("Newton iterations per step:");
      for (const auto n : s.step_iterations)
        std::printf(" %u", n);
      std::printf("\n%s\n", ok ? "OK" : "FAILED");
    }
  return ok ? 0 : 1;
}
