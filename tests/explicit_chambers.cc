// Chambers in explicit dynamics (strategies/explicit_dynamics,
// strategies/border_projection.h, doc/theory.md "Explicit dynamics"), on
// 1 and 2 ranks, on the incompressible neo-Hookean sphere of
// tests/explicit_waves (R = 1 m, H = 1 mm, mu = 20 MPa, rho = 1000 kg/m^3,
// Q2 on two refinements), from rest in real time:
//  - a gas under volume control: the volume rises smoothly by 33.1 % in
//    0.02 s (l = 1.1) and is held to t = 0.05 s. The pressure is the
//    multiplier of V(u) = V(t), found at every step by the projection:
//    the volume holds to round-off at every step (the largest relative
//    error of the constraint since the last row, and the volume in
//    history.csv against V(t)); the mean pressure of the last 0.02 s
//    against the static pressure of the sphere at that stretch,
//    p = 2 mu H/R (1/l - 1/l^7) (1 %); the energy balance T + W = 0
//    (the work of the pump is in W) within 1e-3 of the largest kinetic
//    energy at every row;
//  - liquid pumped into the sphere (gravity on) after a static stage has
//    inflated it with a sealed amount of gas: 0.5 m^3 in 0.02 s, followed
//    for 0.03 s; the free surface's level holds the liquid volume at every
//    step: the liquid volume against the curve at every row (1e-9, the
//    file's digits); the energy balance within 1e-3 of the largest kinetic
//    energy at every row.

#include "test_tools.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
  constexpr double R = 1., H = 1e-3, mu = 2e7;

  pneuma_test::Settings
  sphere()
  {
    return {{"Geometry/Type", "sphere"},
            {"Geometry/sphere/Radius", pneuma_test::number(R)},
            {"Geometry/Global refinements", "2"},
            {"Discretisation/Polynomial degree", "2"},
            {"Materials/Region 0/Law", "neo-Hookean"},
            {"Materials/Region 0/Thickness", pneuma_test::number(H)},
            {"Materials/Region 0/Density", "1000"},
            {"Materials/Region 0/neo-Hookean/Shear modulus",
             pneuma_test::number(mu)},
            {"Boundary conditions/Fixed points",
             "0,0,1: xy; 0,0,-1: xy; 1,0,0: yz; -1,0,0: yz"},
            {"Chambers/Number of chambers", "1"},
            {"Chambers/Chamber 1/Regions", "0"}};
  }

  /// A smooth rise from 0 to 1 over [t0, t0 + 0.02] (muparser).
  std::string
  ramp(const std::string &t0)
  {
    const std::string s = "((t - " + t0 + ")/0.02)";
    return "if(t < " + t0 + ", 0, if(t < " + t0 + " + 0.02, " + s + "^2*(3 - 2*"
           + s + "), 1))";
  }

  bool
  print(const bool ok, const std::string &what)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: %s\n", what.c_str(), ok ? "yes" : "NO");
    return ok;
  }

  /// The largest |T + W + D| over the rows (from rest: T_0 = 0) against
  /// the largest kinetic energy of the run.
  double
  balance(const pneuma::RunResult &s)
  {
    double worst = 0., largest = 0.;
    for (const auto &row : s.history)
      {
        worst =
          std::max(worst,
                   std::abs(row.get("kinetic_energy") + row.get("residual_work")
                            + row.get("damping_energy")));
        largest = std::max(largest, row.get("kinetic_energy"));
      }
    return worst / largest;
  }

  bool
  prescribed_volume()
  {
    pneuma_test::Settings s = sphere();
    s.push_back({"Chambers/Chamber 1/Gas/Control", "volume"});
    s.push_back({"Chambers/Chamber 1/Gas/Volume/Function expression",
                 "1 + 0.331*" + ramp("0")});
    s.push_back({"Load stepping/Stage end times", "0.05"});
    s.push_back({"Load stepping/Strategy", "explicit"});
    s.push_back({"Explicit dynamics/Output interval", "5e-4"});
    const auto r = pneuma_test::run(s);
    if (!print(r.exit_code == 0, "volume: the run finishes"))
      return false;
    const double V0               = r.history.front().get("c1_volume");
    double       worst_constraint = 0., worst_volume = 0., p_sum = 0.;
    unsigned int n = 0;
    for (const auto &row : r.history)
      {
        const double t = row.get("time");
        const double s_t =
          t < 0.02 ? std::pow(t / 0.02, 2) * (3. - 2. * t / 0.02) : 1.;
        worst_constraint =
          std::max(worst_constraint, row.get("constraint_error"));
        worst_volume =
          std::max(worst_volume,
                   std::abs(row.get("c1_volume") / (V0 * (1. + 0.331 * s_t))
                            - 1.));
        if (t >= 0.03)
          {
            p_sum += row.get("c1_pressure");
            ++n;
          }
      }
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("volume: largest constraint error %s 1e-13, largest "
                  "volume error in history.csv %s 1e-9\n",
                  worst_constraint <= 1e-13 ? "below" : "ABOVE",
                  worst_volume <= 1e-9 ? "below" : "ABOVE");
    bool         ok = worst_constraint <= 1e-13 && worst_volume <= 1e-9;
    const double l  = std::cbrt(1.331);
    ok = pneuma_test::check("volume: mean pressure for t >= 0.03 s [Pa]",
                            p_sum / n,
                            2. * mu * H / R * (1. / l - std::pow(l, -7.)),
                            1e-2)
         && ok;
    return print(balance(r) <= 1e-3,
                 "volume: energy balance within 1e-3 at every row")
           && ok;
  }

  bool
  liquid_filling()
  {
    pneuma_test::Settings s = sphere();
    s.push_back({"Chambers/Chamber 1/Filling", "liquid and gas"});
    s.push_back({"Chambers/Chamber 1/Gas/Control", "gas amount"});
    s.push_back({"Chambers/Chamber 1/Gas/Gas amount/Function expression",
                 "1 + 0.4765*min(t, 1)"});
    s.push_back({"Chambers/Chamber 1/Liquid/Volume/Function expression",
                 "0.5*" + ramp("1")});
    s.push_back({"Load stepping/Stage end times", "1, 1.03"});
    s.push_back({"Load stepping/Strategy", "static, explicit"});
    s.push_back({"Explicit dynamics/Output interval", "5e-4"});
    const auto r = pneuma_test::run(s);
    if (!print(r.exit_code == 0, "liquid: the run finishes"))
      return false;
    double worst = 0.;
    for (const auto &row : r.history)
      {
        const double t = row.get("time") - 1.;
        const double V_t =
          t < 0. ? 0.
                 : 0.5
                     * (t < 0.02 ? std::pow(t / 0.02, 2) * (3. - 2. * t / 0.02)
                                 : 1.);
        worst = std::max(worst, std::abs(row.get("c1_liquid_volume") - V_t));
      }
    bool ok = print(worst <= 0.5e-9,
                    "liquid: the liquid volume follows its curve at every "
                    "row (1e-9)");
    return print(balance(r) <= 1e-3,
                 "liquid: energy balance within 1e-3 at every row")
           && ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = prescribed_volume();
  ok                                          = liquid_filling() && ok;
  print(ok, "all checks passed");
  return ok ? 0 : 1;
}
