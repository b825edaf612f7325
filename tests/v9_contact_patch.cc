// V9 contact patch tests (doc/verification.md): a straight, prestressed cable
// (R = 0.01 m, T = 100 N) lies on a flat membrane held fixed (the master)
// under a uniform line load q = 100 N/m. Its ends are held only in the
// plane, so the contact alone carries the load: the contact line load is
// uniform and equal to the load, the penetration is q/eps_N at every
// point, and the whole cable sinks by the same amount. Cases: aligned,
// rotated by 30 degrees, offset, non-matching meshes (7 cable elements on
// 8x8 or 16x16 cells, membrane degree 1 and 2), Gauss and Lobatto points;
// the penalty study: the gap error q/eps_N falls like 1/eps_N; and a
// solid beam with an elliptic section resting on its vertical semi-axis
// (the gap uses the section's extent along the normal; the contact also
// squeezes the section a little, by ~1e-9 m here, hence looser tolerances).
// (The load is per unstressed length: q_eff = q L_0/L = q/(1 + T/EA).)

#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  struct Case
  {
    std::string  name;
    double       angle, offset;
    unsigned int refinements, degree;
    bool         lobatto;
    double       penalty;
    bool         beam = false;
  };

  std::string
  point(const double x, const double y, const double z)
  {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.15g, %.15g, %.15g", x, y, z);
    return buffer;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  const double q = 100., R = 0.01, T = 100., E = 2e11;
  const double EA = E * M_PI * R * R, q_eff = q / (1. + T / EA);

  const std::vector<Case> cases = {
    {"aligned, Gauss, Q1", 0., 0., 3, 1, false, 1e6},
    {"aligned, Lobatto, Q1", 0., 0., 3, 1, true, 1e6},
    {"rotated 30 deg, offset, Gauss, Q2", 30., 0.037, 3, 2, false, 1e6},
    {"rotated 30 deg, offset, Lobatto, Q1 16x16", 30., 0.037, 4, 1, true, 1e6},
    {"penalty 1e5", 0., 0.013, 3, 1, false, 1e5},
    {"penalty 1e7", 0., 0.013, 3, 1, false, 1e7},
    {"solid beam, elliptic section (a = 0.02 vertical, b = 0.01), Q2",
     0.,
     0.013,
     3,
     2,
     false,
     1e6,
     true}};
  std::vector<double> gap_error;
  for (const auto &c : cases)
    {
      const double a = c.angle * M_PI / 180., L = 0.8;
      const double dx = 0.5 * L * std::cos(a), dy = 0.5 * L * std::sin(a);
      // The solid beam rests on its vertical semi-axis a = 0.02.
      const double Rc = c.beam ? 0.02 : R;
      const double oy = c.offset, z0 = Rc - 1e-5; // slightly pressed in
      const double EA_c = c.beam ? E * M_PI * 0.02 * 0.01 : EA;
      const double q_c  = q / (1. + T / EA_c);
      const auto   s    = pneuma_test::run(
        {{"Geometry/Type", "square"},
              {"Geometry/square/Side length", "1"},
              {"Geometry/Global refinements", std::to_string(c.refinements)},
              {"Discretisation/Polynomial degree", std::to_string(c.degree)},
              {"Boundary conditions/Fixed regions", "0"},
              {"Cables/Number of cables", "1"},
              {"Cables/Cable 1/polyline/Points",
               point(-dx, oy - dy, z0) + "; " + point(dx, oy + dy, z0)},
              {"Cables/Cable 1/Number of elements", "7"},
              {"Cables/Cable 1/Element", c.beam ? "solid beam" : "cable"},
              {"Cables/Cable 1/Section semi-axes", c.beam ? "0.02, 0.01" : "0.01"},
              {"Cables/Cable 1/solid beam/Section axis", "0, 0, 1"},
              {"Cables/Cable 1/solid beam/Poisson's ratio", "0"},
              {"Cables/Cable 1/Prestress force", "100"},
              {"Cables/Cable 1/Start support", "fixed"},
              {"Cables/Cable 1/Start components", "xy"},
              {"Cables/Cable 1/End support", "fixed"},
              {"Cables/Cable 1/End components", "xy"},
              {"Cables/Cable 1/Distributed load/Function expression", "0; 0; -100"},
              {"Contact/Number of pairs", "1"},
              {"Contact/Pair 1/Penalty", std::to_string(c.penalty)},
              {"Contact/Pair 1/Integration", c.lobatto ? "lobatto" : "gauss"},
              {"Newton/Residual tolerance", "1e-10"}});
      if (s.exit_code != 0 || !s.summary.has("contact1_points")
          || !s.summary.has("cable1_max_force"))
        {
          std::printf("%s: run failed (exit %d) FAIL\n",
                      c.name.c_str(),
                      s.exit_code);
          ok = false;
          continue;
        }
      const auto active_points =
        static_cast<unsigned int>(s.get("contact1_active_points"));
      const auto   points = static_cast<unsigned int>(s.get("contact1_points"));
      const double max_penetration = s.get("contact1_max_penetration");
      const double penetration     = q_c / c.penalty;
      std::printf("%s: %u/%u points active\n",
                  c.name.c_str(),
                  active_points,
                  points);
      ok &= active_points == points;
      ok &= pneuma_test::check("  total contact force = q L",
                               s.get("contact1_total_force"),
                               q_c * L,
                               1e-8);
      ok &= pneuma_test::check("  max penetration = q/eps_N",
                               max_penetration,
                               penetration,
                               c.beam ? 1e-3 : 1e-6);
      // Every node sinks to the same height R - q/eps_N.
      for (const std::string node : {"start", "mid", "end"})
        ok &= pneuma_test::check(
          "  node height",
          z0 + s.summary.get_vector("cable1_" + node + "_u")[2],
          Rc - penetration,
          c.beam ? 1e-6 : 1e-8);
      if (c.name.rfind("penalty", 0) == 0 || c.name == "aligned, Gauss, Q1")
        gap_error.push_back(max_penetration);
    }
  // Gap error against the impenetrable solution (0) for eps = 1e6, 1e5,
  // 1e7 (cases 0, 4, 5): it scales like 1/eps_N.
  if (gap_error.size() == 3)
    {
      const double r1 = gap_error[1] / gap_error[0],
                   r2 = gap_error[0] / gap_error[2];
      std::printf("penetration ratio eps 1e5/1e6: %.6f, 1e6/1e7: %.6f "
                  "(1/eps_N: 10)\n",
                  r1,
                  r2);
      ok &= std::abs(r1 - 10.) < 1e-5 && std::abs(r2 - 10.) < 1e-5;
    }
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
