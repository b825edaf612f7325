// Slack starts (issue "Cables anchored and tied, contact that holds up"):
// the V7 catenary (span 10 m, unstressed length 12 m, EA = 1e4 N, q = 1
// N/m, pinned ends) started from the straight chord instead of from a V.
// The straight state is an equilibrium of a solid beam (compressed by the
// 2 m of excess length); started there, Newton used to return it, with
// its middle 12 mm above the chord, H = -1273 N, 64 negative eigenvalues
// and exit 0. The first step now starts from the parabola of length 12 m
// sagged along the load (Subsystem::first_guess), and both elements reach
// the hanging catenary: H against Irvine's elastic catenary (4.685299 N,
// the reference of benchmarks/cables) and the middle below the chord.

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  // Solid beam: a = 5e-5 m and E with EA = 1e4 N, so that EI = 6e-6 N m^2
  // is nearly nothing (the catenary of benchmarks/cables).
  const double beam_E = 1e4 / (M_PI * 5e-5 * 5e-5);
  for (const std::string element : {"cable", "solid beam"})
    {
      pneuma_test::Settings settings = {
        {"Geometry/Type", "none"},
        {"Cables/Number of cables", "1"},
        {"Cables/Cable 1/Element", element},
        {"Cables/Cable 1/polyline/Points", "0, 0, 0; 10, 0, 0"},
        {"Cables/Cable 1/Number of elements", "64"},
        {"Cables/Cable 1/Unstressed length", "12"},
        {"Cables/Cable 1/Start support", "pinned"},
        {"Cables/Cable 1/End support", "pinned"},
        {"Cables/Cable 1/Distributed load/Function expression", "0; 0; -1"},
        {"Newton/Maximum iterations", "100"}};
      if (element == "cable")
        {
          settings.push_back({"Cables/Cable 1/Section semi-axes", "0.005"});
          settings.push_back({"Cables/Cable 1/Young's modulus",
                              pneuma_test::number(1e4 / (M_PI * 25e-6))});
        }
      else
        {
          settings.push_back({"Cables/Cable 1/Section semi-axes", "5e-5"});
          settings.push_back(
            {"Cables/Cable 1/Young's modulus", pneuma_test::number(beam_E)});
          settings.push_back(
            {"Cables/Cable 1/solid beam/Poisson's ratio", "0"});
        }
      const auto s = pneuma_test::run(settings);
      if (s.exit_code != 0 || !s.summary.has("cable1_start_reaction"))
        {
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            std::printf("%s: run failed (exit %d): %s\n",
                        element.c_str(),
                        s.exit_code,
                        s.message.c_str());
          ok = false;
          continue;
        }
      const double H = -s.summary.get_vector("cable1_start_reaction")[0];
      ok &= pneuma_test::check(element + ": horizontal force H [N]",
                               H,
                               4.685299,
                               3e-4);
      ok &=
        pneuma_test::check(element + ": the middle hangs below the chord",
                           s.summary.get_vector("cable1_mid_u")[2] < -2. ? 1.
                                                                         : 0.,
                           1.,
                           0.);
      ok &= pneuma_test::check(element + ": tension everywhere",
                               s.get("cable1_min_force") > 0. ? 1. : 0.,
                               1.,
                               0.);
    }
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
