// Consistency of the cable linearisation: the assembled tangent of the
// tension-only cable (taut and slack elements, a prestressed helix, a
// stiff and a soft cable) and of the solid beam (both laws, a bent
// polyline with an end moment, a prestressed helix) against central finite
// differences of the residual at a perturbed state; and the tension-only law: a
// cable pushed together carries (almost) nothing and the solve converges, a
// pulled one carries EA times the engineering strain exactly; a prestress force
// or an unstressed length gives the expected force (Hooke for the cable, the
// St. Venant-Kirchhoff uniaxial force EA lambda (lambda^2-1)/2 for the
// solid beam, whose unstressed length is also set by L/(1 + F/EA)).

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  const std::vector<std::pair<std::string, pneuma_test::Settings>> cases = {
    {"polyline, soft",
     {{"Cables/Cable 1/polyline/Points", "0, 0, 0; 5, 0, -3.3; 10, 0, 0"},
      {"Cables/Cable 1/Young's modulus", "1.27e8"}}},
    {"polyline, stiff",
     {{"Cables/Cable 1/polyline/Points", "0, 0, 0; 5, 0, -3.3; 10, 0, 0"},
      {"Cables/Cable 1/Young's modulus", "1.27e11"}}},
    {"prestressed helix",
     {{"Cables/Cable 1/Shape", "helix"},
      {"Cables/Cable 1/helix/Radius", "0.23"},
      {"Cables/Cable 1/helix/Angle to axis", "30"},
      {"Cables/Cable 1/helix/Turns", "1.5"},
      {"Cables/Cable 1/Prestress force", "1000"}}},
    {"prestressed ring",
     {{"Cables/Cable 1/Shape", "ring"},
      {"Cables/Cable 1/ring/Radius", "0.23"},
      {"Cables/Cable 1/Start support", "free"},
      {"Cables/Cable 1/Prestress force", "1000"}}},
    {"solid beam, St. Venant-Kirchhoff, end moment",
     {{"Cables/Cable 1/Element", "solid beam"},
      {"Cables/Cable 1/polyline/Points", "0, 0, 0; 0.5, 0.1, 0; 1, 0, 0.2"},
      {"Cables/Cable 1/Section semi-axes", "0.02, 0.01"},
      {"Cables/Cable 1/End moment/Function expression", "10; 200; 50"}}},
    {"solid beam, neo-Hookean, prestressed helix",
     {{"Cables/Cable 1/Element", "solid beam"},
      {"Cables/Cable 1/solid beam/Law", "neo-Hookean"},
      {"Cables/Cable 1/Shape", "helix"},
      {"Cables/Cable 1/helix/Radius", "0.23"},
      {"Cables/Cable 1/helix/Angle to axis", "30"},
      {"Cables/Cable 1/Section semi-axes", "0.01"},
      {"Cables/Cable 1/Prestress force", "1000"}}}};
  for (const auto &[name, extra] : cases)
    {
      pneuma_test::Settings settings = {
        {"Geometry/Type", "none"},
        {"Cables/Number of cables", "1"},
        {"Cables/Cable 1/Number of elements", "8"},
        {"Cables/Cable 1/Start support", "fixed"},
        {"Cables/Cable 1/Distributed load/Function expression", "0; 0; -1"},
        {"Output/Quiet", "true"}};
      settings.insert(settings.end(), extra.begin(), extra.end());
      const auto simulator = pneuma_test::make(settings);
      // The random state makes some elements slack and some taut.
      const double error = simulator->check_tangent(1., 0.02, 1e-7).first;
      const bool   pass  = error < 1e-6;
      std::printf("cable tangent vs finite differences, %s: %s\n",
                  name.c_str(),
                  pass ? "relative error < 1e-6" : "FAIL");
      if (!pass)
        std::printf("  relative error %.3e\n", error);
      ok = ok && pass;
    }

  // Tension only: a straight cable of EA = 1e6 N, length 2, one end
  // fixed, the other moved along the axis by +-1 mm.
  for (const double d : {1e-3, -1e-3})
    {
      const auto s = pneuma_test::run(
        {{"Geometry/Type", "none"},
         {"Cables/Number of cables", "1"},
         {"Cables/Cable 1/polyline/Points", "0, 0, 0; 2, 0, 0"},
         {"Cables/Cable 1/Number of elements", "4"},
         {"Cables/Cable 1/Section semi-axes", "0.01"},
         {"Cables/Cable 1/Young's modulus",
          std::to_string(1e6 / (M_PI * 1e-4))},
         {"Cables/Cable 1/Start support", "fixed"},
         {"Cables/Cable 1/End support", "fixed"},
         {"Cables/Cable 1/End displacement/Function expression",
          std::to_string(d) + " * t; 0; 0"}});
      const double N =
        s.summary.has("cable1_max_force") ? s.get("cable1_max_force") : NAN;
      if (d > 0.)
        ok &= pneuma_test::check("taut cable: axial force = EA strain",
                                 N,
                                 1e6 * d / 2.,
                                 1e-10);
      else
        {
          // Slack: EA r strain with r = 1e-6, i.e. 1e-6 of the taut force.
          const bool pass =
            s.exit_code == 0 && std::abs(N) <= 1e-6 * 500. * 1.0001;
          std::printf("slack cable: converged %s, axial force %.3e N "
                      "(taut would be -500 N) %s\n",
                      s.exit_code == 0 ? "yes" : "no",
                      N,
                      pass ? "PASS" : "FAIL");
          ok &= pass;
        }
    }

  // Prestress: a straight cable between fixed supports carries the given
  // force, or EA (L/L0 - 1) for a given unstressed length L0; the solid
  // beam likewise (nu = 0: no lateral contraction to change the area).
  for (const std::string element : {"cable", "solid beam"})
    for (const bool by_length : {false, true})
      {
        const double          EA = 1e6, L = 2., N0 = 1500.;
        const double          L0       = L / (1. + N0 / EA);
        pneuma_test::Settings settings = {
          {"Geometry/Type", "none"},
          {"Cables/Number of cables", "1"},
          {"Cables/Cable 1/Element", element},
          {"Cables/Cable 1/polyline/Points", "0, 0, 0; 2, 0, 0"},
          {"Cables/Cable 1/Number of elements", "4"},
          {"Cables/Cable 1/Section semi-axes", "0.01"},
          {"Cables/Cable 1/solid beam/Poisson's ratio", "0"},
          {"Cables/Cable 1/Young's modulus",
           std::to_string(EA / (M_PI * 1e-4))},
          {"Cables/Cable 1/Start support", "fixed"},
          {"Cables/Cable 1/End support", "fixed"}};
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.15g", by_length ? L0 : N0);
        settings.push_back({by_length ? "Cables/Cable 1/Unstressed length"
                                      : "Cables/Cable 1/Prestress force",
                            buffer});
        const auto s = pneuma_test::run(settings);
        // A solid beam with St. Venant-Kirchhoff: the first Piola force of
        // uniaxial stretch lambda = 1 + N0/EA is EA lambda (lambda^2-1)/2.
        const double lambda = 1. + N0 / EA;
        const double reference =
          element == "cable" ? N0 : EA * lambda * (lambda * lambda - 1.) / 2.;
        ok &= pneuma_test::check(
          element + (by_length ? ", unstressed length" : ", prestress force")
            + ": axial force",
          s.summary.has("cable1_max_force") ? s.get("cable1_max_force") : NAN,
          reference,
          1e-8);
      }

  // Quadratic rate: a solid-beam cantilever under a large tip force
  // (deflection about half the length) and the elastic catenary; order
  // log(r_{k+1})/log(r_k) of the last iteration above round-off.
  const std::vector<std::pair<std::string, pneuma_test::Settings>> rate_cases =
    {{"solid-beam cantilever",
      {{"Cables/Cable 1/Element", "solid beam"},
       {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
       {"Cables/Cable 1/Section semi-axes", "0.02"},
       {"Cables/Cable 1/End forces", "true"},
       {"Cables/Cable 1/End force/Function expression", "0; 3e4 * t; 0"}}},
     {"catenary",
      {{"Cables/Cable 1/polyline/Points",
        "0, 0, 0; 5, 0, -3.3166247903554; 10, 0, 0"},
       {"Cables/Cable 1/End support", "fixed"},
       {"Cables/Cable 1/Young's modulus", "1.2732395447351628e8"},
       {"Cables/Cable 1/Distributed load/Function expression", "0; 0; -t"}}}};
  for (const auto &[name, extra] : rate_cases)
    {
      pneuma_test::Settings settings = {
        {"Geometry/Type", "none"},
        {"Cables/Number of cables", "1"},
        {"Cables/Cable 1/Number of elements", "16"},
        {"Cables/Cable 1/Start support", "fixed"},
        {"Load stepping/Initial increment", "0.25"},
        {"Newton/Residual tolerance", "1e-10"},
        {"Newton/Maximum iterations", "100"},
        // From the extrapolated start the last step is too short to show
        // its rate: the tangent's rate is observed from the last state.
        {"Load stepping/Extrapolation", "none"}};
      settings.insert(settings.end(), extra.begin(), extra.end());
      const auto  s     = pneuma_test::run(settings);
      const auto &r     = s.last_residual_history;
      double      order = 0.;
      for (unsigned int k = 1; k + 1 < r.size(); ++k)
        if (r[k + 1] / r[0] > 1e-11 && r[k] / r[0] < 1e-1)
          order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
      if (order < 1.8)
        for (const double x : r)
          std::printf("  %.3e\n", x / r[0]);
      std::printf("Newton, %s, last step: observed order %s\n",
                  name.c_str(),
                  order >= 1.8 ? ">= 1.8" : "< 1.8 (FAIL)");
      ok = ok && s.exit_code == 0 && order >= 1.8;
    }

  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
