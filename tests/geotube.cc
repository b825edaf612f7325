// A liquid-filled tube lying on the ground (a geotube; issue "Membranes
// that touch"). Plane strain: a 0.1 m slice of a tube of circumference
// L = 1 m with its ends held in x (meshes/geotube_slice.msh, Q2 on 128
// cells, E = 1 GPa, t = 1 mm, nu = 0.3), its chamber an open one whose
// vertical cuts are the slice's ends, filled with water (gamma = 9810
// N/m^3) and pressed by the head of a level above its top: the level
// falls from 10.33 m to h = 0.33 m, so the crown pressure p_top falls
// from about 10 gamma L to about 0.1 gamma L and the tube settles on the
// frictionless ground (a plane obstacle) from a nearly circular shape.
// The bottom line is held in z: the contact acts at Gauss points, so a
// tube that touches along a line of nodes is not held before it sinks in;
// the support's reaction (0.3 % of the floor force) is counted with the
// ground's.
//
// Reference (doc/theory.md §19, "A tube on the ground"): a weightless
// membrane of circumference L on a frictionless floor, liquid of unit
// weight gamma, crown pressure p_top at the height H: its tension T is
// constant, 2T = p_top H + gamma H^2/2 and (p_top + gamma H) b = gamma A
// (b the contact width, A the section), and in closed form, with
// P0 = p_top + gamma H and m = 4 gamma T/P0^2,
//   L = 2 P0 (K(m) - E(m))/gamma,   b = P0 ((2 - m) K(m) - 2 E(m))/gamma,
// A = P0 b/gamma. Under the head h (above the floor's wall), p_top =
// gamma (h - H); with the circumference stretched by the law (SVK in plane
// strain, T = E t/(1 - nu^2) lambda (lambda^2 - 1)/2), one equation for H.
// The solver is first checked against the values the issue gives for
// p_top/(gamma L) = 0.1 (H/L = 0.22935, b/L = 0.21771, T/(gamma L^2) =
// 0.024619, A/L^2 = 0.071703).
//
// Checks: H (the crown's height above the floor's wall), T (from the
// slice's axial end reaction: R_x = nu T L/lambda), A (the liquid volume
// over the slice), the floor's force against the liquid's weight (global
// equilibrium), the contact width from the floor's force, b = F/(p_top +
// gamma H) per length, the points in contact against b, the identity
// 2T = p_top H + gamma H^2/2 from the computed values, and Newton's rate
// in the last step. The same on 2 ranks.

#include "test_tools.h"

#include <cmath>
#include <cstdio>

namespace
{

  /// The plane geotube of circumference L under gamma.
  struct Geotube
  {
    double gamma, L, A_law; // A_law = E t/(1 - nu^2), 0: inextensible

    struct State
    {
      double H, b, T, A;
    };

    double
    stretch(const double T) const
    {
      if (A_law == 0.)
        return 1.;
      double l = 1.;
      for (unsigned int k = 0; k < 50; ++k)
        l -= (A_law * l * (l * l - 1.) / 2. - T)
             / (A_law * (3. * l * l - 1.) / 2.);
      return l;
    }

    /// The closed form at height H and crown pressure p_top; the
    /// circumference it needs is returned in @p needed.
    State
    at(const double H, const double p_top, double &needed) const
    {
      const double T  = p_top * H / 2. + gamma * H * H / 4.;
      const double P0 = p_top + gamma * H;
      const double m  = 4. * gamma * T / (P0 * P0);
      const double k  = std::sqrt(m);
      const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
      needed         = 2. * P0 * (K - E) / gamma;
      const double b = P0 * ((2. - m) * K - 2. * E) / gamma;
      return {H, b, T, P0 * b / gamma};
    }

    /// Bisection on H in (0, L/pi) for a crown pressure p_top(H).
    template <typename CrownPressure>
    State
    solve(const CrownPressure &p_top) const
    {
      double lo = 1e-9 * L, hi = L / M_PI;
      State  s{};
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double H = 0.5 * (lo + hi);
          double       needed;
          s = at(H, p_top(H), needed);
          // The circumference needed grows with H at a fixed load.
          (needed < L * stretch(s.T) ? lo : hi) = H;
        }
      return s;
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double L = 1., slice = 0.1, t = 1e-3, E = 1e9, nu = 0.3;
  const double gamma = 1000. * 9.81, level = 0.33;
  const double crown0 = 1. / M_PI + t / 2.; // the crown's reference height
  bool         ok     = true;

  // The solver against the values.
  {
    const Geotube g{1., 1., 0.};
    const auto    s = g.solve([](double) { return 0.1; });
    ok &= pneuma_test::check("reference solver: H/L at p_top = 0.1 gamma L",
                             s.H,
                             0.22935,
                             1e-4);
    ok &= pneuma_test::check("reference solver: b/L", s.b, 0.21771, 1e-4);
    ok &= pneuma_test::check("reference solver: T/(gamma L^2)",
                             s.T,
                             0.024619,
                             1e-4);
    ok &= pneuma_test::check("reference solver: A/L^2", s.A, 0.071703, 1e-4);
  }

  const auto at_x = [&](const double x, const double z) {
    return pneuma_test::number(x) + ", 0, " + pneuma_test::number(z);
  };
  pneuma_test::Settings settings = {
    {"Geometry/Type", "gmsh"},
    {"Geometry/gmsh/Mesh file",
     std::string(PNEUMA_SOURCE_DIR) + "/meshes/geotube_slice.msh"},
    {"Geometry/gmsh/Curved regions",
     "1: cylinder 0, 0, " + pneuma_test::number(L / (2. * M_PI) + t / 2.)
       + ", 1, 0, 0"},
    {"Geometry/Global refinements", "1"},
    {"Discretisation/Polynomial degree", "2"},
    {"Materials/Region 1/Thickness", pneuma_test::number(t)},
    {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus",
     pneuma_test::number(E)},
    {"Materials/Region 1/Saint Venant-Kirchhoff/Poisson's ratio",
     pneuma_test::number(nu)},
    {"Boundary conditions/Fixed boundaries", "0: x; 1: x"},
    // The lines on the symmetry plane y = 0 held in y, the bottom one
    // also in z.
    {"Boundary conditions/Fixed points",
     at_x(0., crown0) + ": y; " + at_x(slice, crown0) + ": y; "
       + at_x(0., t / 2.) + ": yz; " + at_x(slice / 2., t / 2.) + ": yz; "
       + at_x(slice, t / 2.) + ": yz"},
    {"Chambers/Number of chambers", "1"},
    {"Chambers/Chamber 1/Regions", "1"},
    {"Chambers/Chamber 1/Filling", "liquid"},
    {"Chambers/Chamber 1/Open", "true"},
    {"Chambers/Chamber 1/Liquid/Control", "level"},
    {"Chambers/Chamber 1/Liquid/Level/Function expression",
     pneuma_test::number(level) + " + 10*(1 - t)^2"},
    {"Obstacles/Number of obstacles", "1"},
    {"Obstacles/Obstacle 1/plane/Point", "0, 0, 0"},
    {"Obstacles/Obstacle 1/plane/Normal", "0, 0, 1"},
    {"Output/Monitor points", at_x(slice / 2., crown0)},
    {"Load stepping/Stage end times", "1"},
    {"Load stepping/Initial increment", "0.05"},
    {"Load stepping/Maximum increment", "0.1"},
    {"Newton/Residual tolerance", "1e-12"}};
  const auto s = pneuma_test::run(settings);
  if (s.exit_code != 0 || !s.summary.has("obstacle1_force"))
    {
      if (pneuma_test::root())
        std::printf("run failed (exit %d): %s\nFAILED\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }

  // The reference under the head h = level - t/2 above the floor's wall.
  const Geotube g{gamma, L, E * t / (1. - nu * nu)};
  const double  head  = level - t / 2.;
  const auto    ref   = g.solve([&](double H) { return gamma * (head - H); });
  const double  p_top = gamma * (head - ref.H);
  if (pneuma_test::root())
    std::printf("reference under the head %.4f m: H %.6e m, b %.6e m, "
                "T %.6e N/m, A %.6e m^2, p_top/(gamma L) %.5f\n",
                head,
                ref.H,
                ref.b,
                ref.T,
                ref.A,
                p_top / (gamma * L));

  const double H = crown0 + s.summary.get_vector("m0_u")[2] - t / 2.;
  ok &= pneuma_test::check("height H (crown above the floor's wall)",
                           H,
                           ref.H,
                           2e-3);
  const double Rx = s.summary.get_vector("boundary_0_reaction")[0];
  const double T  = std::abs(Rx) * g.stretch(ref.T) / (nu * L);
  ok &= pneuma_test::check("tension T (axial end reaction)", T, ref.T, 2e-3);
  const double A = s.get("c1_liquid_volume") / slice;
  ok &= pneuma_test::check("section A (liquid volume / slice)", A, ref.A, 2e-3);
  const double floor = s.summary.get_vector("reaction")[2]
                       - s.summary.get_vector("obstacle1_force")[2];
  ok &= pneuma_test::check("floor's force (ground + bottom line's support) "
                           "= the liquid's weight",
                           floor,
                           gamma * A * slice,
                           1e-6);
  const double p_top_fe = gamma * (head - H);
  const double b        = floor / slice / (p_top_fe + gamma * H);
  ok &= pneuma_test::check("contact width F/(p_top + gamma H)", b, ref.b, 5e-3);
  ok &= pneuma_test::check("contact area of the points in contact / slice",
                           s.get("obstacle1_contact_area") / slice,
                           ref.b,
                           0.15,
                           2);
  ok &= pneuma_test::check("2T = p_top H + gamma H^2/2 from the computed T, H",
                           2. * T,
                           p_top_fe * H + gamma * H * H / 2.,
                           2e-3);
  const double order = pneuma_test::last_step_order(s);
  if (pneuma_test::root())
    std::printf("Newton's rate in the last step: %s\n",
                order > 1.4 ? "superlinear (> 1.4)" : "FAIL");
  ok &= order > 1.4;
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
