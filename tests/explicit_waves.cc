// Explicit dynamics (strategies/explicit_dynamics, doc/theory.md "Explicit
// dynamics") of cables and of a gas chamber, on 1 and 2 ranks:
//  - a taut string (cable element, L = 1 m, a = 1 mm, E = 1 GPa,
//    rho = 1000 kg/m^3, prestress T = 100 N, 64 elements) released from
//    the static shape under q = sin(pi x/L) N/m: the period of its motion
//    against the closed form 2 L/c and against the modal analysis of the
//    same model (0.5 %). The density is that of the unstressed cable, so
//    the mass per length of the stretched one is mu = rho A/(1 + T/(E A))
//    and c = sqrt(T/mu);
//  - a pulse in the same string (256 elements, straight at rest): a load
//    concentrated at x = L/4 and in time at t0 sends two pulses out; the
//    mid-point's displacement rises to half its plateau when the first
//    arrives (t0 + L/(4c)) and falls back through it when the second,
//    reflected at the fixed end, arrives (t0 + 3L/(4c)): both speeds
//    against c (0.5 %);
//  - a sealed gas sphere's breathing: an incompressible neo-Hookean
//    sphere (R = 1 m, H = 1 mm, mu = 20 MPa, rho = 1000 kg/m^3, Q2 on two
//    refinements) inflated by a sealed amount of adiabatic air
//    (kappa = 1.4) to the stretch l (about 1.1), pushed by 500 Pa more and
//    released. For a uniform radius r = l R the membrane force is
//    N = mu H (1 - l^-6) (p = 2N/r), the gas follows p_abs V^kappa = const,
//    and the stiffness of the radius is
//      K = 12 pi kappa p_abs r + 8 pi r dN/dr - 8 pi N
//    (gas, membrane, follower pressure) against the mass 4 pi R^2 rho H:
//    the period 2 pi sqrt(M/K) against the one of the run (0.5 %).

#include "test_tools.h"
#include "vibration.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  constexpr double L = 1., a = 1e-3, E = 1e9, rho = 1000., T = 100.;
  const double     A     = M_PI * a * a;
  const double     speed = std::sqrt(T * (1. + T / (E * A)) / (rho * A));

  pneuma_test::Settings
  string(const unsigned int n_elements, const std::string &load)
  {
    return {{"Geometry/Type", "none"},
            {"Cables/Number of cables", "1"},
            {"Cables/Cable 1/Element", "cable"},
            {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
            {"Cables/Cable 1/Number of elements", std::to_string(n_elements)},
            {"Cables/Cable 1/Section semi-axes", pneuma_test::number(a)},
            {"Cables/Cable 1/Young's modulus", pneuma_test::number(E)},
            {"Cables/Cable 1/Density", pneuma_test::number(rho)},
            {"Cables/Cable 1/Prestress force", pneuma_test::number(T)},
            {"Cables/Cable 1/Start support", "fixed"},
            {"Cables/Cable 1/End support", "fixed"},
            {"Cables/Cable 1/Distributed load/Function expression",
             "0; 0; " + load}};
  }

  bool
  print(const bool ok, const std::string &what)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: %s\n", what.c_str(), ok ? "yes" : "NO");
    return ok;
  }

  bool
  string_period()
  {
    pneuma_test::Settings s = string(64, "if(t <= 1, sin(pi*x), 0)");
    pneuma_test::Settings m = s;
    s.push_back({"Load stepping/Stage end times", "1, 1.12"});
    s.push_back({"Load stepping/Strategy", "static, explicit"});
    s.push_back({"Explicit dynamics/Output interval", "2e-4"});
    const auto r = pneuma_test::run(s);
    m.push_back({"Eigen analysis/Type", "modal"});
    m.push_back({"Eigen analysis/Number of modes", "2"});
    const auto modal = pneuma_test::run(m);
    if (!print(r.exit_code == 0 && modal.exit_code == 0,
               "string: the runs finish"))
      return false;
    const auto   z     = pneuma_test::crossings(r, "cable1_mid_u_z", 0., 1.);
    bool         ok    = print(z.size() >= 18, "string: at least 9 periods");
    const double value = pneuma_test::period(z);
    ok                 = pneuma_test::check("string: period against 2L/c [s]",
                            value,
                            2. * L / speed,
                            5e-3)
         && ok;
    return pneuma_test::check("string: period against the modal analysis [s]",
                              value,
                              1. / modal.get("mode1_frequency"),
                              5e-3)
           && ok;
  }

  /// Mass scaling to twice the automatic step: every interior node's
  /// row bound is the same (the axial stiffness governs), so each gets 4
  /// times its mass in all three directions (the two next to the supports
  /// 3 times: their rows miss a neighbour), and the transverse period
  /// doubles.
  bool
  string_mass_scaling()
  {
    const auto with = [](const std::string &end) {
      pneuma_test::Settings s = string(64, "if(t <= 1, sin(pi*x), 0)");
      s.push_back({"Load stepping/Stage end times", "1, " + end});
      s.push_back({"Load stepping/Strategy", "static, explicit"});
      s.push_back({"Explicit dynamics/Output interval", "2e-4"});
      return s;
    };
    const auto   plain = pneuma_test::run(with("1.12"));
    const double step  = 0.9 * plain.history.back().get("stable_time_step");
    pneuma_test::Settings s = with("1.24");
    s.push_back({"Explicit dynamics/Mass scaling time step",
                 pneuma_test::number(2. * step)});
    const auto scaled = pneuma_test::run(s);
    if (!print(plain.exit_code == 0 && scaled.exit_code == 0,
               "mass scaling: the runs finish"))
      return false;
    bool ok =
      pneuma_test::check("mass scaling: added mass fraction",
                         scaled.history.back().get("added_mass_fraction"),
                         (61. * 3. + 2. * 2.) / 63.,
                         1e-3);
    ok = pneuma_test::check("mass scaling: the step reached [s]",
                            0.9 * scaled.history.back().get("stable_time_step"),
                            2. * step,
                            1e-6)
         && ok;
    return pneuma_test::check(
             "mass scaling: period over the unscaled one",
             pneuma_test::period(
               pneuma_test::crossings(scaled, "cable1_mid_u_z", 0., 1.)),
             2.
               * pneuma_test::period(
                 pneuma_test::crossings(plain, "cable1_mid_u_z", 0., 1.)),
             5e-3)
           && ok;
  }

  bool
  string_pulse()
  {
    const double t0 = 5e-4;
    const auto   r  = pneuma_test::run([&] {
      auto s = string(256,
                      "10*exp(-((x - 0.25)/0.02)^2 - ((t - "
                        + pneuma_test::number(t0) + ")/1e-4)^2)");
      s.push_back({"Load stepping/Stage end times", "0.0055"});
      s.push_back({"Load stepping/Strategy", "explicit"});
      s.push_back({"Explicit dynamics/Output interval", "2e-5"});
      return s;
    }());
    if (!print(r.exit_code == 0, "pulse: the run finishes"))
      return false;
    double plateau = 0.;
    for (const auto &row : r.history)
      plateau = std::max(plateau, row.get("cable1_mid_u_z"));
    const auto z =
      pneuma_test::crossings(r, "cable1_mid_u_z", 0.5 * plateau, 0.);
    if (!print(z.size() == 2, "pulse: the mid-point rises and falls once"))
      return false;
    bool ok = pneuma_test::check("pulse: speed to the mid-point [m/s]",
                                 0.25 * L / (z[0] - t0),
                                 speed,
                                 5e-3);
    return pneuma_test::check("pulse: speed of the reflected pulse [m/s]",
                              0.75 * L / (z[1] - t0),
                              speed,
                              5e-3)
           && ok;
  }

  bool
  breathing_sphere()
  {
    const double R = 1., H = 1e-3, mu = 2e7, density = 1000., kappa = 1.4;
    const auto   r = pneuma_test::run(
      {{"Geometry/Type", "sphere"},
         {"Geometry/sphere/Radius", pneuma_test::number(R)},
         {"Geometry/Global refinements", "2"},
         {"Discretisation/Polynomial degree", "2"},
         {"Materials/Region 0/Law", "neo-Hookean"},
         {"Materials/Region 0/Thickness", pneuma_test::number(H)},
         {"Materials/Region 0/Density", pneuma_test::number(density)},
         {"Materials/Region 0/neo-Hookean/Shear modulus",
          pneuma_test::number(mu)},
         {"Boundary conditions/Fixed points",
          "0,0,1: xy; 0,0,-1: xy; 1,0,0: yz; -1,0,0: yz"},
         {"Chambers/Number of chambers", "1"},
         {"Chambers/Chamber 1/Regions", "0"},
         {"Chambers/Chamber 1/Gas/Control", "gas amount"},
         {"Chambers/Chamber 1/Gas/adiabatic/Exponent",
          pneuma_test::number(kappa)},
         {"Chambers/Chamber 1/Gas/Gas amount/Function expression",
          "1 + 0.4765*min(t, 1)"},
         {"Loads/Pressure/Function expression",
          "if(t <= 2, 500*max(t - 1, 0), 0)"},
         {"Load stepping/Stage end times", "1, 2, 2.05"},
         {"Load stepping/Strategy", "static, static, explicit"},
         {"Load stepping/Initial increment", "0.25"},
         {"Explicit dynamics/Output interval", "2e-4"}});
    if (!print(r.exit_code == 0, "sphere: the run finishes"))
      return false;
    // The equilibrium the sphere breathes about: the end of stage 1.
    const pneuma::Statistics *inflated = nullptr;
    for (const auto &row : r.history)
      if (row.get("time") == 1.)
        inflated = &row;
    if (!print(inflated != nullptr, "sphere: a row at t = 1"))
      return false;
    const double V  = inflated->get("c1_volume");
    const double l  = std::cbrt(V / r.history.front().get("c1_volume"));
    const double N  = mu * H * (1. - std::pow(l, -6.));
    const double p  = inflated->get("c1_pressure");
    bool         ok = pneuma_test::check("sphere: gauge pressure against 2N/r",
                                 p,
                                 2. * N / (l * R),
                                 1e-3);
    const double p_abs = inflated->get("c1_absolute_pressure");
    const double K     = 12. * M_PI * kappa * p_abs * l * R
                     + 48. * M_PI * mu * H * std::pow(l, -6.) - 8. * M_PI * N;
    const double M = 4. * M_PI * R * R * density * H;
    const auto   z = pneuma_test::crossings(r, "c1_volume", V, 2.);
    ok             = print(z.size() >= 10, "sphere: at least 5 periods") && ok;
    return pneuma_test::check("sphere: breathing period [s]",
                              pneuma_test::period(z),
                              2. * M_PI * std::sqrt(M / K),
                              5e-3)
           && ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = string_period();
  ok                                          = string_mass_scaling() && ok;
  ok                                          = string_pulse() && ok;
  ok                                          = breathing_sphere() && ok;
  print(ok, "all checks passed");
  return ok ? 0 : 1;
}
