// Membrane-to-membrane contact (issue "Membranes that touch").
// 1. The tangent against central finite differences of the residual: two
//    parallel unit squares 1.5 mm apart (meshes/two_sheets.msh, regions 1
//    and 2, t = 1 mm) at a random state near the reference, where most
//    points press on the other sheet, as a two-sided pair (1 against 2)
//    and as the self-contact of both (one side), on degree 1 and 2; the
//    contact terms must change |K d| by half at least (they are active).
// 2. Two tubes pressed together in plane strain (meshes/two_tubes.msh:
//    R = 0.2 m, a 0.4 m slice with its ends held in x, axes 43.1 cm
//    apart, Q2 on 128 cells each, E t = 1e4 N/m, nu = 0.3). Inflated to
//    10 kPa they grow into each other (the contact engages during the
//    inflation), then two plates press them together until each tube's
//    room is 2c = 43.1 cm, its centre held in z at c (a reaction that
//    vanishes by symmetry). Each tube is then a tube between two flat
//    walls: free arcs of diameter H = 2c - t, hoop force T = p H / 2, flat
//    width b = (2 pi R lambda - pi H)/2 (lambda the hoop stretch of T, SVK
//    in plane strain), and the force between the tubes is p b L, as on
//    the plates (tests/obstacle_contact). Checks that closed form for the
//    contact force between the tubes and on the plates, that the two are
//    equal (the resultant on the first tube), that the interface is flat
//    (the sum of the points' normal forces equals their resultant), the
//    contact area (first order at the contact's edge), the penetration
//    against p J / (2 penalty) (both sides' points press) and Newton's
//    rate in the last step; as a two-sided pair (tube 1 against tube 2)
//    and as the self-contact of both tubes as one side (every cell
//    against every other that shares no vertex with it). The same on 2
//    ranks.

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{

  bool
  tangent_check(const unsigned int degree, const bool self)
  {
    const std::string mesh =
      std::string(PNEUMA_SOURCE_DIR) + "/meshes/two_sheets.msh";
    pneuma_test::Settings settings = {
      {"Geometry/Type", "gmsh"},
      {"Geometry/gmsh/Mesh file", mesh},
      {"Geometry/Global refinements", "0"},
      {"Discretisation/Polynomial degree", std::to_string(degree)},
      {"Surface contact/Number of pairs", "1"},
      {"Surface contact/Pair 1/Regions", self ? "1, 2" : "1"},
      {"Surface contact/Pair 1/Opposite regions", self ? "" : "2"},
      {"Output/Quiet", "true"}};
    for (const std::string r : {"1", "2"})
      {
        settings.push_back({"Materials/Region " + r + "/Thickness", "1e-3"});
        settings.push_back(
          {"Materials/Region " + r + "/Saint Venant-Kirchhoff/Young's modulus",
           "1e8"});
      }
    const auto check =
      pneuma_test::make(settings)->check_tangent(1., 0.0001, 1e-7);
    // The same state without the pair: the contact terms must dominate
    // the tangent there (the sheets press on each other).
    settings.erase(settings.begin() + 4, settings.begin() + 7);
    const auto bare =
      pneuma_test::make(settings)->check_tangent(1., 0.0001, 1e-7);
    const double error  = check.first;
    const bool   active = check.second > 1.5 * bare.second;
    const bool   pass   = error < 1e-6 && active;
    if (pneuma_test::root())
      std::printf("tangent vs finite differences, %s, degree %u: %s%s\n",
                  self ? "self-contact" : "two sides",
                  degree,
                  error < 1e-6 ? "relative error < 1e-6" : "FAIL",
                  active ? ", |K d| > 1.5 x the membrane's alone"
                         : ", FAIL: contact not active");
    if (!pass && pneuma_test::root())
      std::printf("  relative error %.3e, |K d| %.3e, without contact %.3e\n",
                  error,
                  check.second,
                  bare.second);
    return pass;
  }
  /// The tubes pressed together, as a two-sided pair or as self-contact.
  bool
  tubes(const bool self)
  {
    const double R = 0.2, L = 0.4, t = 1e-3, E = 1e7, nu = 0.3, p = 1e4;
    const double c = 0.2155; // each tube's centre, the plates end at 2c
    pneuma_test::Settings settings = {
      {"Geometry/Type", "gmsh"},
      {"Geometry/gmsh/Mesh file",
       std::string(PNEUMA_SOURCE_DIR) + "/meshes/two_tubes.msh"},
      {"Geometry/gmsh/Curved regions",
       "1: cylinder 0, 0, 0.2155, 1, 0, 0; 2: cylinder 0, 0, -0.2155, 1, 0, "
       "0"},
      {"Geometry/Global refinements", "1"},
      {"Discretisation/Polynomial degree", "2"},
      {"Boundary conditions/Fixed boundaries", "0: x; 1: x"},
      // The tubes' top and bottom lines held in y, their sides in z at the
      // centres.
      {"Boundary conditions/Fixed points",
       "0, 0, 0.4155: y; 0, 0, 0.0155: y; 0, 0, -0.0155: y; "
       "0, 0, -0.4155: y; 0.4, 0, 0.4155: y; 0.4, 0, 0.0155: y; "
       "0.4, 0, -0.0155: y; 0.4, 0, -0.4155: y; 0, 0.2, 0.2155: z; "
       "0, -0.2, 0.2155: z; 0, 0.2, -0.2155: z; 0, -0.2, -0.2155: z; "
       "0.4, 0.2, 0.2155: z; 0.4, -0.2, 0.2155: z; 0.4, 0.2, -0.2155: z; "
       "0.4, -0.2, -0.2155: z"},
      {"Loads/Pressure/Function expression",
       pneuma_test::number(p) + "*min(t, 1)"},
      {"Obstacles/Number of obstacles", "2"},
      {"Obstacles/Obstacle 1/plane/Point", "0, 0, 0.47"},
      {"Obstacles/Obstacle 1/plane/Normal", "0, 0, -1"},
      {"Obstacles/Obstacle 1/Displacement/Function expression",
       "0; 0; -0.039*max(t - 1, 0)"},
      {"Obstacles/Obstacle 2/plane/Point", "0, 0, -0.47"},
      {"Obstacles/Obstacle 2/plane/Normal", "0, 0, 1"},
      {"Obstacles/Obstacle 2/Displacement/Function expression",
       "0; 0; 0.039*max(t - 1, 0)"},
      {"Surface contact/Number of pairs", "1"},
      {"Surface contact/Pair 1/Regions", self ? "1, 2" : "1"},
      {"Surface contact/Pair 1/Opposite regions", self ? "" : "2"},
      {"Load stepping/Stage end times", "1, 2"},
      {"Load stepping/Initial increment", "0.2"},
      {"Load stepping/Maximum increment", "0.2"},
      {"Newton/Residual tolerance", "1e-12"},
      {"Load stepping/Extrapolation", "none"}};
    for (const std::string r : {"1", "2"})
      {
        settings.push_back(
          {"Materials/Region " + r + "/Thickness", pneuma_test::number(t)});
        settings.push_back(
          {"Materials/Region " + r + "/Saint Venant-Kirchhoff/Young's modulus",
           pneuma_test::number(E)});
      }
    const auto s = pneuma_test::run(settings);
    if (pneuma_test::root())
      std::printf("%s:\n",
                  self ? "self-contact of both tubes"
                       : "two sides, tube 1 against tube 2");
    if (s.exit_code != 0 || !s.summary.has("surface1_total_force"))
      {
        if (pneuma_test::root())
          std::printf("run failed (exit %d): %s\n",
                      s.exit_code,
                      s.message.c_str());
        return false;
      }
    // Each tube between two flat walls (tests/obstacle_contact).
    const double H = 2. * c - t, T = p * H / 2.;
    double       lambda = 1.;
    for (unsigned int k = 0; k < 50; ++k)
      {
        const double a = E * t / (1. - nu * nu);
        const double f = a * lambda * (lambda * lambda - 1.) / 2. - T;
        lambda -= f / (a * (3. * lambda * lambda - 1.) / 2.);
      }
    const double b       = (2. * M_PI * R * lambda - M_PI * H) / 2.;
    const double plate   = s.summary.get_vector("obstacle1_force")[2];
    const double between = s.summary.get_vector("surface1_force")[2];
    const double total   = s.get("surface1_total_force");
    bool         ok      = true;
    ok &= pneuma_test::check("force between the tubes (sum of the points' "
                             "normal forces) = p b L (closed form)",
                             total,
                             p * b * L,
                             2e-3);
    // The penalty gaps (p J / penalty at the plate, half of it at the
    // interface, 1.3e-4 m in all on this mesh) shorten H: -1.6e-3 in b.
    ok &= pneuma_test::check("plate force = p b L (closed form)",
                             plate,
                             p * b * L,
                             3e-3);
    // Two sides: the resultant on tube 1 balances the plate's force, and
    // it equals the sum of the normal forces only if the interface is
    // flat. (Self-contact has one side: its resultant is zero.)
    if (!self)
      {
        ok &= pneuma_test::check("force on tube 1 from tube 2 = plate force",
                                 between,
                                 plate,
                                 3e-3);
        ok &=
          pneuma_test::check("flat interface: sum of normal forces = resultant",
                             total,
                             between,
                             1e-4);
      }
    ok &= pneuma_test::check(
      "contact area = b L", s.get("surface1_contact_area"), b * L, 0.15, 2);
    const double eps = s.get("surface1_penalty_min");
    // Both sides' points press (two passes): each takes half of p J.
    ok &=
      pneuma_test::check("largest penetration / (p J / 2 penalty), in [1, 1.3]",
                         s.get("surface1_penetration")
                           / (p * lambda / (2. * eps)),
                         1.15,
                         0.13,
                         2);
    const auto &r     = s.last_residual_history;
    double      order = 0.;
    for (unsigned int k = 1; k + 1 < r.size(); ++k)
      if (r[k + 1] / r[0] > 1e-12 && r[k] / r[0] < 1e-1)
        order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
    if (pneuma_test::root())
      {
        std::printf("Newton's rate in the last step: %s\n",
                    order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
        std::printf("Newton iterations per step:");
        for (const auto n : s.step_iterations)
          std::printf(" %u", n);
        std::printf("\n");
      }
    return ok && order > 1.4;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  for (const unsigned int degree : {1u, 2u})
    for (const bool self : {false, true})
      ok = tangent_check(degree, self) && ok;
  for (const bool self : {false, true})
    ok = tubes(self) && ok;
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
