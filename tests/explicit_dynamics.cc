// Explicit dynamics by central differences (strategies/explicit_dynamics,
// doc/theory.md "Explicit dynamics"), on 1 and 2 ranks, on the
// pretensioned square membrane of tests/eigen_analysis (side a = 1 m,
// h = 1 mm, St. Venant-Kirchhoff E = 1 MPa, nu = 0.3, rho = 1000 kg/m^3,
// edges pulled out by 1 %: N = E h/(1 - nu) ((1.01^2 - 1)/2); Q2 on 4 x 4
// cells). Stage 1 pulls the edges, stage 2 loads it by a pressure rising
// to 1 Pa (both static); at t = 2 the pressure is released and stage 3
// (explicit) lets it vibrate. The monitor at (1/6, 1/6) (snapped to the
// vertex (1/4, 1/4)) lies near the nodal lines of the (1,3) and (3,1)
// modes, which the static shape holds by 1/15 each:
//  - undamped, 20 periods: the period (a straight line fitted through the
//    zero crossings of the monitor's motion) against the closed form of
//    the (1,1) mode, f = sqrt(N/(rho h)) sqrt(2)/(2a) (0.5 %); the energy
//    balance T + W = 0 (W: the work of the residual forces) within 1e-3
//    of the largest energy at every row;
//  - mass-proportional damping of ratio 0.05 at the lowest natural
//    frequency, which the run finds by a modal analysis of the state at
//    t = 2 (Damping frequency = 0): that frequency against the closed form
//    f (0.5 %; here the pressure is 0.01 Pa: the 5 mm sag of 1 Pa adds
//    0.85 % to f);
//    every mode decays as exp(-alpha t/2), alpha = 2 zeta omega; the mean
//    ratio of successive maxima of the monitor against exp(-alpha T_d/2)
//    with the run's alpha (2 %);
//  - at every explicit row of both runs and of a run whose explicit stage
//    moves the pulled edges up and down by 1 cm (moving supports): the
//    reactions, the applied loads, the inertial forces -M a and the
//    damping forces -alpha M v balance along each axis, |sum| below 1e-8
//    of the largest of them (static rows balance to Newton's tolerance;
//    the internal forces are self-equilibrated and the reactions come
//    from the same residual); the shaken run's energy balance T + W = 0
//    within 1e-3 of its largest kinetic energy (W holds the supports'
//    work: 5.7e-5 here, O(dt^2));
//  - a Time step above the stable estimate is refused naming the entry
//    (exit 1).

#include "test_tools.h"
#include "vibration.h"

#include <pneuma/core/input_error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  constexpr double E = 1e6, nu = 0.3, h = 1e-3, rho = 1000., eps = 0.01;
  const double     N = E * h / (1. - nu) * ((1. + eps) * (1. + eps) - 1.) / 2.;
  const double     frequency = std::sqrt(N / (rho * h)) * std::sqrt(2.) / 2.;

  pneuma_test::Settings
  vibrating_square(const double damping_ratio,
                   const double end,
                   const double pressure = 1.)
  {
    const std::string e = pneuma_test::number(eps);
    return {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "2"},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Thickness", pneuma_test::number(h)},
      {"Materials/Region 0/Density", pneuma_test::number(rho)},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
       pneuma_test::number(E)},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio",
       pneuma_test::number(nu)},
      {"Boundary conditions/Prescribed displacement boundaries", "0, 1, 2, 3"},
      {"Boundary conditions/Prescribed displacement/Function expression",
       e + "*x*min(t, 1); " + e + "*y*min(t, 1); 0"},
      {"Loads/Pressure/Function expression",
       "if(t <= 2, " + pneuma_test::number(pressure) + "*max(t - 1, 0), 0)"},
      {"Load stepping/Stage end times", "1, 2, " + pneuma_test::number(end)},
      {"Load stepping/Strategy", "static, static, explicit"},
      {"Explicit dynamics/Output interval", "0.01"},
      {"Explicit dynamics/Damping ratio", pneuma_test::number(damping_ratio)},
      {"Explicit dynamics/Damping frequency", "0"},
      {"Output/Monitor points", "0.1666666666666667, 0.1666666666666667, 0"}};
  }

  struct Signal
  {
    std::vector<double> t, u;
  };

  /// The monitor's normal displacement in the free vibration (t > 2).
  Signal
  centre(const pneuma::RunResult &s)
  {
    Signal c;
    for (const auto &row : s.history)
      if (row.get("time") > 2.)
        {
          c.t.push_back(row.get("time"));
          c.u.push_back(row.get("m0_u_z"));
        }
    return c;
  }

  bool
  print(const bool ok, const std::string &what)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: %s\n", what.c_str(), ok ? "yes" : "NO");
    return ok;
  }

  /// The resultant forces at every explicit row of @p s (after
  /// @p explicit_from) balance (see the top).
  bool
  forces_balance(const pneuma::RunResult &s,
                 const std::string       &name,
                 const double             explicit_from)
  {
    double worst = 0., largest = 0.;
    for (const auto &row : s.history)
      for (unsigned int c = 0; c < 3 && row.get("time") > explicit_from; ++c)
        {
          double sum = 0.;
          for (const char *f :
               {"reaction", "applied_load", "inertial_force", "damping_force"})
            if (row.has(f))
              {
                const double v = row.get_vector(f)[c];
                sum += v;
                largest = std::max(largest, std::abs(v));
              }
          worst = std::max(worst, std::abs(sum));
        }
    const bool ok = largest > 0. && worst < 1e-8 * largest;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: |reaction + load + inertia + damping| below 1e-8 of "
                  "the largest term at every row: %s\n",
                  name.c_str(),
                  ok ? "yes" : "NO");
    return ok;
  }

  /// |T + W| at every row against the largest kinetic energy.
  bool
  energy_balance(const pneuma::RunResult &s, const std::string &name)
  {
    double worst = 0., largest = 0.;
    for (const auto &row : s.history)
      {
        worst   = std::max(worst,
                         std::abs(row.get("kinetic_energy")
                                  + row.get("residual_work")));
        largest = std::max(largest, row.get("kinetic_energy"));
      }
    return print(worst < 1e-3 * largest,
                 name + ": energy balance within 1e-3 at every row");
  }

  bool
  undamped()
  {
    const auto s = pneuma_test::run(vibrating_square(0., 9.5));
    if (!print(s.exit_code == 0, "undamped: the run finishes"))
      return false;
    const auto z  = pneuma_test::crossings(s, "m0_u_z", 0., 2.);
    bool       ok = print(z.size() >= 30, "undamped: at least 15 periods");
    ok            = pneuma_test::check("undamped: period of the (1,1) mode [s]",
                            pneuma_test::period(z),
                            1. / frequency,
                            5e-3)
         && ok;
    ok = energy_balance(s, "undamped") && ok;
    return forces_balance(s, "undamped", 2.) && ok;
  }

  bool
  damped()
  {
    const double zeta = 0.05;
    const auto   s    = pneuma_test::run(vibrating_square(zeta, 4.5, 0.01));
    if (!print(s.exit_code == 0, "damped: the run finishes"))
      return false;
    // Successive maxima of the monitor's displacement.
    const Signal        c = centre(s);
    std::vector<double> peak_t, peak_u;
    for (unsigned int i = 1; i + 1 < c.u.size(); ++i)
      if (c.u[i] > c.u[i - 1] && c.u[i] >= c.u[i + 1] && c.u[i] > 0.)
        {
          peak_t.push_back(c.t[i]);
          peak_u.push_back(c.u[i]);
        }
    if (!print(peak_u.size() >= 3, "damped: at least 3 peaks"))
      return false;
    const double f_run = s.get("damping_frequency");
    bool         ok    = pneuma_test::check(
      "damped: lowest natural frequency at t = 2 (modal analysis) [Hz]",
      f_run,
      frequency,
      5e-3);
    const unsigned int n     = peak_u.size() - 1;
    const double       alpha = 4. * M_PI * zeta * f_run;
    const double       decay = std::pow(peak_u[n] / peak_u[0], 1. / n);
    const double       T_d   = (peak_t[n] - peak_t[0]) / n;
    ok = pneuma_test::check("damped: amplitude ratio per period",
                            decay,
                            std::exp(-0.5 * alpha * T_d),
                            2e-2)
         && ok;
    return forces_balance(s, "damped", 2.) && ok;
  }

  /// The edges, pulled out by 1 % (static, t <= 1), move up and down by
  /// 1 cm, u_z = 0.005 (1 - cos(2 pi (t - 1))), in the explicit stage.
  bool
  shaken()
  {
    pneuma_test::Settings settings = vibrating_square(0., 2.);
    const std::string     e        = pneuma_test::number(eps);
    for (auto &[entry, value] : settings)
      if (entry
          == "Boundary conditions/Prescribed displacement/Function "
             "expression")
        value = e + "*x*min(t, 1); " + e
                + "*y*min(t, 1); if(t <= 1, 0, 0.005*(1 - "
                  "cos(6.283185307179586*(t - 1))))";
      else if (entry == "Loads/Pressure/Function expression")
        value = "0";
      else if (entry == "Load stepping/Stage end times")
        value = "1, 2";
      else if (entry == "Load stepping/Strategy")
        value = "static, explicit";
    const auto s = pneuma_test::run(settings);
    if (!print(s.exit_code == 0, "shaken: the run finishes"))
      return false;
    bool ok = energy_balance(s, "shaken");
    return forces_balance(s, "shaken", 1.) && ok;
  }

  bool
  too_large_step()
  {
    pneuma_test::Settings s = pneuma_test::quiet();
    for (const auto &e : vibrating_square(0., 2.5))
      s.push_back(e);
    s.push_back({"Explicit dynamics/Time step", "0.01"});
    // The simulator outlives the exception (its timers print nothing).
    const auto  simulator = pneuma_test::make(s);
    std::string what;
    try
      {
        simulator->run();
      }
    catch (const pneuma::InputError &e)
      {
        what = e.what();
      }
    return print(what.find("Explicit dynamics/Time step: the time step 0.01 s "
                           "is above the stable step")
                   != std::string::npos,
                 "a time step above the stable one is refused");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = undamped();
  ok                                          = damped() && ok;
  ok                                          = shaken() && ok;
  ok                                          = too_large_step() && ok;
  print(ok, "all checks passed");
  return ok ? 0 : 1;
}
