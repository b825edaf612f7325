// Eigen analysis of converged states (solvers/eigen_analysis.h,
// doc/verification.md "Eigen analysis"):
//  - modal, a taut string: a tension-only cable (L = 1 m, T = 1 kN, steel
//    rod of radius 5 mm) between fixed ends; its transverse frequencies
//    f_n = n/(2L) sqrt(T/(rho A)), each twice (two planes), on 20 and 40
//    elements: within 0.5 % on 40 and of order 2 (consistent linear mass:
//    f_h/f = 1 + (n pi h/L)^2/24 + ...);
//  - modal, a pretensioned square membrane: side a = 1 m, h = 1 mm,
//    St. Venant-Kirchhoff E = 1 MPa, nu = 0.3, rho = 1000 kg/m^3, its edges
//    pulled out by 1 % in both directions: the isotropic membrane force
//    N = E h/(1 - nu) ((1.01^2 - 1)/2) (per reference length, with the
//    reference mass rho h) gives f_mn = (1/2) sqrt(N/(rho h))
//    sqrt(m^2 + n^2)/a; the first six modes (1,1), (1,2), (2,1), (2,2),
//    (1,3), (3,1) within 0.5 % (Q2, 8 x 8 cells);
//  - linear buckling, a cantilever column: a solid beam (circular section,
//    a = 10 mm, E = 200 GPa, nu = 0), clamped at x = 0, under an axial end
//    force P_ref t; the buckling analysis at t = 1 (P_ref = 1 kN) predicts
//    the critical time t + lambda with P_cr = pi^2 E I/(4 L^2) within 1 %,
//    the first two modes equal (a circular section buckles in any plane).
//  - tangent, the neo-Hookean balloon of V3 at l = 3, past its pressure
//    maximum at l = 7^(1/6): under prescribed pressure (reached by arc
//    length, parameter_files/sphere_arc_length.prm) the lowest eigenvalue
//    is negative and the only one below zero (the breathing mode; 1 by
//    Sylvester's count); sealed with its gas amount, the rank-one gas
//    term makes every eigenvalue positive (the chamber term in the
//    eigenproblem).
//  - modal, an inflated closed cylinder (R = 0.1 m, L = 2 m, h = 1 mm,
//    E = 1 GPa, nu = 0.3, rho = 1000 kg/m^3, p = 10 kPa, rigid massless end
//    plates on simple supports): the lowest bending frequency against the
//    inflated Timoshenko beam (bending E I = E pi R^3 h, shear kappa G A +
//    p pi R^2 with kappa = 1/2 for a thin tube's shear flow, rotary
//    inertia m R^2/2), within 1 %, and its effective mass 8/pi^2 of the
//    tube's within 2 %; with steel end plates the free plate's axial mode
//    on the tube (a rod with a tip mass: x tan x = m_tube/m_plate) within
//    1 %; the square membrane's (1,1) mode carries 64/pi^4 of its mass.
// Each case also checks ARPACK's residual and, for the shift-and-invert
// cases, that no eigenvalue lies below the shift (Sylvester's count from
// the same factorization).

#include "test_paths.h"
#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  /// Exit code, ARPACK's residual, and (shift-and-invert) no eigenvalue
  /// below the shift.
  bool
  common_checks(const pneuma::RunResult &s,
                const std::string       &name,
                const bool               count     = true,
                const double             tolerance = 1e-6)
  {
    const double residual = s.get("eigen_residual");
    const double below    = count ? s.get("eigen_below_shift") : 0.;
    const bool   ok = s.exit_code == 0 && residual < tolerance && below == 0.;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: exit code %d, largest relative residual of the modes "
                  "%s %.0e%s %s\n",
                  name.c_str(),
                  s.exit_code,
                  residual < tolerance ? "below" : "above",
                  tolerance,
                  count ? (below == 0. ? ", no eigenvalue below the shift"
                                       : ", eigenvalues below the shift")
                        : "",
                  ok ? "PASS" : "FAIL");
    return ok;
  }

  /// The taut string on @p n elements; returns the worst error of the
  /// first three transverse frequencies (each of the two planes).
  double
  string_error(const unsigned int n, bool &ok)
  {
    const double L = 1., T = 1e3, a = 5e-3, rho = 7850.;
    const double A         = M_PI * a * a,
                 f1        = 1. / (2. * L) * std::sqrt(T / (rho * A));
    const auto        s    = pneuma_test::run({
                {"Geometry/Type", "none"},
                {"Cables/Number of cables", "1"},
                {"Cables/Cable 1/Element", "cable"},
                {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
                {"Cables/Cable 1/Number of elements", std::to_string(n)},
                {"Cables/Cable 1/Section semi-axes",
                 pneuma_test::number(a) + ", " + pneuma_test::number(a)},
                {"Cables/Cable 1/Young's modulus", "2e11"},
                {"Cables/Cable 1/Density", pneuma_test::number(rho)},
                {"Cables/Cable 1/Prestress force", pneuma_test::number(T)},
                {"Cables/Cable 1/Start support", "fixed"},
                {"Cables/Cable 1/End support", "fixed"},
                {"Eigen analysis/Type", "modal"},
                {"Eigen analysis/Number of modes", "6"},
    });
    const std::string name = "string, " + std::to_string(n) + " elements";
    ok                     = common_checks(s, name) && ok;
    double worst           = 0.;
    for (unsigned int k = 1; k <= 6; ++k)
      {
        const double reference = f1 * ((k + 1) / 2);
        const double value = s.get("mode" + std::to_string(k) + "_frequency");
        worst              = std::max(worst, std::abs(value / reference - 1.));
        if (n == 40)
          ok = pneuma_test::check(name + ": f of mode " + std::to_string(k)
                                    + " [Hz]",
                                  value,
                                  reference,
                                  5e-3)
               && ok;
      }
    return worst;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  bool ok = true;

  // The taut string, and the order of its frequency error.
  {
    const double e20 = string_error(20, ok), e40 = string_error(40, ok);
    const double order = std::log2(e20 / e40);
    if (root)
      std::printf("string: worst frequency error %.2e (20 elements), %.2e "
                  "(40); order %.2f (reference 2, at least 1.9) %s\n",
                  e20,
                  e40,
                  order,
                  order > 1.9 ? "PASS" : "FAIL");
    ok = ok && order > 1.9;
  }

  // The pretensioned square membrane.
  {
    const double E = 1e6, nu = 0.3, h = 1e-3, rho = 1000., eps = 0.01, a = 1.;
    const double N = E * h / (1. - nu) * ((1. + eps) * (1. + eps) - 1.) / 2.;
    const double c = 0.5 * std::sqrt(N / (rho * h)) / a;
    const pneuma_test::Settings square = {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "3"},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Thickness", pneuma_test::number(h)},
      {"Materials/Region 0/Density", pneuma_test::number(rho)},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
       pneuma_test::number(E)},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio",
       pneuma_test::number(nu)},
      {"Boundary conditions/Prescribed displacement boundaries", "0, 1, 2, 3"},
      {"Boundary conditions/Prescribed displacement/Function expression",
       pneuma_test::number(eps) + "*x*t; " + pneuma_test::number(eps)
         + "*y*t; 0"},
      {"Eigen analysis/Type", "modal"},
      {"Eigen analysis/Number of modes", "6"},
    };
    const auto s = pneuma_test::run(square);
    ok           = common_checks(s, "square membrane") && ok;
    // The (1,1) mode carries 64/pi^4 of the membrane's mass rho h a^2.
    ok = pneuma_test::check("square membrane: effective mass of mode 1 [kg]",
                            s.get("mode1_effective_mass_z"),
                            64. / std::pow(M_PI, 4) * rho * h * a * a,
                            1e-2)
         && ok;
    // The same by the non-symmetric solver (Arnoldi on the LU): the same
    // frequencies.
    {
      pneuma_test::Settings n = square;
      n.push_back({"Eigen analysis/Solver", "non-symmetric"});
      const auto u     = pneuma_test::run(n);
      double     worst = 0.;
      for (unsigned int k = 1; k <= 6; ++k)
        {
          const std::string f = "mode" + std::to_string(k) + "_frequency";
          worst = std::max(worst, std::abs(u.get(f) / s.get(f) - 1.));
        }
      const bool same =
        u.exit_code == 0 && worst < 1e-8 && u.get("eigen_non_symmetric") == 1.;
      if (root)
        std::printf("square membrane, non-symmetric solver: largest relative "
                    "difference of the six frequencies %s 1e-08 %s\n",
                    worst < 1e-8 ? "below" : "above",
                    same ? "PASS" : "FAIL");
      ok = ok && same;
    }
    const double mn[6] = {2., 5., 5., 8., 10., 10.};
    for (unsigned int k = 1; k <= 6; ++k)
      ok = pneuma_test::check("square membrane: f of mode " + std::to_string(k)
                                + " [Hz]",
                              s.get("mode" + std::to_string(k) + "_frequency"),
                              c * std::sqrt(mn[k - 1]),
                              5e-3)
           && ok;
  }

  // The inflated closed cylinder: its lowest bending mode against the
  // inflated Timoshenko beam (doc/verification.md derives it).
  {
    const double E = 1e9, nu = 0.3, h = 1e-3, R = 0.1, L = 2., rho = 1000.,
                 p = 1e4;
    const double m = rho * h * 2. * M_PI * R, EI = E * M_PI * R * R * R * h;
    const double kGA =
      0.5 * E / (2. * (1. + nu)) * 2. * M_PI * R * h + p * M_PI * R * R;
    const double k = M_PI / L, rI = m * R * R / 2.;
    const double A = rI * m / kGA, B = m + rI * k * k + m * EI * k * k / kGA,
                 C = EI * k * k * k * k;
    const double f_beam =
      std::sqrt((B - std::sqrt(B * B - 4. * A * C)) / (2. * A)) / (2. * M_PI);
    pneuma_test::Settings c = {
      {"Geometry/Type", "closed cylinder"},
      {"Geometry/Global refinements", "2"},
      {"Geometry/closed cylinder/Radius", pneuma_test::number(R)},
      {"Geometry/closed cylinder/Length", pneuma_test::number(L)},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Thickness", pneuma_test::number(h)},
      {"Materials/Region 0/Density", pneuma_test::number(rho)},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
       pneuma_test::number(E)},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio",
       pneuma_test::number(nu)},
      {"Loads/Pressure/Function expression", pneuma_test::number(p) + "*t"},
      {"Boundary conditions/Rigid regions", "1, 2"},
      {"Boundary conditions/Fixed points",
       "0,0,0: xyz; 2,0,0: yz; 0.05,0,0.1: y"},
      {"Eigen analysis/Type", "modal"},
      {"Eigen analysis/Number of modes", "4"}};
    for (const std::string r : {"1", "2"})
      {
        c.push_back({"Materials/Region " + r + "/Thickness", "1e-2"});
        c.push_back(
          {"Materials/Region " + r + "/Saint Venant-Kirchhoff/Young's modulus",
           "2.1e11"});
      }
    const auto s = pneuma_test::run(c);
    ok           = common_checks(s, "inflated cylinder") && ok;
    // The bending mode in z: the one with the largest effective mass
    // along z (the torsion support at (0.05, 0, R) holds y, not z).
    unsigned int bending = 1;
    for (unsigned int k = 2; k <= 4; ++k)
      if (s.get("mode" + std::to_string(k) + "_effective_mass_z")
          > s.get("mode" + std::to_string(bending) + "_effective_mass_z"))
        bending = k;
    const std::string mode = "mode" + std::to_string(bending);
    ok = pneuma_test::check("inflated cylinder: bending frequency [Hz]",
                            s.get(mode + "_frequency"),
                            f_beam,
                            1e-2)
         && ok;
    ok = pneuma_test::check("inflated cylinder: its effective mass [kg]",
                            s.get(mode + "_effective_mass_z"),
                            8. / (M_PI * M_PI) * m * L,
                            2e-2)
         && ok;

    // Steel end plates (7850 kg/m^3, 1 cm): the plate at x = L, free
    // along the axis, is a tip mass on the tube's axial rod (wave speed
    // c = sqrt(E/rho)): its axial mode has x tan(x) = m_tube/m_plate,
    // omega = x c/L. The plate's mass reaches the model through its rigid
    // constraint.
    for (const std::string r : {"1", "2"})
      c.push_back({"Materials/Region " + r + "/Density", "7850"});
    const auto   heavy   = pneuma_test::run(c);
    const double m_plate = 7850. * 1e-2 * M_PI * R * R, beta = m * L / m_plate;
    double       lo = 0., hi = M_PI / 2. - 1e-12;
    for (unsigned int k = 0; k < 200; ++k)
      {
        const double mid                       = 0.5 * (lo + hi);
        (mid * std::tan(mid) < beta ? lo : hi) = mid;
      }
    const double f_axial =
      0.5 * (lo + hi) * std::sqrt(E / rho) / L / (2. * M_PI);
    unsigned int axial = 1;
    for (unsigned int k = 2; k <= 4; ++k)
      if (heavy.get("mode" + std::to_string(k) + "_effective_mass_x")
          > heavy.get("mode" + std::to_string(axial) + "_effective_mass_x"))
        axial = k;
    ok = pneuma_test::check(
           "inflated cylinder with steel end plates: axial frequency [Hz]",
           heavy.get("mode" + std::to_string(axial) + "_frequency"),
           f_axial,
           1e-2)
         && ok;
  }

  // A non-symmetric tangent: a square membrane clamped on two edges under
  // follower pressure (the load stiffness on its free edges is not
  // symmetric). The automatic choice is Arnoldi on the LU, which also
  // counts the stability at every step; the symmetric solver on the upper
  // triangle is printed for comparison (it is 3 % off: the asymmetry,
  // 2.5e-6 of the whole tangent, is not small for the soft modes).
  {
    const pneuma_test::Settings open = {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "3"},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e8"},
      {"Loads/Pressure/Function expression", "1e3*t"},
      {"Boundary conditions/Fixed boundaries", "0: xyz; 1: xyz"},
      {"Eigen analysis/Type", "tangent"},
      {"Eigen analysis/Number of modes", "4"}};
    const auto a            = pneuma_test::run(open);
    auto       sym_settings = open;
    sym_settings.push_back({"Eigen analysis/Solver", "symmetric"});
    const auto b = pneuma_test::run(sym_settings);
    ok           = common_checks(a, "open square, non-symmetric", false) && ok;
    double worst = 0.;
    for (unsigned int k = 1; k <= 4; ++k)
      {
        const std::string v = "mode" + std::to_string(k) + "_eigenvalue";
        worst = std::max(worst, std::abs(a.get(v) / b.get(v) - 1.));
      }
    const bool chosen = a.get("eigen_non_symmetric") == 1.
                        && a.get("eigen_asymmetry") > 1e-8
                        && b.get("eigen_non_symmetric") == 0.;
    const bool stable =
      a.get("negative_eigenvalues") == 0. && a.get("mode1_eigenvalue") > 0.;
    if (root)
      std::printf("open square: asymmetry %s 1e-08, Arnoldi chosen: %s; "
                  "stable by the Arnoldi count at every step: %s %s\n"
                  "open square: the symmetric solver on the upper triangle "
                  "is %.1f %% off in the lowest four (why a non-symmetric "
                  "tangent is not solved as a symmetric one)\n",
                  a.get("eigen_asymmetry") > 1e-8 ? "above" : "below",
                  chosen ? "yes" : "no",
                  stable && a.get("unstable_steps") == 0. ? "yes" : "no",
                  chosen && stable ? "PASS" : "FAIL",
                  100. * worst);
    ok = ok && chosen && stable && a.get("unstable_steps") == 0.;
  }

  // Linear buckling of the cantilever column.
  {
    const double E = 2e11, a = 0.01, L = 1., P = 1e3;
    const double I    = M_PI * std::pow(a, 4) / 4.,
                 P_cr = M_PI * M_PI * E * I / (4. * L * L);
    const auto s      = pneuma_test::run({
           {"Geometry/Type", "none"},
           {"Cables/Number of cables", "1"},
           {"Cables/Cable 1/Element", "solid beam"},
           {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
           {"Cables/Cable 1/Number of elements", "16"},
           {"Cables/Cable 1/Section semi-axes",
            pneuma_test::number(a) + ", " + pneuma_test::number(a)},
           {"Cables/Cable 1/solid beam/Section axis", "0, 0, 1"},
           {"Cables/Cable 1/Young's modulus", pneuma_test::number(E)},
           {"Cables/Cable 1/solid beam/Poisson's ratio", "0"},
           {"Cables/Cable 1/Start support", "fixed"},
           {"Cables/Cable 1/End forces", "true"},
           {"Cables/Cable 1/End force/Function expression",
            pneuma_test::number(-P) + " * t; 0; 0"},
           {"Eigen analysis/Type", "buckling"},
           {"Eigen analysis/Number of modes", "2"},
    });
    ok                = common_checks(s, "cantilever column", false) && ok;
    for (unsigned int k = 1; k <= 2; ++k)
      ok = pneuma_test::check(
             "cantilever column: critical load of mode " + std::to_string(k)
               + " [N]",
             P * s.get("mode" + std::to_string(k) + "_critical_time"),
             P_cr,
             1e-2)
           && ok;
  }
  // The balloon past its pressure maximum: prescribed pressure against a
  // sealed gas amount.
  {
    pneuma_test::Settings quiet = pneuma_test::quiet();
    quiet.insert(quiet.end(),
                 {{"Eigen analysis/Type", "tangent"},
                  {"Eigen analysis/Number of modes", "3"},
                  {"Eigen analysis/Every step", "true"},
                  {"Output/Quiet", "true"},
                  {"Output/Write VTU", "false"},
                  {"Output/Directory", "output-eigen-pressure"}});
    const auto pressure =
      pneuma_test::make(quiet,
                        std::string(PNEUMA_SOURCE_DIR)
                          + "/parameter_files/sphere_arc_length.prm")
        ->run();
    pneuma_test::Settings gas = pneuma_test::neo_hookean_sphere_chamber();
    gas.insert(gas.end(),
               {{"Chambers/Chamber 1/Gas/Control", "gas amount"},
                {"Chambers/Chamber 1/Gas/Gas amount/Function expression",
                 pneuma_test::balloon_gas_amount()},
                {"Eigen analysis/Type", "tangent"},
                {"Eigen analysis/Number of modes", "3"},
                {"Output/Directory", "output-eigen-gas"}});
    const auto sealed = pneuma_test::run(gas);
    ok = common_checks(pressure, "balloon under pressure", false) && ok;
    ok = common_checks(sealed, "sealed balloon") && ok;
    const double l_p       = 1. + pressure.get("m0_u_z");
    const double below_p   = pressure.get("eigen_below_shift");
    const double lambda_p1 = pressure.get("mode1_eigenvalue");
    const double lambda_p2 = pressure.get("mode2_eigenvalue");
    const double lambda_g1 = sealed.get("mode1_eigenvalue");
    const bool pressure_ok = below_p == 1. && lambda_p1 < 0. && lambda_p2 > 0.;
    const bool gas_ok      = lambda_g1 > 0.;
    if (root)
      {
        std::printf("balloon at l = %.3f under pressure: eigenvalues below 0: "
                    "reference 1 value %g; lowest %.3e N/m, next %.3e N/m %s\n",
                    l_p,
                    below_p,
                    lambda_p1,
                    lambda_p2,
                    pressure_ok ? "PASS" : "FAIL");
        std::printf("sealed balloon at l = 3: lowest eigenvalue %.3e N/m "
                    "(reference: positive) %s\n",
                    lambda_g1,
                    gas_ok ? "PASS" : "FAIL");
      }
    ok = ok && pressure_ok && gas_ok;
    // Along the path: the lowest eigenvalue (ARPACK) is negative exactly
    // where the inertia (LDL^T) counts a negative eigenvalue.
    unsigned int states = 0, disagree = 0, negative = 0;
    for (unsigned int k = 1; k < pressure.history.size(); ++k)
      {
        const auto  &row    = pressure.history[k];
        const double count  = row.get("negative_eigenvalues");
        const double lowest = row.get("mode1_eigenvalue");
        ++states;
        negative += lowest < 0.;
        disagree += (lowest < 0.) != (count > 0.);
      }
    if (root)
      std::printf("balloon under pressure, every step: %u states, %u with a "
                  "negative lowest eigenvalue, %u where its sign and the "
                  "inertia disagree (reference 0) %s\n",
                  states,
                  negative,
                  disagree,
                  disagree == 0 && negative > 0 ? "PASS" : "FAIL");
    ok = ok && disagree == 0 && negative > 0 && states > 5;
  }
  return ok ? 0 : 1;
}
