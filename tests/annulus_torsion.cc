// An annular membrane under hub torsion (doc/verification.md "Annulus
// under torsion"; Mikulas 1964, Miller & Hedgepeth 1982): a flat annulus
// a = 0.1 m <= r <= b = 0.5 m (H = 1 mm, E = 1 GPa, nu = 0.3) with a
// uniform prestress n0 = 10 N/m, the outer edge fixed and the inner edge
// turned as a rigid hub by theta. Wrinkling starts at the hub at the torque
// 2 pi n0 a^2; beyond it a wrinkled zone a <= r <= r_w carries uniaxial
// tension along straight rays at sin(phi) = c / r to the radius. The
// small-strain tension-field solution (scripts/annulus_torsion.py) gives,
// for the hub rotations of torques k = 3 and k = 6 times the onset torque:
// the torque (reaction moment of the hub, boundary 0), the border r_w of
// the wrinkled zone (where the plain law's minor force at the probes
// along the x axis crosses zero, interpolated; and, coarser, from the
// wrinkled area), and the wrinkles' tension angle and force N1 at probes
// inside the zone. Below the onset (k = 1/2) the sheet stays taut and
// the torque is the linear 4 pi G H theta / (1/a^2 - 1/b^2).
// The strains are about 1e-4, so the finite-strain model is within 1e-3
// of the small-strain reference.

#include "test_tools.h"

#include <cmath>
#include <string>
#include <vector>

namespace
{
  const double a = 0.1, b = 0.5, n0 = 10., E = 1e9, nu = 0.3, H = 1e-3;

  /// The reference for one load (scripts/annulus_torsion.py).
  struct Case
  {
    double k;     // torque / onset torque 2 pi n0 a^2
    double theta; // hub rotation [rad], clockwise
    double c;     // radius of the rays' circle [m]
    double r_w;   // border of the wrinkled zone [m]
    double r_low; // first of the probes that bracket r_w
  };

  pneuma_test::Settings
  annulus(const double theta, const std::string &probes)
  {
    return {{"Geometry/Type", "annulus"},
            {"Geometry/annulus/Inner radius", pneuma_test::number(a)},
            {"Geometry/annulus/Outer radius", pneuma_test::number(b)},
            {"Geometry/annulus/Cells around", "16"},
            {"Geometry/Global refinements", "3"},
            {"Discretisation/Polynomial degree", "2"},
            {"Materials/Region 0/Thickness", pneuma_test::number(H)},
            {"Materials/Region 0/Prestress", pneuma_test::number(n0)},
            {"Materials/Region 0/Wrinkling", "tension field"},
            {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
             pneuma_test::number(E)},
            {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio",
             pneuma_test::number(nu)},
            {"Boundary conditions/Fixed boundaries", "1: xyz"},
            {"Boundary conditions/Prescribed displacement boundaries", "0"},
            {"Boundary conditions/Prescribed displacement/Function constants",
             "w=" + pneuma_test::number(theta)},
            // The hub turned clockwise by w t, exactly (finite rotation).
            {"Boundary conditions/Prescribed displacement/Function expression",
             "x*(cos(w*t)-1)+y*sin(w*t); -x*sin(w*t)+y*(cos(w*t)-1); 0"},
            {"Load stepping/Stage end times", "1"},
            {"Load stepping/Initial increment", "0.25"},
            {"Output/Probe points", probes}};
  }

  std::string
  probes_on_x(const std::vector<double> &radii)
  {
    std::string s;
    for (const double r : radii)
      s += (s.empty() ? "" : "; ") + pneuma_test::number(r) + ", 0, 0";
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  bool ok = true;

  // Below the onset: taut, the linear torque.
  {
    const double k     = 0.5;
    const double G     = E / (2. * (1. + nu));
    const double K     = k * n0 * a * a;
    const double theta = K / (2. * G * H) * (1. / (a * a) - 1. / (b * b));
    const auto   s     = pneuma_test::run(annulus(theta, probes_on_x({0.2})));
    ok =
      pneuma_test::check("k = 0.5 (taut): hub torque vs 4 pi G H theta / "
                         "(1/a^2 - 1/b^2)",
                         -s.summary.get_vector("boundary_0_reaction_moment")[2],
                         2. * M_PI * K,
                         1e-3)
      && ok;
    const bool taut = s.get("wrinkled_area") == 0. && s.get("slack_area") == 0.;
    if (root)
      std::printf("k = 0.5: wrinkled and slack area %s 0 %s\n",
                  taut ? "=" : "!=",
                  taut ? "PASS" : "FAIL");
    ok = ok && taut;
  }

  // Partly wrinkled.
  const std::vector<Case> cases = {
    {3., 5.87087510381422e-5, 0.0880418382597, 0.174996246514, 0.15},
    {6., 1.44566796153227e-4, 0.0898852925537, 0.243724601226, 0.22}};
  for (const auto &c : cases)
    {
      const std::string k = "k = " + std::to_string(int(c.k)) + ": ";
      // Probes inside the zone at 0.12, 0.15 (and 0.2), then every 5 mm
      // across r_w.
      std::vector<double> inside = {0.12, 0.15}, radii;
      if (c.r_w > 0.2)
        inside.push_back(0.2);
      radii = inside;
      for (unsigned int i = 0; i <= 10; ++i)
        radii.push_back(c.r_low + 0.005 * i);
      const auto   s = pneuma_test::run(annulus(c.theta, probes_on_x(radii)));
      const double K = c.k * n0 * a * a;
      ok             = pneuma_test::check(k + "hub torque [N m]",
                              -s.summary.get_vector(
                                "boundary_0_reaction_moment")[2],
                              2. * M_PI * K,
                              2e-3)
           && ok;

      // r_w: the plain minor force's zero crossing along the probes.
      double r_w = 0.;
      for (unsigned int i = inside.size(); i + 1 < radii.size(); ++i)
        {
          const std::string p0 = "p" + std::to_string(i) + "_",
                            p1 = "p" + std::to_string(i + 1) + "_";
          const double f0      = s.get(p0 + "plain_minor_force"),
                       f1      = s.get(p1 + "plain_minor_force");
          if (f0 < 0. && f1 >= 0. && r_w == 0.)
            r_w = radii[i] - f0 * (radii[i + 1] - radii[i]) / (f1 - f0);
        }
      ok = pneuma_test::check(k + "border r_w of the wrinkled zone [m]",
                              r_w,
                              c.r_w,
                              1e-2)
           && ok;
      // The wrinkled area's radius: within half a radial cell (the
      // quadrature points are counted, a cell ring is 10 % of r thick).
      ok = pneuma_test::check(k + "r_w from the wrinkled area [m]",
                              std::sqrt(s.get("wrinkled_area") / M_PI + a * a),
                              c.r_w,
                              0.05)
           && ok;

      for (unsigned int i = 0; i < inside.size(); ++i)
        {
          const std::string p = "p" + std::to_string(i) + "_";
          const double      r = inside[i];
          const auto        d = s.summary.get_vector(p + "wrinkle_direction");
          const bool        wrinkled = s.get(p + "wrinkling_state") == 1.;
          if (root)
            std::printf("%sr = %.2f wrinkled: %s\n",
                        k.c_str(),
                        r,
                        wrinkled ? "PASS" : "FAIL");
          ok = ok && wrinkled;
          // The ray's angle to the radius (the x axis here).
          ok = pneuma_test::check(k + "tension angle to the radius at r = "
                                    + std::to_string(r).substr(0, 4)
                                    + " [deg], asin(c/r)",
                                  std::atan2(std::abs(d[1]), std::abs(d[0]))
                                    * 180. / M_PI,
                                  std::asin(c.c / r) * 180. / M_PI,
                                  5e-3)
               && ok;
          ok = pneuma_test::check(k + "tension N1 at r = "
                                    + std::to_string(r).substr(0, 4)
                                    + " [N/m], K/(c sqrt(r^2-c^2))",
                                  s.get(p + "N1"),
                                  K / (c.c * std::sqrt(r * r - c.c * c.c)),
                                  5e-3)
               && ok;
        }
    }

  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
