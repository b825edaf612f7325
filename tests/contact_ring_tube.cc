// A ring cable on a mesh line of an inflated tube (issue "Cables anchored
// and tied, contact that holds up"): a closed steel ring (R_c = 5 mm,
// 64 elements) around the airbeam's wall (R = 0.23 m, t = 1 mm,
// E = 7.6e9 Pa, nu = 0.3) on a tube 0.2 m long with rigid caps, its centre
// exactly on the vertex line x = 0.1 of the cells, where facet normals
// jump. Stage 1 inflates to 1 bar (the ring is tensioned as the tube grows
// into it); stage 2 tensions the ring by a prestress of 500 N (Prestress
// factor t - 1). With the smoothed master normal Newton converges and all
// points stay in contact; the ring tension is compared with the boundary
// layer of a pressurised membrane cylinder under a ring load
// (doc/verification.md "Ring on an inflated tube"):
//   w(x) = w0 exp(-lambda |x|),  lambda^2 = (E t / R^2 - p / R) / N_x,
//   2 lambda N_x w0 = T / r_t,   N_x = p R / 2,
// closed by the ring's elasticity T = EA (r / r_0 - 1) and the penalty
// penetration, with the contact points' radius on the 64-gon.
// Also: a step in which cable points move relative to the membrane by
// more than the pair's Maximum motion per step is cut back.

#include "test_tools.h"

#include <cmath>

namespace
{
  constexpr double E = 7.6e9, thickness = 1e-3, nu = 0.3, p = 1e5, R = 0.23,
                   a = 0.005, penalty = 1e8, prestress = 500.;
  const double  EA       = 2.1e11 * M_PI * a * a;
  constexpr int elements = 64;

  /// The ring tension of the boundary-layer solution for a ring of radius
  /// @p ring_radius (its reference) with the prestress.
  double
  analytic_tension(const double ring_radius)
  {
    // Contact points: 2 Gauss points per element of the regular 64-gon.
    const double eta   = 0.5 - 0.5 / std::sqrt(3.);
    const double phi   = std::atan((1. - 2. * eta) * std::tan(M_PI / elements));
    const double kappa = std::cos(M_PI / elements) / std::cos(phi);
    // The free inflated tube (closed ends) and its boundary layer.
    const double r_free   = R + p * R * R / (E * thickness) * (1. - nu / 2.);
    const double N_x      = p * r_free / 2.;
    const double lambda   = std::sqrt((E * thickness / (R * R) - p / R) / N_x);
    const double r_0      = ring_radius / (1. + prestress / EA);
    const auto   residual = [&](const double T) {
      const double r   = r_0 * (1. + T / EA);
      const double gap = T / r / penalty; // penetration under q = T / r
      const double r_t = kappa * r - a + gap;
      return 2. * lambda * N_x * (r_free - r_t) - T / r_t;
    };
    double lo = 0., hi = 1e4;
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double mid                               = 0.5 * (lo + hi);
        (residual(lo) * residual(mid) <= 0. ? hi : lo) = mid;
      }
    return 0.5 * (lo + hi);
  }

  pneuma_test::Settings
  ring_on_tube(const unsigned int degree,
               const unsigned int refinements,
               const double       ring_radius,
               const bool         staged)
  {
    pneuma_test::Settings s = {
      {"Geometry/Type", "closed cylinder"},
      {"Geometry/closed cylinder/Radius", "0.23"},
      {"Geometry/closed cylinder/Length", "0.2"},
      {"Geometry/closed cylinder/Cells along length", "4"},
      {"Geometry/Global refinements", std::to_string(refinements)},
      {"Discretisation/Polynomial degree", std::to_string(degree)},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"},
      {"Materials/Region 1/Thickness", "1e-2"},
      {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
      {"Materials/Region 2/Thickness", "1e-2"},
      {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
      {"Loads/Pressure/Function expression", "1e5*min(t, 1)"},
      {"Boundary conditions/Rigid regions", "1, 2"},
      {"Boundary conditions/Fixed points",
       "0,0,0: xyz; 0.2,0,0: yz; 0.05,0,0.23: y"},
      {"Cables/Number of cables", "1"},
      {"Cables/Cable 1/Shape", "ring"},
      {"Cables/Cable 1/ring/Centre", "0.1, 0, 0"},
      {"Cables/Cable 1/ring/Axis", "1, 0, 0"},
      {"Cables/Cable 1/ring/Radius", pneuma_test::number(ring_radius)},
      {"Cables/Cable 1/Number of elements", std::to_string(elements)},
      {"Cables/Cable 1/Section semi-axes", "0.005"},
      {"Cables/Cable 1/Young's modulus", "2.1e11"},
      {"Cables/Cable 1/Prestress force", "500"},
      {"Contact/Number of pairs", "1"},
      {"Contact/Pair 1/Membrane regions", "0"},
      {"Contact/Pair 1/Penalty", pneuma_test::number(penalty)},
      {"Contact/Pair 1/Master normal", "smoothed"},
      {"Load stepping/Initial increment", "0.5"},
      {"Load stepping/Maximum increment", "0.5"}};
    if (staged)
      {
        s.push_back({"Cables/Cable 1/Prestress factor/Function expression",
                     "max(t - 1, 0)"});
        s.push_back({"Load stepping/Stage end times", "1, 2"});
      }
    else
      s.push_back({"Load stepping/Stage end times", "1"});
    return s;
  }

  pneuma_test::Settings
  sliding_cable(const double max_motion)
  {
    return {
      {"Geometry/Type", "square"},
      {"Geometry/Global refinements", "4"},
      {"Geometry/square/Side length", "1"},
      {"Boundary conditions/Fixed regions", "0"},
      {"Cables/Number of cables", "1"},
      {"Cables/Cable 1/polyline/Points", "-0.3, 0, 0.00999; 0.3, 0, 0.00999"},
      {"Cables/Cable 1/Number of elements", "6"},
      {"Cables/Cable 1/Section semi-axes", "0.01"},
      {"Cables/Cable 1/Prestress force", "100"},
      {"Cables/Cable 1/Start support", "fixed"},
      {"Cables/Cable 1/End support", "fixed"},
      {"Cables/Cable 1/Start components", "xy"},
      {"Cables/Cable 1/End components", "xy"},
      {"Cables/Cable 1/Start displacement/Function expression", "0.2*t; 0; 0"},
      {"Cables/Cable 1/End displacement/Function expression", "0.2*t; 0; 0"},
      {"Cables/Cable 1/Distributed load/Function expression", "0; 0; -100"},
      {"Contact/Number of pairs", "1"},
      {"Contact/Pair 1/Penalty", "1e6"},
      {"Contact/Pair 1/Integration", "lobatto"},
      {"Contact/Pair 1/Points per element", "3"},
      {"Contact/Pair 1/Maximum motion per step",
       pneuma_test::number(max_motion)},
      {"Load stepping/Initial increment", "1"},
      {"Load stepping/Maximum increment", "1"}};
  }

  bool
  check_ring(const char              *name,
             const pneuma::RunResult &s,
             const double             ring_radius,
             const double             tolerance,
             const int                precision)
  {
    if (s.exit_code != 0 || !s.summary.has("cable1_max_force"))
      {
        std::printf("%s: run failed (exit %d): %s\n",
                    name,
                    s.exit_code,
                    s.message.c_str());
        return false;
      }
    bool         ok         = true;
    const double T          = s.get("cable1_max_force");
    const double active     = s.get("contact1_active_points");
    unsigned int iterations = 0;
    for (const auto n : s.step_iterations)
      iterations += n;
    // Printed with @p precision digits after the mantissa's point: the Q1 ring
    // on a mesh line sits at 2377.4 N, and on 2 ranks under CPU load its state
    // moved by up to 8e-5 (2377.6 N; round-off that depends on timing,
    // presumably MUMPS' dynamic scheduling, in a state that the ring's weakly
    // held axial position leaves ill-conditioned). The checks are unchanged.
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: %u/%u points in contact, total contact force %.*e N, "
                  "cutbacks %u\n",
                  name,
                  static_cast<unsigned int>(active),
                  static_cast<unsigned int>(s.get("contact1_points")),
                  precision,
                  s.get("contact1_total_force"),
                  static_cast<unsigned int>(s.get("cutbacks")));
    // Newton: 17 4 2 2 (Q2), 11 4 3 2 (Q1), 14 4 4 3 after the cutback.
    ok &=
      pneuma_test::check(std::string(name) + ": at most 40 Newton iterations",
                         iterations <= 40 ? 1. : 0.,
                         1.,
                         0.);
    // The smoothed force is not symmetric: LU, not the LDL^T that its
    // numbering-dependent asymmetry measure could let through.
    ok &= pneuma_test::check(std::string(name)
                               + ": LU for the smoothed normal (1: yes)",
                             s.get("factorization_symmetric") == 0. ? 1. : 0.,
                             1.,
                             0.);
    ok &= pneuma_test::check(std::string(name) + ": every point in contact",
                             active,
                             s.get("contact1_points"),
                             0.);
    ok &= pneuma_test::check(std::string(name) + ": ring tension [N]",
                             T,
                             analytic_tension(ring_radius),
                             tolerance,
                             precision);
    // Equilibrium of the ring's nodes (frictionless, radial normals): a
    // node's kink 2 T sin(pi/N) balances the contact forces of the Gauss
    // points of its two elements, lumped with the shape functions,
    // F_e ((1 - eta) cos(pi/N - phi) + eta cos(pi/N + phi)) per element.
    const double eta = 0.5 - 0.5 / std::sqrt(3.);
    const double phi = std::atan((1. - 2. * eta) * std::tan(M_PI / elements));
    const double lumped = (1. - eta) * std::cos(M_PI / elements - phi)
                          + eta * std::cos(M_PI / elements + phi);
    ok &=
      pneuma_test::check(std::string(name)
                           + ": total contact force from the tension",
                         s.get("contact1_total_force"),
                         2. * elements * std::sin(M_PI / elements) * T / lumped,
                         1e-4,
                         precision);
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  // Q2 on the mesh line: the C0 surface carries the slope kink of the
  // ring load exactly, so the tension is converged at h = 6.25 mm
  // (564.54, 564.11, 564.07 N at h = 6.25, 3.13, 1.56 mm for the ring
  // started at 0.2348 m; between mesh lines the kink is smeared over a
  // cell and T converges to it at first order: 667.7, 617.4, 591.2 N).
  ok &= check_ring("Q2 on a mesh line, staged",
                   pneuma_test::run(ring_on_tube(2, 3, 0.235, true)),
                   0.235,
                   3e-3,
                   4);
  // Q1 on the mesh line converges as well; its flat facets leave the
  // tube's radius under the ring short of the circle by up to
  // R (1 - cos(pi/64)) = 0.28 mm, a third of the ring's indentation
  // w0 = 0.8 mm, so the tension is only checked to 20 % (it is 16 % low).
  ok &= check_ring("Q1 on a mesh line, staged",
                   pneuma_test::run(ring_on_tube(1, 4, 0.235, true)),
                   0.235,
                   0.2,
                   2);
  // A cable dragged 0.2 m across a fixed flat patch in one step (ends
  // prescribed, pressed on by 100 N/m): its points move relative to the
  // membrane by 0.2 m, more than half the search distance 0.11 m, so the
  // step is cut back (at least to dt = 0.25, 0.05 m per step) and the run
  // ends where a run without the limit ends.
  for (const double limit : {0.5, 0.})
    {
      const auto        s = pneuma_test::run(sliding_cable(limit));
      const std::string name =
        "cable dragged across a patch, Maximum motion per step = "
        + pneuma_test::number(limit);
      if (s.exit_code != 0 || !s.summary.has("contact1_total_force"))
        {
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::printf("%s: run failed (exit %d): %s\n",
                        name.c_str(),
                        s.exit_code,
                        s.message.c_str());
          ok = false;
          continue;
        }
      // The limit needs two halvings at least (0.05 m < 0.055 m); without
      // it the full step still fails the candidate test (its points end
      // on cells 0.2 m away, outside the step's candidates).
      const unsigned int needed = limit > 0. ? 2 : 1;
      ok &= pneuma_test::check(name + ": cut back at least "
                                 + std::to_string(needed) + " time(s)",
                               s.get("cutbacks") >= needed ? 1. : 0.,
                               1.,
                               0.);
      ok &= pneuma_test::check(name + ": total contact force q L [N]",
                               s.get("contact1_total_force"),
                               60.,
                               1e-3);
      ok &= pneuma_test::check(name + ": cable slid by 0.2 m",
                               s.summary.get_vector("cable1_mid_u")[0],
                               0.2,
                               1e-8);
    }
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
