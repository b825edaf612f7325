// Cable-membrane contact on a curved master (doc/verification.md
// "Contact"): a prestressed cable (R_c = 0.01 m, EA = 6.3e7 N) is wrapped
// over the top half of a fixed cylinder (R = 0.23 m, Q2), its two
// straight ends held fixed straight below (frictionless wrap of pi).
// Equilibrium of the wrapped arc (V8 for a half turn): the contact line
// load is T/rho with rho = R + R_c - penetration, so its integral is
// pi T and its resultant is 2 T, T the (uniform) cable force. Also: the
// assembled tangent (cable, contact with the variation of the normal and
// of the projection point) against central finite differences at a
// perturbed contact state (Q1 and Q2, facet and smoothed master normals),
// and the Newton iterations per
// load step. Then V8 for a helix: a prestressed helix at alpha = 60
// degrees to the axis (one turn, ends fixed) pressed onto the cylinder:
// the line load is T sin^2(alpha)/rho, its integral over the turn
// 2 pi T sin(alpha), and the frictionless cable does not drift along its
// path (displacement of the middle node along the cable ~ 0).

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace
{
  /// The wrapped polyline, 0.2 mm pressed into the surface.
  std::string
  wrap_points()
  {
    const double R = 0.23, r = 0.01, rc = R + r - 2e-4, x = 1.;
    std::string  s;
    char         buffer[96];
    const auto   add = [&](const double y, const double z) {
      std::snprintf(buffer,
                    sizeof buffer,
                    "%s%.12g, %.12g, %.12g",
                    s.empty() ? "" : "; ",
                    x,
                    y,
                    z);
      s += buffer;
    };
    add(-rc, -0.3);
    add(-rc, 0.);
    for (unsigned int i = 1; i < 24; ++i)
      {
        const double th = M_PI - M_PI * i / 24.;
        add(rc * std::cos(th), rc * std::sin(th));
      }
    add(rc, 0.);
    add(rc, -0.3);
    return s;
  }

  pneuma_test::Settings
  wrap(const unsigned int degree)
  {
    return {{"Geometry/Type", "closed cylinder"},
            {"Geometry/closed cylinder/Radius", "0.23"},
            {"Geometry/closed cylinder/Length", "2"},
            {"Geometry/Global refinements", "2"},
            {"Discretisation/Polynomial degree", std::to_string(degree)},
            {"Materials/Region 0/Thickness", "1e-3"},
            {"Materials/Region 1/Thickness", "1e-3"},
            {"Materials/Region 2/Thickness", "1e-3"},
            {"Boundary conditions/Fixed regions", "0, 1, 2"},
            {"Cables/Number of cables", "1"},
            {"Cables/Cable 1/polyline/Points", wrap_points()},
            {"Cables/Cable 1/Number of elements", "40"},
            {"Cables/Cable 1/Section semi-axes", "0.01"},
            {"Cables/Cable 1/Prestress force", "1000"},
            {"Cables/Cable 1/Start support", "fixed"},
            {"Cables/Cable 1/End support", "fixed"},
            {"Contact/Number of pairs", "1"},
            {"Contact/Pair 1/Penalty", "1e8"},
            {"Newton/Residual tolerance", "1e-10"}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  for (const unsigned int degree : {1u, 2u})
    {
      // Finite-difference check at a perturbed state in contact, with the
      // facet and with the smoothed master normal (whose force chains
      // through the nodal normals of the neighbouring cells).
      for (const std::string normal : {"facet", "smoothed"})
        {
          auto settings = wrap(degree);
          settings.push_back({"Contact/Pair 1/Master normal", normal});
          // The membrane free too, so that the master side is perturbed.
          settings.push_back({"Output/Quiet", "true"});
          settings.push_back({"Boundary conditions/Fixed regions", ""});
          const double error =
            pneuma_test::make(settings)->check_tangent(1., 1e-4, 1e-8).first;
          const bool pass = error < 1e-6;
          std::printf("degree %u, %s normal: tangent with contact vs finite "
                      "differences: %s\n",
                      degree,
                      normal.c_str(),
                      pass ? "relative error < 1e-6" : "FAIL");
          if (!pass)
            std::printf("  relative error %.3e\n", error);
          ok &= pass;
        }

      // The wrap itself on the exact (Q2) cylinder only: a Q1 cylinder is
      // faceted (sagitta 4 mm here), so the pressed-in cable would start
      // out of contact between the facet corners.
      if (degree == 1)
        continue;
      const auto s = pneuma_test::run(wrap(degree));
      if (s.exit_code != 0 || !s.summary.has("contact1_points")
          || !s.summary.has("cable1_max_force"))
        {
          std::printf("degree %u: run failed (exit %d) FAIL\n",
                      degree,
                      s.exit_code);
          ok = false;
          continue;
        }
      const double T = s.get("cable1_max_force");
      std::printf("degree %u: cable force %.1f..%.1f N, %u/%u points in "
                  "contact, penetration %.2e m\n",
                  degree,
                  s.get("cable1_min_force"),
                  T,
                  static_cast<unsigned int>(s.get("contact1_active_points")),
                  static_cast<unsigned int>(s.get("contact1_points")),
                  s.get("contact1_max_penetration"));
      ok &= pneuma_test::check("  integral of the line load = pi T",
                               s.get("contact1_total_force"),
                               M_PI * T,
                               5e-3);
      ok &= pneuma_test::check("  resultant on the cable = 2 T",
                               s.summary.get_vector("contact1_force")[2],
                               2. * T,
                               5e-3);
      std::printf("  Newton iterations per step:");
      for (const auto n : s.step_iterations)
        std::printf(" %u", n);
      std::printf("\n");
    }
  // V8, helix at 60 degrees to the axis, one turn from x = 0.5.
  {
    const double alpha = M_PI / 3., start = 10. * M_PI / 180.;
    auto         settings = wrap(2);
    settings.erase(std::remove_if(settings.begin(),
                                  settings.end(),
                                  [](const auto &e) {
                                    return e.first.rfind("Cables/Cable 1/", 0)
                                           == 0;
                                  }),
                   settings.end());
    const pneuma_test::Settings helix = {
      {"Cables/Cable 1/Shape", "helix"},
      {"Cables/Cable 1/helix/Centre", "0.5, 0, 0"},
      {"Cables/Cable 1/helix/Axis", "1, 0, 0"},
      {"Cables/Cable 1/helix/Radius", "0.2398"},
      {"Cables/Cable 1/helix/Angle to axis", "60"},
      {"Cables/Cable 1/helix/Turns", "1"},
      {"Cables/Cable 1/helix/Start angle", "10"},
      {"Cables/Cable 1/Number of elements", "64"},
      {"Cables/Cable 1/Section semi-axes", "0.01"},
      {"Cables/Cable 1/Prestress force", "1000"},
      {"Cables/Cable 1/Start support", "fixed"},
      {"Cables/Cable 1/End support", "fixed"}};
    settings.insert(settings.end(), helix.begin(), helix.end());
    const auto s = pneuma_test::run(settings);
    if (s.exit_code != 0 || !s.summary.has("contact1_points")
        || !s.summary.has("cable1_max_force"))
      {
        std::printf("helix: run failed (exit %d) FAIL\n", s.exit_code);
        ok = false;
      }
    else
      {
        const double T =
          0.5 * (s.get("cable1_max_force") + s.get("cable1_min_force"));
        std::printf("helix: cable force %.1f..%.1f N, %u/%u points in "
                    "contact, penetration %.2e m\n",
                    s.get("cable1_min_force"),
                    s.get("cable1_max_force"),
                    static_cast<unsigned int>(s.get("contact1_active_points")),
                    static_cast<unsigned int>(s.get("contact1_points")),
                    s.get("contact1_max_penetration"));
        ok &=
          pneuma_test::check("  integral of the line load = 2 pi T sin(alpha)",
                             s.get("contact1_total_force"),
                             2. * M_PI * T * std::sin(alpha),
                             5e-3);
        // The middle node (half a turn): tangent t = cos(a) e_x + sin(a)
        // e_theta of the helix, e_theta at angle start + pi.
        const double               th = start + M_PI;
        const dealii::Tensor<1, 3> e_x({1., 0., 0.}),
          e_theta({0., -std::cos(th), -std::sin(th)});
        const dealii::Tensor<1, 3> t =
          std::cos(alpha) * e_x + std::sin(alpha) * e_theta;
        const auto           mid_u = s.summary.get_vector("cable1_mid_u");
        dealii::Tensor<1, 3> u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = mid_u[d];
        const bool pass = std::abs(u * t) < 1e-5;
        std::printf("  no drift: middle node moved %.1e m along the cable "
                    "(limit 1e-5) %s\n",
                    std::abs(u * t) < 5e-7 ? 0. : std::abs(u * t),
                    pass ? "PASS" : "FAIL");
        ok &= pass;
        // The reports balance: per cable, the end reactions (which take
        // the contact forces on the end elements) and the contact
        // resultant; over the scene, every support and the applied loads.
        const auto a     = s.summary.get_vector("cable1_start_reaction");
        const auto b     = s.summary.get_vector("cable1_end_reaction");
        const auto f     = s.summary.get_vector("contact1_force");
        const auto rm    = s.summary.get_vector("reaction");
        const auto fa    = s.summary.get_vector("applied_load");
        double     cable = 0., scene = 0.;
        for (unsigned int d = 0; d < 3; ++d)
          {
            cable += std::pow(a[d] + b[d] + f[d], 2);
            scene += std::pow(rm[d] + a[d] + b[d] + fa[d], 2);
          }
        const bool balanced =
          std::sqrt(cable) < 1e-6 * T && std::sqrt(scene) < 1e-6 * T;
        std::printf("  |cable reactions + contact resultant| and |all "
                    "reactions + applied loads| %s 1e-6 T %s\n",
                    balanced ? "<" : ">=",
                    balanced ? "PASS" : "FAIL");
        ok &= balanced;
      }
  }
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
