// Two tubes at different pressures pressed together (issue "Membranes that
// touch": "two different pressures curve [the interface] towards the lower
// one"). Plane strain: two tubes of circumference L = 2 pi 0.2 m, a 0.4 m
// slice of each with its ends held in x (meshes/two_tubes_stacked.msh, Q2
// on 128 cells each, E = 1 GPa, t = 1 mm, nu = 0.3), stacked so that they
// touch; the lower tube is inflated to p1 = 10 kPa, the upper one to
// p2 = p1/4, then two rigid plates close in until D = L/2 is left between
// the walls' mid-surfaces (the plates' gap less two thicknesses). Nothing
// holds the tubes in z but the contacts.
//
// Reference (doc/theory.md §20, "Two different pressures"): with frictionless
// contact each wall's hoop force T_i is constant, so each free arc is a circle
// of radius R_i = T_i/p_i, each plate contact is flat (width c_i, p_i c_i = F,
// the plate force per length), and the interface, loaded by p1 on one wall, p2
// on the other and the contact pressure q between them, is a circular arc of
// curvature kappa = (p1 - p2)/(T1 + T2), bulging into the tube of lower
// pressure, with q = (T2 p1 + T1 p2)/(T1 + T2). The five unknowns T1, T2, c1,
// c2 and the interface's half length s follow from
//   c1 + 2 R1 (pi - b) + 2 s = L1,   c2 + 2 R2 (pi + b) + 2 s = L2,
//   c1/2 + R1 sin b = x_s,           c2/2 - R2 sin b = x_s,
//   (R1 + R2)(1 + cos b) = D,        b = kappa s, x_s = sin(b)/kappa,
// with the stretched circumferences L_i = L lambda(T_i) of the law (SVK in
// plane strain: T = E t/(1 - nu^2) lambda (lambda^2 - 1)/2), solved here by
// Newton. For equal pressures it is the stadium of tests/surface_contact.
//
// Checks: the hoop forces from each tube's axial end reaction (plane
// strain: N_x = nu S_tt t, so R_x = nu T_i L / lambda_i; the pointwise
// forces of a probe carry the Q2 gradients' error, which in a wall
// strained by 2e-3 is as large as the strain), the plate forces p1 c1 L_s,
// the force between the tubes, the interface's curvature through the ratio
// of the sum of the contact points' normal forces to their resultant
// (q s / (q x_s) = b / sin b for a circular arc: 1 for a flat interface),
// the interface's rise above mid-height (the lower tube's top point), and
// Newton's rate in the last step. The same on 2 ranks.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include "test_tools.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace
{

  /// The plane-strain reference: two inextensible-in-shape (but stretched)
  /// tubes between two plates at distance D.
  struct Reference
  {
    double L, p1, p2, D, A; // A = E t / (1 - nu^2)

    double
    stretch(const double T) const
    {
      double l = 1.;
      for (unsigned int k = 0; k < 50; ++k)
        l -= (A * l * (l * l - 1.) / 2. - T) / (A * (3. * l * l - 1.) / 2.);
      return l;
    }

    std::array<double, 5>
    residual(const std::array<double, 5> &v) const
    {
      const double T1 = v[0], T2 = v[1], c1 = v[2], c2 = v[3], s = v[4];
      const double R1 = T1 / p1, R2 = T2 / p2, kappa = (p1 - p2) / (T1 + T2);
      const double b  = kappa * s;
      const double xs = b == 0. ? s : std::sin(b) / kappa;
      return {{(c1 + 2. * R1 * (M_PI - b) + 2. * s) / (L * stretch(T1)) - 1.,
               (c2 + 2. * R2 * (M_PI + b) + 2. * s) / (L * stretch(T2)) - 1.,
               (c1 / 2. + R1 * std::sin(b) - xs) / L,
               (c2 / 2. - R2 * std::sin(b) - xs) / L,
               ((R1 + R2) * (1. + std::cos(b)) - D) / L}};
    }

    /// Newton with a finite-difference Jacobian from the stadium of the
    /// mean pressure.
    std::array<double, 5>
    solve() const
    {
      const double          R = D / 4., c = (L - 2. * M_PI * R) / 2.;
      std::array<double, 5> v{{p1 * R, p2 * R, c, c, c / 2.}};
      for (unsigned int it = 0; it < 100; ++it)
        {
          const auto r = residual(v);
          if (std::abs(r[0]) + std::abs(r[1]) + std::abs(r[2]) + std::abs(r[3])
                + std::abs(r[4])
              < 1e-14)
            break;
          dealii::FullMatrix<double> J(5, 5);
          for (unsigned int j = 0; j < 5; ++j)
            {
              auto         w = v;
              const double h = 1e-7 * std::abs(v[j]);
              w[j] += h;
              const auto rw = residual(w);
              for (unsigned int i = 0; i < 5; ++i)
                J(i, j) = (rw[i] - r[i]) / h;
            }
          J.gauss_jordan();
          dealii::Vector<double> rv(5), dv(5);
          for (unsigned int i = 0; i < 5; ++i)
            rv[i] = r[i];
          J.vmult(dv, rv);
          for (unsigned int i = 0; i < 5; ++i)
            v[i] -= dv[i];
        }
      return v;
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double L = 2. * M_PI * 0.2, slice = 0.4, t = 1e-3, E = 1e9, nu = 0.3;
  const double p1 = 1e4, p2 = p1 / 4., D = L / 2.;
  // The plates start on the tubes' outer faces (4 micrometres into them)
  // and stop at D + 2 t apart.
  const double          plate0 = 0.400996, travel = plate0 - (D / 2. + t);
  const std::string     move = pneuma_test::number(travel) + "*max(t - 1, 0)";
  pneuma_test::Settings settings = {
    {"Geometry/Type", "gmsh"},
    {"Geometry/gmsh/Mesh file",
     std::string(PNEUMA_SOURCE_DIR) + "/meshes/two_tubes_stacked.msh"},
    {"Geometry/gmsh/Curved regions",
     "1: cylinder 0, 0, 0.200498, 1, 0, 0; 2: cylinder 0, 0, -0.200498, 1, "
     "0, 0"},
    {"Geometry/Global refinements", "1"},
    {"Discretisation/Polynomial degree", "2"},
    {"Boundary conditions/Fixed boundaries", "0: x; 1: x; 2: x; 3: x"},
    // The tubes' lines on the symmetry plane y = 0 held in y.
    {"Boundary conditions/Fixed points",
     "0, 0, 0.400498: y; 0, 0, 0.000498: y; 0, 0, -0.000498: y; "
     "0, 0, -0.400498: y; 0.4, 0, 0.400498: y; 0.4, 0, 0.000498: y; "
     "0.4, 0, -0.000498: y; 0.4, 0, -0.400498: y"},
    // p2 in the upper tube (region 1), p1 in the lower one.
    {"Loads/Pressure/Function expression",
     pneuma_test::number(p1) + "*min(t, 1)*(z > 0 ? 0.25 : 1)"},
    {"Obstacles/Number of obstacles", "2"},
    {"Obstacles/Obstacle 1/plane/Point",
     "0, 0, " + pneuma_test::number(plate0)},
    {"Obstacles/Obstacle 1/plane/Normal", "0, 0, -1"},
    {"Obstacles/Obstacle 1/Displacement/Function expression", "0; 0; -" + move},
    {"Obstacles/Obstacle 2/plane/Point",
     "0, 0, -" + pneuma_test::number(plate0)},
    {"Obstacles/Obstacle 2/plane/Normal", "0, 0, 1"},
    {"Obstacles/Obstacle 2/Displacement/Function expression", "0; 0; " + move},
    {"Surface contact/Number of pairs", "1"},
    {"Surface contact/Pair 1/Regions", "1"},
    {"Surface contact/Pair 1/Opposite regions", "2"},
    {"Output/Monitor points", "0.2, 0, -0.000498; 0.2, 0, 0.000498"},
    {"Load stepping/Stage end times", "1, 2"},
    {"Load stepping/Initial increment", "0.1"},
    {"Load stepping/Maximum increment", "0.1"},
    {"Newton/Residual tolerance", "1e-12"}};
  for (const std::string r : {"1", "2"})
    {
      settings.push_back(
        {"Materials/Region " + r + "/Thickness", pneuma_test::number(t)});
      settings.push_back(
        {"Materials/Region " + r + "/Saint Venant-Kirchhoff/Young's modulus",
         pneuma_test::number(E)});
      settings.push_back(
        {"Materials/Region " + r + "/Saint Venant-Kirchhoff/Poisson's ratio",
         pneuma_test::number(nu)});
    }
  const auto s = pneuma_test::run(settings);
  if (s.exit_code != 0 || !s.summary.has("surface1_total_force"))
    {
      if (pneuma_test::root())
        std::printf("run failed (exit %d): %s\nFAILED\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }

  const Reference ref{L, p1, p2, D, E * t / (1. - nu * nu)};
  const auto      v  = ref.solve();
  const double    T1 = v[0], T2 = v[1], c1 = v[2], si = v[4];
  const double    kappa = (p1 - p2) / (T1 + T2), b = kappa * si;
  const double    R1 = T1 / p1;
  // The interface's top (x = 0) above the lower tube's flat wall.
  const double rise = R1 * (1. + std::cos(b)) + si * (1. - std::cos(b)) / b;
  if (pneuma_test::root())
    std::printf("reference: T1 %.5e N/m, T2 %.5e N/m, c1 %.5e m, c2 %.5e m, "
                "kappa %.5e 1/m, half angle %.5e, q %.5e Pa\n",
                T1,
                T2,
                c1,
                v[3],
                kappa,
                b,
                (T2 * p1 + T1 * p2) / (T1 + T2));

  bool ok = true;
  // Hoop forces from the axial end reactions (boundaries 2 and 3: the
  // lower tube, 0 and 1: the upper one).
  const auto hoop = [&](const unsigned int id, const double T) {
    const double Rx =
      s.summary.get_vector("boundary_" + std::to_string(id) + "_reaction")[0];
    return std::abs(Rx) * ref.stretch(T) / (nu * L);
  };
  ok &=
    pneuma_test::check("hoop force T1 (lower tube, p1)", hoop(2, T1), T1, 2e-3);
  ok &= pneuma_test::check("hoop force T2 (upper tube, p2 = p1/4)",
                           hoop(0, T2),
                           T2,
                           5e-3);
  const double F = p1 * c1 * slice;
  ok &= pneuma_test::check("upper plate's force = p1 c1 L_s",
                           s.summary.get_vector("obstacle1_force")[2],
                           F,
                           5e-3);
  ok &= pneuma_test::check("lower plate's force = p1 c1 L_s",
                           -s.summary.get_vector("obstacle2_force")[2],
                           F,
                           5e-3);
  // The force on the upper tube (region 1) from the lower one.
  const double resultant = s.summary.get_vector("surface1_force")[2];
  ok &= pneuma_test::check("force between the tubes = upper plate's force",
                           resultant,
                           s.summary.get_vector("obstacle1_force")[2],
                           2e-3);
  // A circular interface of half angle b: sum of the normal forces over
  // their resultant = b / sin b (0.98 % above 1 here).
  ok &= pneuma_test::check("curved interface: sum of normal forces / "
                           "resultant - 1 = b / sin b - 1",
                           s.get("surface1_total_force") / resultant - 1.,
                           b / std::sin(b) - 1.,
                           0.1);
  // The lower tube's top at x = 0: the interface's rise above the lower
  // plate's face less half a wall, against D/2 for equal pressures.
  const double top =
    -0.000498 + s.summary.get_vector("m0_u")[2] + D / 2. + t - t / 2.;
  ok &= pneuma_test::check("interface's rise above mid-height, towards the "
                           "upper (lower-pressure) tube",
                           top - D / 2.,
                           rise - D / 2.,
                           1e-2);
  // The walls at the interface's top stay a wall thickness apart.
  ok &= pneuma_test::check("wall distance at the interface's top / t",
                           (0.000996 + s.summary.get_vector("m1_u")[2]
                            - s.summary.get_vector("m0_u")[2])
                             / t,
                           1.,
                           1e-2);
  const double order = pneuma_test::last_step_order(s);
  if (pneuma_test::root())
    std::printf("Newton's rate in the last step: %s\n",
                order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
  ok &= order > 1.4;
  if (pneuma_test::root())
    {
      std::printf("steps %u, Newton iterations per step:",
                  static_cast<unsigned int>(s.step_iterations.size()));
      for (const auto n : s.step_iterations)
        std::printf(" %u", n);
      std::printf("\n");
    }
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
