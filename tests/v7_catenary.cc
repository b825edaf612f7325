// V7 catenary (doc/verification.md): span S = 10, unstressed length L = 12,
// weight w = 1 N/m. Inextensible (EA = 1e9 N): sag 2.923438, H 4.695415,
// T_max 7.618853. Elastic, EA = 1e4 N: H 4.685299, sag 2.929124 (Irvine's
// elastic catenary, Hooke's law on the engineering strain).
//
// The near-inextensible cable (EA = 1e5 N = 8000 times its weight; the
// extensibility changes H by 2e-4) starts stress-free on a circular arc of
// length 12 (nodes on the arc); its H and sag are compared with the
// inextensible values, and its convergence order with Irvine's elastic
// catenary for the same EA. The elastic one (EA = 1e4 N) starts stress-free as
// a V of length 12 between the supports, far from the answer (a mechanism: the
// pseudo-time continuation of Newton finds the hanging shape). The weight is a
// distributed load for the first and gravity on density * area for the second.
// Reported: H (support reaction), sag (the apex node), T_max (support force);
// errors and the observed order over 8, 16, 32, 64 linear elements.

#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  struct Result
  {
    double H, sag, T_max;
  };

  /// Polyline through n+1 points of the arc of length 12 over the span 10,
  /// or the V of length 12 (apex depth sqrt(11)); returns the apex depth.
  double
  reference_shape(const unsigned int n, const bool arc, std::string &points)
  {
    char buffer[128];
    if (!arc)
      {
        const double depth = std::sqrt(36. - 25.);
        std::snprintf(buffer,
                      sizeof buffer,
                      "0, 0, 0; 5, 0, %.15g; 10, 0, 0",
                      -depth);
        points = buffer;
        return depth;
      }
    // sin(theta)/theta = 10/12 by bisection; radius R = 6/theta.
    double lo = 1e-3, hi = M_PI / 2;
    for (unsigned int k = 0; k < 100; ++k)
      {
        const double mid                            = 0.5 * (lo + hi);
        (std::sin(mid) / mid > 10. / 12. ? lo : hi) = mid;
      }
    const double theta = 0.5 * (lo + hi), R = 6. / theta;
    const double zc = R * std::cos(theta); // centre above the chord
    points.clear();
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double phi = -theta + 2. * theta * i / n;
        std::snprintf(buffer,
                      sizeof buffer,
                      "%s%.15g, 0, %.15g",
                      i ? "; " : "",
                      5. + R * std::sin(phi),
                      zc - R * std::cos(phi));
        points += buffer;
      }
    return R - zc;
  }

  Result
  catenary(const unsigned int n_elements,
           const double       EA,
           const bool         by_gravity)
  {
    std::string  points;
    const double depth      = reference_shape(n_elements, !by_gravity, points);
    const double a          = 0.005; // section radius
    const double area       = M_PI * a * a;
    pneuma_test::Settings s = {
      {"Geometry/Type", "none"},
      {"Cables/Number of cables", "1"},
      {"Cables/Cable 1/Shape", "polyline"},
      {"Cables/Cable 1/polyline/Points", points},
      {"Cables/Cable 1/Number of elements", std::to_string(n_elements)},
      {"Cables/Cable 1/Section semi-axes", "0.005"},
      {"Cables/Cable 1/Young's modulus", std::to_string(EA / area)},
      {"Cables/Cable 1/Start support", "fixed"},
      {"Cables/Cable 1/End support", "fixed"},
      {"Newton/Residual tolerance", "1e-11"}};
    s.push_back({"Newton/Maximum iterations", "200"});
    if (by_gravity)
      {
        s.push_back({"Loads/Gravity", "true"});
        s.push_back({"Loads/Gravity vector/Function expression", "0; 0; -1"});
        s.push_back({"Cables/Cable 1/Density", std::to_string(1. / area)});
      }
    else
      {
        s.push_back(
          {"Cables/Cable 1/Distributed load/Function expression", "0; 0; -1"});
      }
    const auto summary = pneuma_test::run(s);
    if (summary.exit_code != 0 || !summary.summary.has("cable1_max_force")
        || summary.summary.has("cable2_max_force"))
      return {NAN, NAN, NAN};
    const auto reaction = summary.summary.get_vector("cable1_start_reaction");
    const auto mid_u    = summary.summary.get_vector("cable1_mid_u");
    return {std::abs(reaction[0]),
            depth - mid_u[2],
            std::hypot(reaction[0], reaction[2])};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  // Irvine's elastic catenary for EA = 1e5: S = H L/EA + 2H/w asinh(wL/2H).
  double lo = 1., hi = 10.;
  for (unsigned int k = 0; k < 200; ++k)
    {
      const double H = 0.5 * (lo + hi);
      (H * 12. / 1e5 + 2. * H * std::asinh(6. / H) - 10. > 0. ? hi : lo) = H;
    }
  const double H_irvine = 0.5 * (lo + hi);
  std::printf("Irvine's H for EA = 1e5 N: %.6f\n", H_irvine);

  // Near-inextensible, convergence in the number of elements.
  const double        H_ref = 4.695415, sag_ref = 2.923438, T_ref = 7.618853;
  std::vector<double> errors;
  Result              r{};
  for (const unsigned int n : {8u, 16u, 32u, 64u})
    {
      r = catenary(n, 1e5, false);
      errors.push_back(std::abs(r.H - H_irvine) / H_irvine);
      std::printf("inextensible, %2u elements: H %.6f sag %.6f T_max %.6f "
                  "(error against Irvine %.2e)\n",
                  n,
                  r.H,
                  r.sag,
                  r.T_max,
                  errors.back());
    }
  ok &= pneuma_test::check("inextensible H, 64 elements", r.H, H_ref, 5e-3);
  ok &= pneuma_test::check("inextensible sag", r.sag, sag_ref, 5e-3);
  ok &= pneuma_test::check("inextensible T_max", r.T_max, T_ref, 5e-3);
  for (unsigned int k = 1; k < errors.size(); ++k)
    {
      const double order = std::log2(errors[k - 1] / errors[k]);
      std::printf("observed order of the H error, %u -> %u elements: %.2f\n",
                  8u << (k - 1),
                  8u << k,
                  order);
      ok &= order > 1.8 && order < 2.2;
    }

  // Elastic, EA = 1e4 N, weight by gravity.
  const Result e = catenary(64, 1e4, true);
  ok &= pneuma_test::check("elastic H, 64 elements", e.H, 4.685299, 5e-3);
  ok &= pneuma_test::check("elastic sag", e.sag, 2.929124, 5e-3);

  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
