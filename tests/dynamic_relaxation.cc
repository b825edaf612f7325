// Dynamic relaxation with kinetic damping (strategies/dynamic_relaxation,
// doc/theory.md "Dynamic relaxation"), on 1 and 2 ranks:
//  - the clamped Hencky membrane (V1, 768 Q1 cells) relaxed alone to
//    |r| <= 1e-8 |r_ref|: the centre deflection equals Newton's (1e-6) and
//    the reference 15.247 mm (3e-3, the mesh's error);
//  - the neo-Hookean balloon of V3 filled with a gas amount to the stretch
//    1.5 in one relaxation (the chamber pressure follows the volume at
//    every iteration), finished by Newton: stretch and pR/(mu H) against
//    1.5 and 1.216278 (1e-4);
//  - the square airbag (two flat, stress-free seamed sheets, tension-field
//    wrinkling, tests/square_airbag.cc) on 4 x 4 cells per sheet: relaxed
//    to 1.25 kPa then Newton to 5 kPa, the same rise as Newton alone
//    (1e-6); on 16 x 16 cells per sheet Newton alone fails (exit 2, and
//    the message proposes the relaxation), relaxation then Newton inflates
//    it to within 0.5 % of the literature's 0.217 m (on 1 rank only).

#include "test_tools.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
  using pneuma_test::Settings;

  bool
  print(const bool ok, const std::string &what)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: %s\n", what.c_str(), ok ? "yes" : "NO");
    return ok;
  }

  bool
  hencky()
  {
    const Settings disc = {
      {"Geometry/Type", "disc"},
      {"Geometry/disc/Radius", "0.1425"},
      {"Geometry/Global refinements", "2"},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
       "3.11488e8"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.34"},
      {"Loads/Pressure/Function expression", "1e4*t"},
      {"Boundary conditions/Fixed boundaries", "0: xyz"},
      {"Output/Monitor points", "0,0,0"}};
    Settings relaxed = disc;
    relaxed.insert(relaxed.end(),
                   {{"Load stepping/Strategy", "relaxation"},
                    {"Dynamic relaxation/Finish with Newton", "false"},
                    {"Dynamic relaxation/Residual tolerance", "1e-8"}});
    const auto   r  = pneuma_test::run(relaxed);
    const auto   n  = pneuma_test::run(disc);
    const double w  = r.summary.get_vector("m0_u")[2];
    bool         ok = print(r.exit_code == 0 && n.exit_code == 0
                      && r.summary.get("relaxation_newton_iterations") == 0
                      && r.summary.get("relaxation_iterations") > 0
                      && r.summary.get("relaxation_iterations") < 2000,
                    "Hencky: relaxed alone (no Newton), in under 2000 "
                            "iterations");
    ok = pneuma_test::check("Hencky: w0 relaxed against Newton's [m]",
                            w,
                            n.summary.get_vector("m0_u")[2],
                            1e-6)
         && ok;
    return pneuma_test::check("Hencky: w0 relaxed [m]", w, 15.247e-3, 3e-3)
           && ok;
  }

  bool
  gas_balloon()
  {
    Settings s = pneuma_test::neo_hookean_sphere_chamber();
    s.insert(s.end(),
             {{"Chambers/Chamber 1/Gas/Control", "gas amount"},
              {"Chambers/Chamber 1/Gas/Gas amount/Function expression",
               pneuma_test::balloon_gas_amount()},
              {"Load stepping/Stage end times", "0.5"},
              {"Load stepping/Strategy", "relaxation"}});
    const auto r  = pneuma_test::run(s);
    bool       ok = print(r.exit_code == 0 && r.history.size() == 2,
                    "gas balloon: one relaxation to t = 0.5");
    if (!ok)
      return false;
    const double l = std::cbrt(r.history.back().get("c1_volume")
                               / r.history.front().get("c1_volume"));
    ok = pneuma_test::check("gas balloon: stretch", l, 1.5, 1e-4) && ok;
    return pneuma_test::check("gas balloon: pR/(mu H)",
                              r.history.back().get("c1_pressure") / 1e3,
                              1.216278,
                              1e-4)
           && ok;
  }

  /// The same balloon under volume control: the pressure is the
  /// multiplier of V(u) = V(t), which the relaxation holds by projection.
  bool
  volume_balloon()
  {
    Settings s = pneuma_test::neo_hookean_sphere_chamber();
    s.insert(s.end(),
             {{"Chambers/Chamber 1/Gas/Control", "volume"},
              {"Chambers/Chamber 1/Gas/Volume/Function expression",
               "(1 + t)^3"},
              {"Load stepping/Stage end times", "0.5"},
              {"Load stepping/Strategy", "relaxation"}});
    const auto r  = pneuma_test::run(s);
    bool       ok = print(r.exit_code == 0 && r.history.size() == 2,
                    "volume balloon: one relaxation to t = 0.5");
    if (!ok)
      return false;
    const double l = std::cbrt(r.history.back().get("c1_volume")
                               / r.history.front().get("c1_volume"));
    ok = pneuma_test::check("volume balloon: stretch", l, 1.5, 1e-10) && ok;
    return pneuma_test::check("volume balloon: pR/(mu H)",
                              r.history.back().get("c1_pressure") / 1e3,
                              1.216278,
                              1e-4)
           && ok;
  }

  Settings
  relaxed_first(Settings s)
  {
    s.insert(s.end(),
             {{"Load stepping/Stage end times", "0.25, 1"},
              {"Load stepping/Strategy", "relaxation, static"}});
    return s;
  }

  bool
  square_airbag()
  {
    const auto n = pneuma_test::run(pneuma_test::square_airbag(0));
    const auto r =
      pneuma_test::run(relaxed_first(pneuma_test::square_airbag(0)));
    bool ok = print(n.exit_code == 0 && r.exit_code == 0,
                    "airbag 4 x 4: Newton alone and relaxation then Newton "
                    "converge");
    if (ok)
      ok = pneuma_test::check("airbag 4 x 4: rise relaxed first against "
                              "Newton's [m]",
                              r.summary.get_vector("m0_u")[2],
                              n.summary.get_vector("m0_u")[2],
                              1e-6);
    // The fine mesh (36 of the test's 47 s) on 1 rank only: the 2-rank run
    // checks the same relaxation and hand-over on the cases above.
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      return ok;
    const auto fails = pneuma_test::run(pneuma_test::square_airbag(2));
    ok               = print(fails.exit_code == 2
                 && fails.message.find("Strategy = relaxation")
                      != std::string::npos,
               "airbag 16 x 16: Newton alone fails (exit 2) and proposes "
                             "the relaxation")
         && ok;
    const auto fine =
      pneuma_test::run(relaxed_first(pneuma_test::square_airbag(2)));
    ok = print(fine.exit_code == 0,
               "airbag 16 x 16: relaxation then Newton converges")
         && ok;
    return fine.exit_code == 0
           && pneuma_test::check("airbag 16 x 16: rise [m]",
                                 fine.summary.get_vector("m0_u")[2],
                                 0.217,
                                 5e-3,
                                 3)
           && ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = hencky();
  ok                                          = gas_balloon() && ok;
  ok                                          = volume_balloon() && ok;
  ok                                          = square_airbag() && ok;
  print(ok, "all checks passed");
  return ok ? 0 : 1;
}
