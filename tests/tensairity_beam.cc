// Luchsinger's basic Tensairity element on the paper's airbeam
// (parameter_files/tensairity_beam.prm, doc/scenes.md "Tensairity beam"):
// the Figure 7 airbeam (sealed gas at 2 bar absolute, tension-field wall,
// compression element tied along the top) with two opposite one-turn
// helices anchored to the end plates' rims, in frictionless contact with
// the wall, then the line load on the compression element at mid-span
// under displacement control, here to 3 cm (the scene's mesh, 60 elements
// per helix instead of 120). Checks:
//  - equilibrium of the whole: the vertical support reactions carry F, the
//    weights of the compression element and of the helices, and the
//    membrane's applied load (wall and plates), to 1e-8;
//  - equilibrium of each helix: the forces of its two plate ties, its
//    contact resultant and its weight sum to zero (to 1e-8 of the contact
//    force);
//  - a frictionless helix carries one tension along its length (within
//    0.5 %: its weight changes it by 0.2 % from the bottom to the plates);
//  - the sealed gas: p_abs V^1.4 at the end equals its value at the seal;
//  - the helices work: inflated, their prestress lifts the tube's bottom
//    at mid-span above where the airbeam without them hangs;
//  - smoothed master normals from t = 1 (Smoothed normal from): the facet
//    run's path to round-off up to t = 1, an LU after, and the same load
//    at 3 cm (1e-4) and helix tension (1e-3) as the facet run;
//  - 1 and 2 ranks print the same.

#include "scene_history.h"
#include "test_tools.h"

#include <cmath>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string  dir = std::string(PNEUMA_SOURCE_DIR) + "/parameter_files/";
  const double       g = 9.81, L = 2., pi = M_PI;
  const unsigned int n_elements                   = 60;
  const pneuma_test::Settings settings            = {{"Output/Quiet", "true"},
                                                     {"Output/Write VTU", "false"},
                                                     {"Newton/Print convergence table",
                                                      "false"}};
  auto                        tensairity_settings = settings;
  tensairity_settings.push_back(
    {"Load stepping/Path following/Target monitor value", "-0.03"});
  for (const char *k : {"2", "3"})
    tensairity_settings.push_back(
      {std::string("Cables/Cable ") + k + "/Number of elements",
       std::to_string(n_elements)});
  const auto s =
    pneuma_test::make(tensairity_settings, dir + "tensairity_beam.prm")->run();
  if (s.exit_code != 0)
    {
      if (root)
        std::printf("run failed (exit %d): %s\nFAILED\n",
                    s.exit_code,
                    s.message.c_str());
      return 1;
    }
  bool ok = true;

  // Weights: the compression element (elliptic section, density 1) and
  // each helix (steel, radius 5 mm, on its unstressed length: the
  // discrete reference helix of radius 0.2348 m and pitch L over n chords,
  // shortened by the prestress 1 kN / EA).
  const double W_beam = g * pi * 0.0551 * 0.00577 * L * 1.;
  const double R = 0.2348, A = pi * 0.005 * 0.005, EA = 2.1e11 * A;
  const double chord =
    std::hypot(2. * R * std::sin(pi / n_elements), L / n_elements);
  const double W_helix = 7850. * A * g * n_elements * chord / (1. + 1e3 / EA);
  const double F       = 1e4 * (s.get("final_time") - 1.);
  ok = pneuma_test::check("vertical reactions vs F + compression element, "
                          "helix and membrane weights [N]",
                          s.summary.get_vector("reaction")[2],
                          F + W_beam + 2. * W_helix
                            - s.summary.get_vector("applied_load")[2],
                          1e-8)
       && ok;

  // Each helix: ties 2, 3 hold cable 2 (contact pair 1), ties 4, 5 cable 3
  // (pair 2).
  for (unsigned int h = 0; h < 2; ++h)
    {
      const std::string cable = std::to_string(h + 2);
      const auto        t1 =
        s.summary.get_vector("tie" + std::to_string(2 + 2 * h) + "_force");
      const auto t2 =
        s.summary.get_vector("tie" + std::to_string(3 + 2 * h) + "_force");
      const std::string pair      = "contact" + std::to_string(h + 1);
      const auto        c         = s.summary.get_vector(pair + "_force");
      double            imbalance = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        imbalance = std::hypot(imbalance,
                               t1[d] + t2[d] + c[d] + (d == 2 ? -W_helix : 0.));
      const double scale    = s.get(pair + "_total_force");
      const bool   balanced = imbalance <= 1e-8 * scale;
      if (root)
        std::printf("cable %s: |ties + contact + weight| / contact force "
                    "%s 1e-8 %s\n",
                    cable.c_str(),
                    balanced ? "<=" : ">",
                    balanced ? "PASS" : "FAIL");
      ok = ok && balanced;
      // Frictionless: the contact force is normal to the wall the helix
      // lies on, so the tension is constant but for the weight per length
      // w times the rise from the bottom at mid-span to the plates
      // (2.8 N here, 0.2 % of T; issue 14's criterion: 0.5 %).
      const double max_force = s.get("cable" + cable + "_max_force");
      const double min_force = s.get("cable" + cable + "_min_force");
      ok                     = pneuma_test::check("cable " + cable
                                + ": least vs largest tension "
                                                      "(frictionless)",
                              min_force,
                              max_force,
                              5e-3)
           && ok;
    }

  // The sealed gas, and the bottom at the end of the inflation.
  const double gas_error = pneuma_test::sealed_gas_change(s, 1, 1.);
  const double bottom_tensairity =
    pneuma_test::at_time(s, 1., [](const auto &row) {
      return row.get_vector("m1_u")[2];
    });
  if (root)
    std::printf("sealed gas p_abs V^1.4 at the end vs the seal: relative "
                "change %s 1e-9 %s\n",
                gas_error <= 1e-9 ? "<=" : ">",
                gas_error <= 1e-9 ? "PASS" : "FAIL");
  ok = ok && gas_error <= 1e-9;

  // The same with smoothed master normals after the inflation
  // (Contact/Pair k/Smoothed normal from = 1; facet normals while the wall
  // is flaccid): up to t = 1 the path is the facet run's to round-off, then
  // the smoothed normal takes over with its non-symmetric tangent (LU),
  // and off the mesh lines both normals reach the same target load.
  {
    auto switched_settings = tensairity_settings;
    for (const char *k : {"1", "2"})
      {
        const std::string pair = std::string("Contact/Pair ") + k;
        switched_settings.push_back({pair + "/Master normal", "smoothed"});
        switched_settings.push_back({pair + "/Smoothed normal from", "1"});
      }
    const auto w =
      pneuma_test::make(switched_settings, dir + "tensairity_beam.prm")->run();
    if (w.exit_code != 0)
      {
        if (root)
          std::printf("smoothed from t = 1: run failed (exit %d): %s FAIL\n",
                      w.exit_code,
                      w.message.c_str());
        ok = false;
      }
    else
      {
        const auto contact_at_1 = [](const pneuma::RunResult &r) {
          return pneuma_test::at_time(r, 1., [](const auto &row) {
            return row.get("contact1_total_force");
          });
        };
        ok = pneuma_test::check("smoothed from t = 1: contact force at t = 1 "
                                "vs the facet run [N]",
                                contact_at_1(w),
                                contact_at_1(s),
                                1e-10)
             && ok;
        ok =
          pneuma_test::check("smoothed from t = 1: LU at the end (1: yes)",
                             w.get("factorization_symmetric") == 0. ? 1. : 0.,
                             1.,
                             0.)
          && ok;
        ok = pneuma_test::check("smoothed from t = 1: load at 3 cm vs the "
                                "facet run",
                                w.get("final_time") - 1.,
                                s.get("final_time") - 1.,
                                1e-4)
             && ok;
        ok = pneuma_test::check("smoothed from t = 1: helix tension vs the "
                                "facet run [N]",
                                w.get("cable2_max_force"),
                                s.get("cable2_max_force"),
                                1e-3)
             && ok;
      }
  }

  // The airbeam of Figure 7 on the same mesh and pressure, inflated only:
  // its bottom hangs under gravity, the helices' prestress lifts it.
  auto airbeam_settings = settings;
  airbeam_settings.insert(
    airbeam_settings.end(),
    {{"Geometry/Global refinements", "2"},
     {"Discretisation/Polynomial degree", "2"},
     {"Chambers/Chamber 1/Gas/Pressure/Function constants", "p0=1e5"},
     {"Load stepping/Path following/Target monitor value", ""},
     {"Load stepping/Stage end times", "1"},
     {"Load stepping/Control", "load"}});
  const auto a =
    pneuma_test::make(airbeam_settings, dir + "airbeam_figure7.prm")->run();
  const double bottom_airbeam = a.summary.get_vector("m1_u")[2];
  const bool   lifted = a.exit_code == 0 && bottom_tensairity > bottom_airbeam;
  if (root)
    std::printf("inflated, bottom at mid-span: airbeam %.3f mm, with the "
                "helices %.3f mm (lifted: %s)\n",
                1e3 * bottom_airbeam,
                1e3 * bottom_tensairity,
                lifted ? "PASS" : "FAIL");
  ok = ok && lifted;
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
