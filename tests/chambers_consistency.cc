// Chamber terms: consistency of the bordered Jacobian and the identities
// of the fillings.
// 1. The assembled bordered Jacobian (follower and hydrostatic stiffness,
//    B = dR/d(p,h), C = dg/du, D = dg/d(p,h)) against central finite
//    differences of the residual, at a perturbed state off equilibrium in
//    the chamber unknowns too: gas with a closed amount, gas with
//    prescribed volume, an open liquid tank and liquid + gas in a closed
//    tube, the last two also with a prescribed level, on degree 1 and 2.
// 2. Liquid + gas in the airbeam tube (gas amount doubled, then 0.15 m^3
//    of water filled in, the free surface crossing cells in every step):
//    Newton's quadratic rate; the gas law p V_gas^1.4 = p_a (2 V0)^1.4; the
//    liquid volume; the vertical reaction equals the water weight.

#include "test_tools.h"

#include <cmath>
#include <tuple>
#include <vector>

namespace
{
  const pneuma_test::Settings sphere = {
    {"Geometry/Type", "sphere"},
    {"Geometry/sphere/Radius", "1"},
    {"Geometry/Global refinements", "1"},
    {"Materials/Region 0/Law", "neo-Hookean"},
    {"Materials/Region 0/neo-Hookean/Shear modulus", "1e6"},
    {"Chambers/Number of chambers", "1"},
    {"Chambers/Chamber 1/Regions", "0"}};

  const pneuma_test::Settings tank = {
    {"Geometry/Type", "disc"},
    {"Geometry/disc/Radius", "0.5"},
    {"Geometry/Global refinements", "2"},
    {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
    {"Boundary conditions/Fixed boundaries", "0: xyz"},
    {"Chambers/Number of chambers", "1"},
    {"Chambers/Chamber 1/Regions", "-0"},
    {"Chambers/Chamber 1/Open", "true"},
    {"Chambers/Chamber 1/Filling", "liquid"},
    {"Chambers/Chamber 1/Liquid/Volume/Function expression", "0.05*t"}};

  const pneuma_test::Settings tube = {
    {"Geometry/Type", "closed cylinder"},
    {"Geometry/closed cylinder/Radius", "0.23"},
    {"Geometry/closed cylinder/Length", "2"},
    {"Geometry/Global refinements", "2"},
    {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
    {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
    {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
    {"Chambers/Number of chambers", "1"},
    {"Chambers/Chamber 1/Regions", "0, 1, 2"},
    {"Chambers/Chamber 1/Filling", "liquid and gas"},
    {"Chambers/Chamber 1/Gas/Control", "gas amount"},
    {"Chambers/Chamber 1/Gas/Gas amount/Function expression", "2"},
    {"Chambers/Chamber 1/Liquid/Volume/Function expression", "0.1*t"}};

  bool
  tangent_check(const std::string    &name,
                pneuma_test::Settings settings,
                const unsigned int    degree,
                const double          amplitude)
  {
    settings.push_back(
      {"Discretisation/Polynomial degree", std::to_string(degree)});
    settings.push_back({"Output/Quiet", "true"});
    const double error =
      pneuma_test::make(settings)->check_tangent(1., amplitude, 1e-7).first;
    const bool pass = error < 1e-6;
    std::printf("bordered Jacobian vs finite differences, %s, degree %u: %s\n",
                name.c_str(),
                degree,
                pass ? "relative error < 1e-6" : "FAIL");
    if (!pass)
      std::printf("  relative error %.3e\n", error);
    return pass;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // A base scene with a filling's settings added.
  const auto with = [](pneuma_test::Settings        base,
                       const pneuma_test::Settings &filling) {
    base.insert(base.end(), filling.begin(), filling.end());
    return base;
  };
  const std::string chamber = "Chambers/Chamber 1/";
  const auto        gas_amount =
    with(sphere,
         {{chamber + "Gas/Control", "gas amount"},
          {chamber + "Gas/Gas amount/Function expression", "1.5"}});
  const auto volume =
    with(sphere,
         {{chamber + "Gas/Control", "volume"},
          {chamber + "Gas/Volume/Function expression", "1.3"}});
  // The liquid fillings with a prescribed level (Liquid/Control = level):
  // the tank to 0.1 m above its rim, the tube to its axis.
  const auto tank_level =
    with(tank,
         {{chamber + "Liquid/Control", "level"},
          {chamber + "Liquid/Level/Function expression", "0.1*t"}});
  const auto tube_level =
    with(tube,
         {{chamber + "Liquid/Control", "level"},
          {chamber + "Liquid/Level/Function expression", "0.1*t-0.1"}});
  const std::vector<std::tuple<std::string, pneuma_test::Settings, double>>
    cases = {{"gas, closed amount", gas_amount, 0.05},
             {"gas, prescribed volume", volume, 0.05},
             {"liquid, open tank", tank, 0.02},
             {"liquid and gas", tube, 0.005},
             {"liquid, open tank, prescribed level", tank_level, 0.02},
             {"liquid and gas, prescribed level", tube_level, 0.005}};
  for (const unsigned int degree : {1u, 2u})
    for (const auto &[name, settings, amplitude] : cases)
      ok = tangent_check(name, settings, degree, amplitude) && ok;

  // Liquid + gas filling of the airbeam tube.
  pneuma_test::Settings liquid_gas = pneuma_test::liquid_gas_tube();
  liquid_gas.insert(
    liquid_gas.end(),
    {{"Load stepping/Initial increment", "0.25"},
     {"Load stepping/Maximum increment", "0.25"},
     {"Newton/Residual tolerance", "1e-12"},
     // The tangent's rate, observed from the last state (from the
     // extrapolated start the last step is too short to show it).
     {"Load stepping/Extrapolation", "none"},
     {"Output/Directory", "output-liquid-gas"}});
  const auto s      = pneuma_test::run(liquid_gas);
  ok                = ok && s.exit_code == 0;
  const auto &r     = s.last_residual_history;
  double      order = 0.;
  for (unsigned int k = 1; k + 1 < r.size(); ++k)
    if (r[k + 1] / r[0] > 1e-12 && r[k] / r[0] < 1e-1)
      order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
  unsigned int max_iterations = 0;
  for (const auto n : s.step_iterations)
    max_iterations = std::max(max_iterations, n);
  std::printf("liquid and gas: Newton iterations per step at most %s, "
              "observed order in the last step %s\n",
              max_iterations <= 6 ? "6" : "more than 6 (FAIL)",
              order >= 1.8 ? ">= 1.8" : "< 1.8 (FAIL)");
  ok = ok && max_iterations <= 6 && order >= 1.8;

  const double V0  = s.history.front().get("c1_volume");
  const double p_a = 101325.;
  ok = pneuma_test::check("liquid and gas: p V_gas^1.4 / (p_a (2 V0)^1.4)",
                          s.get("c1_absolute_pressure")
                            * std::pow(s.get("c1_gas_volume"), 1.4)
                            / (p_a * std::pow(2. * V0, 1.4)),
                          1.,
                          1e-8)
       && ok;
  ok = pneuma_test::check("liquid and gas: liquid volume",
                          s.get("c1_liquid_volume"),
                          0.15,
                          1e-8)
       && ok;
  ok = pneuma_test::check("liquid and gas: vertical reaction / water weight",
                          s.summary.get_vector("reaction")[2],
                          1000. * 9.81 * 0.15,
                          1e-8)
       && ok;
  return ok ? 0 : 1;
}
