// Rigid obstacles given as Gmsh surface meshes (issue "Membranes that
// touch": "rigid bodies given as a Gmsh surface"), Obstacles/Obstacle
// k/Shape = gmsh.
// 0. The shape itself: (a) around the wedge's ridge (meshes/
//    obstacle_wedge.msh: faces, edges and vertices nearest), the gradient
//    of the signed distance against central differences of phi and its
//    Hessian against differences of the gradient at 400 random points
//    (seeded), and phi's sign (the membrane below the ridge is outside);
//    (b) a faceted sphere (meshes/obstacle_sphere.msh, R = 0.3 m, closed,
//    normals turned out): |phi - (|x| - R)| stays below the largest
//    sagitta h^2 / (8 R) + the vertices' distance from the sphere, and the
//    sign agrees wherever |phi| exceeds that, at 2000 random points in
//    the ball of radius 2R; Side = inside flips phi.
// 1. The tangent against central finite differences of the residual: the
//    square membrane of tests/obstacle_contact at a smooth random state,
//    pressed from above by a wedge whose sharp lower ridge is split into
//    four segments (meshes/obstacle_wedge.msh: the ridge's edges and
//    vertices, the faces beside them) and from below by a faceted sphere
//    (meshes/obstacle_sphere.msh, 4 cm triangles, moved by its
//    Displacement near where tests/obstacle_contact has its sphere), on
//    degree 1 and 2; the obstacles must act (they change |K d| by more
//    than 1 %).
// 2. The tube of tests/obstacle_contact squeezed between two slabs
//    (meshes/obstacle_slab.msh, closed boxes of 0.1 m, membrane outside)
//    instead of two planes: where the membrane touches, the nearest
//    feature is a slab's face, so every force, area, penetration and
//    iteration must equal the planes' run to round-off.
// 3. A tube (R = 0.2 m, Q1, 32 cells around, plane strain: ends held in
//    x, E t = 1e5 N/m, nu = 0.3) inflated to 10 kPa inside a rigid
//    32-sided prism (meshes/obstacle_pipe.msh, closed, membrane inside,
//    inscribed radius r_i = 0.2025 m, its corners at the tube's nodes'
//    angles). The Q1 tube is a polygon whose sides lie flat on the faces
//    at a = r_i - t/2 + e (e the penetration): hoop stretch
//    lambda = a / (R cos(pi/32)), hoop force T = lambda S t (SVK, plane
//    strain), contact pressure q = p - T / a, e = q lambda / penalty, all
//    exact on this mesh (solved in the test). Checks T (from the ends'
//    axial reaction nu T / lambda x 2 N R sin(pi/N)), e, the contact area
//    (every point touches) and the obstacle's vanishing resultant; a
//    smooth pipe of the same inscribed radius would give a T 33 % lower
//    (the strain is small), so the faces are what the membrane touches.
// The same on 2 ranks.

#include "test_tools.h"

#include <pneuma/contact/obstacles/obstacle_shape.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace
{

  std::string
  mesh(const std::string &name)
  {
    return std::string(PNEUMA_SOURCE_DIR) + "/meshes/" + name + ".msh";
  }

  std::unique_ptr<pneuma::contact::ObstacleShape>
  shape(const std::string &file, const std::string &side)
  {
    using Registry = pneuma::contact::ObstacleShapeRegistry;
    dealii::ParameterHandler prm;
    auto                     all = Registry::instance().declare_all(prm);
    prm.enter_subsection("gmsh");
    prm.set("Mesh file", mesh(file));
    prm.set("Side", side);
    prm.leave_subsection();
    return Registry::instance().take(all, prm, "gmsh", "Shape", "test");
  }

  /// Gradient and Hessian of phi against central differences around the
  /// wedge's ridge.
  bool
  ridge_derivatives()
  {
    const auto   wedge = shape("obstacle_wedge", "outside");
    std::mt19937 random(7);
    std::uniform_real_distribution<double> x(0.03, 0.17), y(-0.55, 0.55),
      z(-0.06, 0.06);
    const double h              = 1e-6;
    double       gradient_error = 0., hessian_error = 0.;
    bool         outside = true;
    for (unsigned int k = 0; k < 400; ++k)
      {
        const dealii::Point<3> p(x(random), y(random), z(random));
        const auto             s = wedge->distance(p);
        // Inside the wedge: above its faces, which rise from the ridge
        // with the slope 0.395 / 0.4.
        const bool in = p[2] > 0.005 + 0.9875 * std::abs(p[0] - 0.1);
        outside &= (s.phi > 0.) != in || std::abs(s.phi) < 1e-12;
        for (unsigned int d = 0; d < 3; ++d)
          {
            dealii::Point<3> a = p, b = p;
            a[d] += h;
            b[d] -= h;
            const auto sa = wedge->distance(a), sb = wedge->distance(b);
            gradient_error =
              std::max(gradient_error,
                       std::abs((sa.phi - sb.phi) / (2. * h) - s.normal[d]));
            for (unsigned int e = 0; e < 3; ++e)
              hessian_error =
                std::max(hessian_error,
                         std::abs((sa.normal[e] - sb.normal[e]) / (2. * h)
                                  - s.hessian[d][e])
                           * std::max(std::abs(s.phi), 1e-3));
          }
      }
    // The Hessian is 1/r near the ridge: its error is taken times
    // max(|phi|, 1 mm) (relative to a curvature of 1/|phi|).
    const bool ok = gradient_error < 1e-8 && hessian_error < 1e-7 && outside;
    if (pneuma_test::root())
      std::printf("wedge: gradient of phi vs differences %s, Hessian %s, "
                  "its sign (inside the wedge or not) %s\n",
                  gradient_error < 1e-8 ? "< 1e-8" : "FAIL",
                  hessian_error < 1e-7 ? "< 1e-7 (x max(|phi|, 1 mm))" : "FAIL",
                  outside ? "right" : "FAIL");
    if (!ok && pneuma_test::root())
      std::printf("  errors %.3e %.3e\n", gradient_error, hessian_error);
    return ok;
  }

  /// The faceted sphere against the sphere.
  bool
  faceted_sphere()
  {
    const double R       = 0.3;
    const auto   outside = shape("obstacle_sphere", "outside");
    const auto   inside  = shape("obstacle_sphere", "inside");
    // The largest sagitta: the mesh's longest edge (MeshSizeMax 4 cm, with
    // Gmsh's tolerance) and the vertices' own distance from the sphere.
    const double bound = 0.06 * 0.06 / (8. * R) + 1e-6;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-2. * R, 2. * R);
    double                                 error = 0.;
    bool                                   signs = true, flipped = true;
    for (unsigned int k = 0; k < 2000; ++k)
      {
        const dealii::Point<3> p(u(random), u(random), u(random));
        if (p.norm() > 2. * R)
          continue;
        const double exact = p.norm() - R;
        const auto   s     = outside->distance(p);
        error              = std::max(error, std::abs(s.phi - exact));
        if (std::abs(exact) > bound)
          signs &= (s.phi > 0.) == (exact > 0.);
        flipped &= inside->distance(p).phi == -s.phi;
      }
    const bool ok = error < bound && signs && flipped;
    if (pneuma_test::root())
      std::printf("faceted sphere: |phi - (|x| - R)| %s the sagitta bound "
                  "%.1e m, signs %s, Side = inside flips phi %s\n",
                  error < bound ? "<" : "FAIL: >",
                  bound,
                  signs ? "agree" : "FAIL",
                  flipped ? "yes" : "FAIL");
    return ok;
  }

  bool
  tangent_check(const unsigned int degree)
  {
    pneuma_test::Settings settings = {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "3"},
      {"Discretisation/Polynomial degree", std::to_string(degree)},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e8"},
      {"Output/Quiet", "true"}};
    const auto bare =
      pneuma_test::make(settings)->check_tangent(1., 0.02, 1e-7);
    settings.insert(
      settings.end(),
      {{"Obstacles/Number of obstacles", "2"},
       {"Obstacles/Obstacle 1/Shape", "gmsh"},
       {"Obstacles/Obstacle 1/gmsh/Mesh file", mesh("obstacle_wedge")},
       {"Obstacles/Obstacle 2/Shape", "gmsh"},
       {"Obstacles/Obstacle 2/gmsh/Mesh file", mesh("obstacle_sphere")},
       {"Obstacles/Obstacle 2/Displacement/Function expression",
        "0.2; 0.1; -0.27"}});
    const auto check =
      pneuma_test::make(settings)->check_tangent(1., 0.02, 1e-7);
    const double error  = check.first;
    const bool   active = std::abs(check.second / bare.second - 1.) > 0.01;
    const bool   pass   = error < 1e-6 && active;
    if (pneuma_test::root())
      std::printf("tangent vs finite differences, wedge and faceted sphere, "
                  "degree %u: %s%s\n",
                  degree,
                  error < 1e-6 ? "relative error < 1e-6" : "FAIL",
                  active ? ", |K d| changed by > 1 %"
                         : ", FAIL: obstacles not active");
    if (!pass && pneuma_test::root())
      std::printf("  relative error %.3e, |K d| %.3e against %.3e\n",
                  error,
                  check.second,
                  bare.second);
    return pass;
  }

  /// The plane-strain tube of tests/obstacle_contact between two plates
  /// (@p slabs: the meshed slabs instead of planes).
  pneuma::RunResult
  tube_between(const bool slabs)
  {
    pneuma_test::Settings settings = {
      {"Geometry/Type", "open cylinder"},
      {"Geometry/open cylinder/Radius", "0.2"},
      {"Geometry/open cylinder/Length", "0.4"},
      {"Geometry/Global refinements", "3"},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e8"},
      {"Boundary conditions/Fixed boundaries", "0: x; 1: x"},
      {"Boundary conditions/Fixed points",
       "0, 0.2, 0: z; 0, -0.2, 0: z; 0, 0, 0.2: y; 0.4, 0.2, 0: z; "
       "0.4, -0.2, 0: z; 0.4, 0, 0.2: y"},
      {"Loads/Pressure/Function expression", "1e4*min(t, 1)"},
      {"Obstacles/Number of obstacles", "2"},
      {"Load stepping/Stage end times", "1, 2"},
      {"Load stepping/Initial increment", "0.2"},
      {"Load stepping/Maximum increment", "0.2"},
      {"Newton/Residual tolerance", "1e-12"},
      {"Load stepping/Extrapolation", "none"}};
    if (slabs)
      settings.insert(
        settings.end(),
        {{"Obstacles/Obstacle 1/Shape", "gmsh"},
         {"Obstacles/Obstacle 1/gmsh/Mesh file", mesh("obstacle_slab")},
         {"Obstacles/Obstacle 1/Displacement/Function expression",
          "0; 0; 0.205 - 0.05*max(t - 1, 0)"},
         {"Obstacles/Obstacle 2/Shape", "gmsh"},
         {"Obstacles/Obstacle 2/gmsh/Mesh file", mesh("obstacle_slab")},
         {"Obstacles/Obstacle 2/Displacement/Function expression",
          "0; 0; -0.305 + 0.05*max(t - 1, 0)"}});
    else
      settings.insert(settings.end(),
                      {{"Obstacles/Obstacle 1/plane/Point", "0, 0, 0.205"},
                       {"Obstacles/Obstacle 1/plane/Normal", "0, 0, -1"},
                       {"Obstacles/Obstacle 1/Displacement/Function expression",
                        "0; 0; -0.05*max(t - 1, 0)"},
                       {"Obstacles/Obstacle 2/plane/Point", "0, 0, -0.205"},
                       {"Obstacles/Obstacle 2/plane/Normal", "0, 0, 1"},
                       {"Obstacles/Obstacle 2/Displacement/Function expression",
                        "0; 0; 0.05*max(t - 1, 0)"}});
    return pneuma_test::run(settings);
  }


  bool
  slabs_equal_planes()
  {
    const auto planes = tube_between(false);
    const auto slabs  = tube_between(true);
    if (pneuma_test::failed(planes, "planes")
        || pneuma_test::failed(slabs, "slabs"))
      return false;
    bool ok = true;
    for (const std::string k : {"1", "2"})
      ok &= pneuma_test::check(
        "slab " + k + "'s force = plane " + k + "'s (z)",
        slabs.summary.get_vector("obstacle" + k + "_force")[2],
        planes.summary.get_vector("obstacle" + k + "_force")[2],
        1e-10);
    for (const std::string q : {"contact_area", "penetration"})
      ok &= pneuma_test::check("slab 1's " + q + " = plane 1's",
                               slabs.get("obstacle1_" + q),
                               planes.get("obstacle1_" + q),
                               1e-10);
    const bool same_path = slabs.step_iterations == planes.step_iterations;
    if (pneuma_test::root())
      std::printf("Newton iterations per step, slabs as planes: %s\n",
                  same_path ? "equal" : "FAIL: different");
    return ok && same_path;
  }

  bool
  tube_in_pipe()
  {
    const double R = 0.2, L = 0.4, t = 1e-3, E = 1e8, nu = 0.3, p = 1e4,
                 r_i     = 0.2025;
    const unsigned int N = 32;
    const auto         s = pneuma_test::run(
      {{"Geometry/Type", "open cylinder"},
               {"Geometry/open cylinder/Radius", pneuma_test::number(R)},
               {"Geometry/open cylinder/Length", pneuma_test::number(L)},
               {"Geometry/Global refinements", "3"},
               {"Discretisation/Polynomial degree", "1"},
               {"Materials/Region 0/Thickness", pneuma_test::number(t)},
               {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
                pneuma_test::number(E)},
               {"Boundary conditions/Fixed boundaries", "0: x; 1: x"},
               {"Boundary conditions/Fixed points",
                "0, 0.2, 0: z; 0, -0.2, 0: z; 0, 0, 0.2: y; 0.4, 0.2, 0: z; "
                        "0.4, -0.2, 0: z; 0.4, 0, 0.2: y"},
               {"Loads/Pressure/Function expression",
                pneuma_test::number(p) + "*min(t, 1)"},
               {"Obstacles/Number of obstacles", "1"},
               {"Obstacles/Obstacle 1/Shape", "gmsh"},
               {"Obstacles/Obstacle 1/gmsh/Mesh file", mesh("obstacle_pipe")},
               {"Obstacles/Obstacle 1/gmsh/Side", "inside"},
               {"Load stepping/Initial increment", "0.1"},
               {"Load stepping/Maximum increment", "0.1"},
               {"Newton/Residual tolerance", "1e-12"}});
    if (pneuma_test::failed(s, "tube in the pipe"))
      return false;
    // The exact polygon: a fixed point for the sides' distance a.
    const double eps = s.get("obstacle1_penalty_min");
    const double c = E * t / (1. - nu * nu), cos_n = std::cos(M_PI / N);
    double       a = r_i - t / 2, lambda = 1., T = 0., q = 0., e = 0.;
    for (unsigned int k = 0; k < 100; ++k)
      {
        lambda = a / (R * cos_n);
        T      = c * lambda * (lambda * lambda - 1.) / 2.;
        q      = p - T / a;
        e      = q * lambda / eps;
        a      = r_i - t / 2 + e;
      }
    const double perimeter = 2. * N * R * std::sin(M_PI / N);
    const double reaction  = s.summary.get_vector("boundary_0_reaction")[0];
    bool         ok        = true;
    ok &= pneuma_test::check("hoop force from the ends' axial reaction "
                             "(exact polygon)",
                             std::abs(reaction) * lambda / (nu * perimeter),
                             T,
                             1e-6);
    ok &= pneuma_test::check("penetration = q lambda / penalty",
                             s.get("obstacle1_penetration"),
                             e,
                             1e-6);
    ok &= pneuma_test::check("contact area = lambda x the tube's area",
                             s.get("obstacle1_contact_area"),
                             lambda * perimeter * L,
                             1e-9);
    const auto   f     = s.summary.get_vector("obstacle1_force");
    const double total = q * lambda * perimeter * L; // the pressure's sum
    const double net   = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (pneuma_test::root())
      std::printf("pipe's resultant / the contact pressure's sum: %s\n",
                  net < 1e-9 * total ? "< 1e-9" : "FAIL");
    ok &= net < 1e-9 * total;
    const double smooth_lambda = (r_i - t / 2) / R;
    const double smooth_T =
      c * smooth_lambda * (smooth_lambda * smooth_lambda - 1.) / 2.;
    if (pneuma_test::root())
      std::printf("(a smooth pipe of the same inscribed radius: T %.1f N/m, "
                  "%.1f %% lower)\n",
                  smooth_T,
                  100. * (1. - smooth_T / T));
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = ridge_derivatives();
  ok                                          = faceted_sphere() && ok;
  for (const unsigned int degree : {1u, 2u})
    ok = tangent_check(degree) && ok;
  ok = slabs_equal_planes() && ok;
  ok = tube_in_pipe() && ok;
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
