// A beam tied along a membrane line, in bending (doc/verification.md
// "Beam tied along a membrane line"): a flat membrane strip (L = 2 m,
// W = 0.2 m, E = 1e9 Pa, t = 1 mm, nu = 0, Q2, held in its plane) clamped
// at x = -1 m, with a solid beam (E_b = 1e10 Pa, circular, r = 10 mm) tied
// at all its 65 nodes along the edge y = +W/2, and a tip force F = 1 N
// along -y spread over the free edge x = +1 m. The membrane is the web and
// the beam the flange of a composite cantilever. Its tip deflection is
// Timoshenko's v = F L^3 / (3 EI) + v_s for the section transformed to the
// web's E:
//   centroid y_c = EA_b (W/2) / (EA_w + EA_b),
//   EI = E t W^3/12 + EA_w y_c^2 + EA_b (W/2 - y_c)^2 + E_b pi r^4/4,
//   v_s = (L / (G F)) int tau^2 t dy over the web, tau(y) = F Q_E(y)/(EI t)
//   (Q_E: the E-weighted first moment of the section above y, flange
//   included).
// The tip deflection at the web's middle is compared within 1e-3 (the
// clamp restrains the section's warping locally), the support reaction
// with F to 1e-8; 1 and 2 ranks print the same.

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double E = 1e9, t = 1e-3, W = 0.2, E_b = 1e10, r = 0.01, L = 2., F = 1.;
  const auto   s = pneuma_test::run(
    {{"Geometry/Type", "rectangle"},
       {"Geometry/rectangle/Length", "2"},
       {"Geometry/rectangle/Width", "0.2"},
       {"Geometry/Global refinements", "4"},
       {"Discretisation/Polynomial degree", "2"},
       {"Materials/Region 0/Thickness", "1e-3"},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0"},
       {"Loads/Line load boundaries", "1"},
       {"Loads/Line load/Function expression", "0; -5*t; 0"},
       {"Boundary conditions/Fixed boundaries", "0: xy"},
       {"Boundary conditions/Fixed regions", "0: z"},
       {"Cables/Number of cables", "1"},
       {"Cables/Cable 1/Element", "solid beam"},
       {"Cables/Cable 1/solid beam/Section axis", "0, 0, 1"},
       {"Cables/Cable 1/solid beam/Poisson's ratio", "0"},
       {"Cables/Cable 1/polyline/Points", "-1, 0.1, 0; 1, 0.1, 0"},
       {"Cables/Cable 1/Number of elements", "64"},
       {"Cables/Cable 1/Section semi-axes", "0.01"},
       {"Cables/Cable 1/Young's modulus", "1e10"},
       {"Ties/Number of ties", "1"},
       {"Ties/Tie 1/Cable", "1"},
       {"Ties/Tie 1/Nodes", "all"},
       {"Load stepping/Initial increment", "1"},
       {"Output/Monitor points", "1, 0, 0"}});
  if (s.exit_code != 0)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::printf("run failed (exit %d): %s\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }
  // The composite section, transformed to the web's E.
  const double A_b = M_PI * r * r, EA_w = E * t * W, EA_b = E_b * A_b;
  const double y_c = EA_b * (W / 2.) / (EA_w + EA_b);
  const double EI  = E * t * W * W * W / 12. + EA_w * y_c * y_c
                    + EA_b * (W / 2. - y_c) * (W / 2. - y_c)
                    + E_b * M_PI * r * r * r * r / 4.;
  const double bending = F * L * L * L / (3. * EI);
  // Shear: the web's energy int tau^2 t dy per unit length, v_s = L/(G F)
  // times it.
  const double G      = E / 2.;
  double       energy = 0.;
  const int    n      = 20000;
  for (int i = 0; i < n; ++i)
    {
      const double y   = -W / 2. + (i + 0.5) * W / n;
      const double Q_E = E * t * (W * W / 4. - y * y) / 2.
                         - E * t * y_c * (W / 2. - y) + EA_b * (W / 2. - y_c);
      const double tau = F * Q_E / (EI * t);
      energy += tau * tau * t * W / n;
    }
  const double shear = L * energy / (G * F);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("composite EI = %.2f N m^2 (web alone %.2f), bending %.4e "
                "m, shear %.4e m\n",
                EI,
                E * t * W * W * W / 12.,
                bending,
                shear);
  bool ok = pneuma_test::check("tip deflection [m]",
                               -s.summary.get_vector("m0_u")[1],
                               bending + shear,
                               1e-3);
  ok      = pneuma_test::check("support reaction along y [N]",
                          s.summary.get_vector("reaction")[1],
                          F,
                          1e-8)
       && ok;
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
