// Path following through a limit point (solvers/path_following.h): the
// incompressible neo-Hookean sphere (R = 1 m, H = 1 mm, mu = 1 MPa, Q2 on
// 3 refinements) under a prescribed chamber pressure p = 2000 t Pa, so that
// p R/(mu H) = 2 t on the exact path p R/(mu H) = 2 (1/l - 1/l^7), whose
// pressure peaks at p_max R/(mu H) = 1.239463 at l = 7^(1/6) = 1.383088.
// Load control cannot pass the peak; arc-length control (cylindrical and
// spherical constraints) follows the path from l = 1.017 (t = 0.1, load
// control) to the target l = 3 (pole displacement 2 m), where the load
// factor has fallen back to t = 0.329.
//  - every converged state lies on the exact path: |2 t - f(l)|/f(l)
//    <= 0.5 %;
//  - the last state is at the target l = 3;
//  - the limit point is detected by the stability count (0 -> 1 under
//    prescribed pressure), classified as a limit point (the load factor
//    peaks in the final bracket) and located within 0.5 % in l and in p;
//  - Newton's rate on the bordered system is quadratic (order >= 1.8 in
//    every path-controlled step of a pressurised disc, under arc-length
//    and under displacement control, which ends at its target exactly);
//  - the Jacobian of the bordered system (the load-factor column by the
//    residual's difference quotient, the constraint row) matches central
//    differences of the bordered residual.

#include "test_tools.h"

#include <cmath>

namespace
{
  const double l_crit = std::pow(7., 1. / 6.);

  double
  f(const double l)
  {
    return 2. * (1. / l - 1. / std::pow(l, 7));
  }

  pneuma_test::Settings
  settings(const std::string &constraint)
  {
    pneuma_test::Settings s = pneuma_test::neo_hookean_sphere_chamber();
    s.push_back({"Chambers/Chamber 1/Gas/Control", "pressure"});
    s.push_back(
      {"Chambers/Chamber 1/Gas/Pressure/Function expression", "2000*t"});
    s.push_back({"Load stepping/Stage end times", "0.1, 1"});
    s.push_back({"Load stepping/Control", "load, arc-length"});
    s.push_back({"Load stepping/Initial increment", "0.05"});
    s.push_back({"Load stepping/Maximum increment", "1"});
    s.push_back({"Load stepping/Path following/Constraint", constraint});
    s.push_back({"Load stepping/Path following/Target monitor value", "2"});
    s.push_back({"Output/Monitor points", "0,0,1"});
    s.push_back({"Stability/Check inertia", "true"});
    s.push_back({"Output/Directory", "output-path-" + constraint});
    return s;
  }

  bool
  follow(const std::string &constraint)
  {
    const unsigned int root =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const pneuma::RunResult s  = pneuma_test::run(settings(constraint));
    bool                    ok = s.exit_code == 0;
    if (root == 0)
      std::printf("%s: exit code %d, %zu states\n",
                  constraint.c_str(),
                  s.exit_code,
                  s.history.size() - 1);
    // Every state on the exact path.
    double       worst = 0., worst_l = 0.;
    unsigned int past = 0;
    for (unsigned int k = 1; k < s.history.size(); ++k)
      {
        const double l   = 1. + s.history[k].get("m0_u_z");
        const double t   = s.history[k].get("time");
        const double err = std::abs(2. * t - f(l)) / f(l);
        if (err > worst)
          {
            worst   = err;
            worst_l = l;
          }
        if (l > l_crit)
          ++past;
      }
    if (root == 0)
      std::printf("%s: %u states past l = 7^(1/6); worst deviation from "
                  "p R/(mu H) = 2 (1/l - 1/l^7): %.1e at l = %.3f "
                  "(tolerance 5.0e-03) %s\n",
                  constraint.c_str(),
                  past,
                  worst,
                  worst_l,
                  worst <= 5e-3 ? "PASS" : "FAIL");
    ok = ok && worst <= 5e-3 && past >= 3;
    ok = pneuma_test::check(constraint + ": final stretch",
                            1. + s.get("m0_u_z"),
                            3.,
                            1e-6)
         && ok;
    // The limit point.
    const auto &summary = s.summary;
    if (summary.has("cp1_time"))
      {
        const bool limit = summary.get("cp1_limit_point") == 1.;
        if (root == 0)
          std::printf("%s: critical point 1 is %s (reference: a limit "
                      "point) %s\n",
                      constraint.c_str(),
                      limit ? "a limit point" : "a bifurcation",
                      limit ? "PASS" : "FAIL");
        ok = ok && limit;
        ok = pneuma_test::check(constraint + ": stretch at the limit point",
                                1. + summary.get("cp1_monitor"),
                                l_crit,
                                5e-3)
             && ok;
        ok = pneuma_test::check(constraint + ": p R/(mu H) at the limit point",
                                2. * summary.get("cp1_time"),
                                f(l_crit),
                                5e-3)
             && ok;
      }
    else
      {
        if (root == 0)
          std::printf("%s: no critical point reported FAIL\n",
                      constraint.c_str());
        ok = false;
      }
    return ok;
  }
  /**
   * Newton's rate on the bordered system: the pressurised flat disc of
   * tangent_and_newton (p = 1e4 t Pa), loaded to t = 0.25, then by
   * @p control with a residual tolerance of 1e-12 until the centre has
   * risen 12 mm. The order log(r_{k+1}/r_0)/log(r_k/r_0) of the last
   * iteration above round-off, over the path-controlled steps.
   */
  bool
  rate(const std::string &control)
  {
    const auto s = pneuma_test::run(
      {{"Geometry/Type", "disc"},
       {"Geometry/disc/Radius", "0.1425"},
       {"Geometry/Global refinements", "3"},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
        "3.11488e8"},
       {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.34"},
       {"Loads/Pressure/Function expression", "1e4*t"},
       {"Boundary conditions/Fixed boundaries", "0: xyz"},
       {"Load stepping/Stage end times", "0.25, 1"},
       {"Load stepping/Control", "load, " + control},
       {"Load stepping/Initial increment", "0.1"},
       {"Load stepping/Path following/Target monitor value", "0.012"},
       {"Output/Monitor points", "0,0,0"},
       {"Newton/Residual tolerance", "1e-12"},
       {"Output/Directory", "output-rate-" + control}});
    double       worst = 10.;
    unsigned int steps = 0;
    for (unsigned int n = 1; n < s.residual_histories.size(); ++n)
      {
        const auto &r     = s.residual_histories[n];
        double      order = 0.;
        for (unsigned int k = 1; k + 1 < r.size(); ++k)
          if (r[k + 1] / r[0] > 1e-11 && r[k] / r[0] < 1e-1)
            order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
        if (order > 0.)
          {
            worst = std::min(worst, order);
            ++steps;
          }
      }
    const bool ok = s.exit_code == 0 && steps > 0 && worst >= 1.8;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s control: %zu steps, %u with an observable rate; lowest "
                  "order %.1f (reference 2, at least 1.8) %s\n",
                  control.c_str(),
                  s.residual_histories.size(),
                  steps,
                  worst,
                  ok ? "PASS" : "FAIL");
    return pneuma_test::check(control + " control: centre rise at the end",
                              s.get("m0_u_z"),
                              0.012,
                              1e-8)
           && ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = follow("cylindrical");
  ok                                          = follow("spherical") && ok;
  ok                                          = rate("arc-length") && ok;
  ok                                          = rate("displacement") && ok;

  // The bordered Jacobian against central differences, on the inflated
  // sphere state family of the chamber consistency test.
  auto simulator = pneuma_test::make(settings("spherical"));
  // (The step 1e-7 keeps the truncation error of the differences, which
  // scales as h^2 at this large perturbation, below the tolerance.)
  const double error = simulator->check_tangent(0.5, 0.05, 1e-7, true).first;
  const double plain = simulator->check_tangent(0.5, 0.05, 1e-7).first;
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("bordered arc-length Jacobian: relative difference to "
                "central differences %.1e (the field tangent alone %.1e; "
                "tolerance 1.0e-06) %s\n",
                error,
                plain,
                error <= 1e-6 ? "PASS" : "FAIL");
  ok = ok && error <= 1e-6;
  return ok ? 0 : 1;
}
