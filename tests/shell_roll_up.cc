// Large rotations and the energy split of the Kirchhoff-Love shell
// (membrane/bending, doc/theory.md §21) on a strip of 1 m x 0.1 m, t = 1 cm,
// E = 1 GPa, nu = 0, clamped at x = -1/2, on 40 x 4 Q2 cells:
// - Roll-up: an edge moment m = 2 pi D/L per unit length at x = 1/2
//   (Bending/Edge moment, D = E t^3/12) bends the strip into a full circle
//   of circumference L, its tip back at the clamp. At m/4 and m/2 the
//   strip is a quarter and a half circle: the tip's displacement against
//   (2L/pi - L, 2L/pi) and (-L, 2L/pi); at m the tip's distance from the
//   clamp, the bending energy against M^2 L/(2 EI) = 2 pi^2 EI/L (M = m b,
//   EI = D b) and the membrane energy against the bending energy (the
//   exact circle is inextensional), and the clamp's reaction moment
//   against M. With the assumed membrane strains
//   (the default) 20 x 2, 40 x 4 and 80 x 8 cells agree: the tip is
//   6.6e-4 L from the clamp and the bending energy 6.9e-4 above, the
//   Kirchhoff-Love energy's own coupling of bending and stretch at order
//   (kappa t)^2 (membrane energy (kappa t)^2/12 of the bending energy),
//   not a discretisation error (doc/verification.md).
// - The tangent with an edge moment (a turned, stretched strip) against
//   central differences of the residual.
// - Stretch: a dead line load f = 1 MN/m along the strip at x = 1/2: the
//   uniaxial Saint Venant-Kirchhoff state lambda E (lambda^2 - 1)/2 = f/t
//   (nu = 0: no contraction), the tip's displacement (lambda - 1) L and the
//   membrane energy t A E/2 ((lambda^2 - 1)/2)^2; the bending energy zero.
// The same on 2 ranks.

#include "shell_strip.h"

#include <cmath>
#include <cstdio>

namespace
{
  const double pi = 3.14159265358979323846;
  const double E = 1e9, h = 0.01, b = 0.1, L = 1.;
  const double D = E * h * h * h / 12., EI = D * b;

  /// The strip, clamped at boundary 0 (x = -1/2), its tip monitored.
  pneuma_test::Settings
  strip()
  {
    return pneuma_test::shell_strip(2, 2);
  }

  /// The history row at time @p t.
  const pneuma::Statistics *
  at_time(const pneuma::RunResult &s, const double t)
  {
    for (const auto &row : s.history)
      if (std::abs(row.get("time") - t) < 1e-12)
        return &row;
    return nullptr;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // The tangent with an edge moment against finite differences.
  {
    auto settings = pneuma_test::quiet();
    for (const auto &entry : strip())
      settings.push_back(entry);
    settings.insert(settings.end(),
                    {{"Geometry/Global refinements", "1"},
                     {"Bending/Edge moment boundaries", "1"},
                     {"Bending/Edge moment/Function expression", "300"}});
    auto         sim   = pneuma_test::make(settings);
    const double error = sim->check_tangent(1., 0.2, 1e-7).first;
    if (pneuma_test::root())
      std::printf("tangent with an edge moment vs finite differences: %s\n",
                  error < 1e-6 ? "relative error < 1e-6" : "FAIL");
    if (error >= 1e-6 && pneuma_test::root())
      std::printf("  relative error %.3e\n", error);
    ok = error < 1e-6 && ok;
  }

  // Roll-up.
  {
    auto settings = strip();
    settings.insert(settings.end(),
                    {{"Bending/Edge moment boundaries", "1"},
                     {"Bending/Edge moment/Function expression",
                      pneuma_test::number(2. * pi * D / L) + "*t"},
                     {"Load stepping/Stage end times", "0.25, 0.5, 1"},
                     {"Load stepping/Initial increment", "0.125"}});
    const auto s = pneuma_test::run(settings);
    if (pneuma_test::failed(s, "roll-up"))
      return 1;
    const double R4 = 2. * L / pi;
    for (const auto &[t, ux, uz] :
         {std::array<double, 3>{{0.25, R4 - L, R4}},
          std::array<double, 3>{{0.5, -L, L / pi * 2.}}})
      {
        const auto *row = at_time(s, t);
        if (row == nullptr)
          {
            if (pneuma_test::root())
              std::printf("roll-up: no converged state at t = %g\n", t);
            return 1;
          }
        const std::string name =
          "roll-up at m" + std::string(t == 0.25 ? "/4" : "/2");
        ok = pneuma_test::check(name + ": tip along [m]",
                                row->get("m0_u_x"),
                                ux,
                                2e-3)
             && ok;
        ok = pneuma_test::check(name + ": tip across [m]",
                                row->get("m0_u_z"),
                                uz,
                                2e-3)
             && ok;
      }
    const double gap = std::hypot(L + s.get("m0_u_x"), s.get("m0_u_z")) / L;
    if (pneuma_test::root())
      std::printf("roll-up at m: tip from the clamp %.1e L (%s)\n",
                  gap,
                  gap < 1e-3 ? "< 1e-3 L" : "FAIL");
    ok             = gap < 1e-3 && ok;
    const double M = 2. * pi * EI / L;
    ok             = pneuma_test::check("roll-up at m: bending energy [J]",
                            s.get("bending_energy"),
                            M * M * L / (2. * EI),
                            2e-3)
         && ok;
    const double share = s.get("membrane_energy") / s.get("bending_energy");
    if (pneuma_test::root())
      std::printf("roll-up at m: membrane energy / bending energy %s\n",
                  share < 1e-3 ? "< 1e-3" : "FAIL");
    ok = share < 1e-3 && ok;
    // The clamp holds the end moment: its reaction moment about the edge
    // (the weak clamp's forces on the nodes next to the edge included).
    ok = pneuma_test::check(
           "roll-up at m: the clamp's reaction moment about y [N m]",
           s.summary.get_vector("boundary_0_reaction_moment")[1],
           M,
           1e-5)
         && ok;
  }

  // Uniaxial stretch.
  {
    const double f        = 1e6;
    auto         settings = strip();
    settings.insert(settings.end(),
                    {{"Loads/Line load boundaries", "1"},
                     {"Loads/Line load/Function expression",
                      pneuma_test::number(f) + "*t; 0; 0"}});
    const auto s = pneuma_test::run(settings);
    if (pneuma_test::failed(s, "stretch"))
      return 1;
    // lambda E (lambda^2 - 1)/2 = f/t by Newton from 1.
    double lambda = 1.;
    for (unsigned int it = 0; it < 50; ++it)
      lambda -= (lambda * E * (lambda * lambda - 1.) / 2. - f / h)
                / (E * (3. * lambda * lambda - 1.) / 2.);
    const double strain = (lambda * lambda - 1.) / 2.;
    ok                  = pneuma_test::check("stretch: tip along [m]",
                            s.get("m0_u_x"),
                            (lambda - 1.) * L,
                            1e-8)
         && ok;
    ok = pneuma_test::check("stretch: membrane energy [J]",
                            s.get("membrane_energy"),
                            h * L * b * E / 2. * strain * strain,
                            1e-8)
         && ok;
    const double bending =
      std::abs(s.get("bending_energy")) / s.get("membrane_energy");
    if (pneuma_test::root())
      std::printf("stretch: bending energy / membrane energy %s\n",
                  bending < 1e-12 ? "< 1e-12" : "FAIL");
    ok = bending < 1e-12 && ok;
  }
  if (pneuma_test::root())
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
