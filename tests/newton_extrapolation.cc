// The load-step predictor (Load stepping/Extrapolation, doc/theory.md §5
// "Predictor"): a load-controlled step starts from the last step's
// increment scaled to this one. It changes the iterations, not the
// equilibrium. Two scenes, each run with linear extrapolation and with
// none:
// - V1, the clamped disc under follower pressure 50 kPa in 8 steps (Q1,
//   768 cells): centre deflection against the finite-strain reference
//   26.194 mm (within 0.5 %), and the two runs' deflections alike to 1e-6;
// - the airbeam tube filled with gas then liquid (gas amount and liquid
//   volume controlled, Q1, 3 refinements): the border unknowns (pressure,
//   level) are extrapolated with the field; the gas law p V^1.4 =
//   p_a (2 V0)^1.4 after the filling, and absolute pressure and gas volume
//   alike in both runs to 1e-6.
// With the predictor no step may need more Newton iterations, and all
// together fewer.

#include "test_tools.h"

#include <cmath>

namespace
{
  /// The summary values @p names of @p with against @p without (1e-6),
  /// and the iterations: none more in any step, fewer in all.
  bool
  compare(const std::string              &scene,
          const pneuma::RunResult        &with,
          const pneuma::RunResult        &without,
          const std::vector<std::string> &names)
  {
    bool ok = with.exit_code == 0 && without.exit_code == 0;
    for (const auto &name : names)
      ok = pneuma_test::check(scene + ", " + name
                                + " with extrapolation against without",
                              with.get(name),
                              without.get(name),
                              1e-6)
           && ok;
    const auto list = [](const std::vector<unsigned int> &its) {
      std::string text;
      for (const auto n : its)
        text += " " + std::to_string(n);
      return text;
    };
    bool no_more =
      with.step_iterations.size() == without.step_iterations.size();
    unsigned int total[2] = {0, 0};
    for (unsigned int k = 0; no_more && k < with.step_iterations.size(); ++k)
      {
        no_more =
          no_more && with.step_iterations[k] <= without.step_iterations[k];
        total[0] += with.step_iterations[k];
        total[1] += without.step_iterations[k];
      }
    std::printf("%s: Newton iterations per step with extrapolation:%s, "
                "without:%s (%s)\n",
                scene.c_str(),
                list(with.step_iterations).c_str(),
                list(without.step_iterations).c_str(),
                no_more && total[0] < total[1]
                  ? "none more, fewer in all"
                  : "FAIL: more in a step, or not fewer in all");
    return ok && no_more && total[0] < total[1];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // V1 disc.
  {
    pneuma::RunResult runs[2];
    for (const unsigned int k : {0u, 1u})
      runs[k] = pneuma_test::run(
        {{"Geometry/Type", "disc"},
         {"Geometry/disc/Radius", "0.1425"},
         {"Geometry/Global refinements", "3"},
         {"Materials/Region 0/Law", "Saint Venant-Kirchhoff"},
         {"Materials/Region 0/Thickness", "1e-3"},
         {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
          "3.11488e8"},
         {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.34"},
         {"Loads/Pressure/Function expression", "5e4*t"},
         {"Boundary conditions/Fixed boundaries", "0: xyz"},
         {"Load stepping/Initial increment", "0.125"},
         {"Load stepping/Maximum increment", "0.125"},
         {"Load stepping/Extrapolation", k == 0 ? "linear" : "none"},
         {"Output/Directory", "output-disc"},
         {"Output/Monitor points", "0,0,0"}});
    const double w[2] = {runs[0].summary.get_vector("m0_u")[2],
                         runs[1].summary.get_vector("m0_u")[2]};
    ok = pneuma_test::check("V1 disc, w0 at 50 kPa [m], with extrapolation",
                            w[0],
                            26.194e-3,
                            5e-3)
         && ok;
    ok = compare("V1 disc", runs[0], runs[1], {"m0_u_z"}) && ok;
  }

  // Gas, then liquid, in the airbeam tube.
  {
    pneuma::RunResult runs[2];
    for (const unsigned int k : {0u, 1u})
      {
        pneuma_test::Settings settings = pneuma_test::liquid_gas_tube();
        settings.insert(settings.end(),
                        {{"Load stepping/Initial increment", "0.125"},
                         {"Load stepping/Maximum increment", "0.125"},
                         {"Load stepping/Extrapolation",
                          k == 0 ? "linear" : "none"},
                         {"Output/Directory", "output-tube"}});
        runs[k] = pneuma_test::run(settings);
      }
    const double V0  = runs[0].history.front().get("c1_volume");
    const double p_a = 101325.;
    ok               = pneuma_test::check(
           "tube, p V_gas^1.4 / (p_a (2 V0)^1.4) with extrapolation",
           runs[0].get("c1_absolute_pressure")
             * std::pow(runs[0].get("c1_gas_volume"), 1.4)
             / (p_a * std::pow(2. * V0, 1.4)),
           1.,
           1e-8)
         && ok;
    ok = compare("tube",
                 runs[0],
                 runs[1],
                 {"c1_absolute_pressure", "c1_gas_volume"})
         && ok;
  }
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
