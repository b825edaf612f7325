// Identity check on the main scene (parameter_files/airbeam.prm on a
// coarser mesh): after inflation, gravity on tube and steel plates and the
// transverse surface load, the support reactions balance the applied loads
// (doc/verification.md, "Identities for every run"). Exercises rigid plates,
// point supports, gravity, surface traction, follower pressure and two load
// stages. The vertical applied load must also equal the weight of tube and
// plates plus the load F integrated over the band (within the quadrature
// error of the band's edges, which cut cells).
// Loads/Surface load regions: a uniform traction q on the plates only
// (regions 1, 2), on the tube only (region 0) and on every cell (empty)
// after the inflation without gravity: the parts add up to the whole to
// 1e-10, and each is q times its discrete area, the rims being 32-gons at
// this refinement: two plates of 16 R^2 sin(2 pi/32) and a tube of
// L 64 R sin(pi/32) (0.64 % and 0.16 % below 2 pi R^2 and 2 pi R L), to
// 1e-9.

#include "test_tools.h"

#include <cmath>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto s = pneuma_test::make({{"Geometry/Global refinements", "3"},
                                    {"Output/Directory", "output-airbeam"},
                                    {"Output/Quiet", "true"},
                                    {"Output/Write VTU", "false"}},
                                   SOURCE_DIR "/../parameter_files/airbeam.prm")
                   ->run();
  const auto reaction     = s.summary.get_vector("reaction");
  const auto applied_load = s.summary.get_vector("applied_load");

  const double R = 0.23, L = 2., g = 9.81;
  const double weight =
    (2. * M_PI * R * L * 1e-3 * 1. + 2. * M_PI * R * R * 1e-2 * 7850.) * g;
  bool ok = s.exit_code == 0;
  std::printf("steps %u, final time %.1f\n",
              static_cast<unsigned int>(s.get("steps")),
              s.get("final_time"));
  double imbalance = 0.;
  for (unsigned int c = 0; c < 3; ++c)
    imbalance += std::pow(reaction[c] + applied_load[c], 2);
  imbalance           = std::sqrt(imbalance) / std::abs(applied_load[2]);
  const bool balanced = imbalance < 1e-6;
  if (!balanced)
    std::printf("reaction %g %g %g, applied %g %g %g\n",
                reaction[0],
                reaction[1],
                reaction[2],
                applied_load[0],
                applied_load[1],
                applied_load[2]);
  std::printf("|reactions + applied loads| / |applied vertical load| %s 1e-6\n",
              balanced ? "<" : ">=");
  ok = ok && balanced;
  ok = pneuma_test::check("vertical load (weight + F)",
                          -applied_load[2],
                          weight + 1000.,
                          5e-2)
       && ok;

  // Surface load regions.
  const double q        = 100.;
  const auto   vertical = [&](const std::string &regions) {
    const auto r =
      pneuma_test::make({{"Geometry/Global refinements", "3"},
                         {"Output/Directory", "output-airbeam"},
                         {"Output/Quiet", "true"},
                         {"Output/Write VTU", "false"},
                         {"Loads/Gravity", "false"},
                         {"Loads/Surface traction/Function expression",
                          "0; 0; -" + pneuma_test::number(q) + "*min(t, 1)"},
                         {"Loads/Surface load regions", regions},
                         {"Load stepping/Stage end times", "1"}},
                        SOURCE_DIR "/../parameter_files/airbeam.prm")
        ->run();
    ok = ok && r.exit_code == 0;
    return -r.summary.get_vector("applied_load")[2];
  };
  const double plates = vertical("1, 2"), tube = vertical("0"),
               all   = vertical("");
  const bool adds_up = std::abs(plates + tube - all) <= 1e-10 * all;
  std::printf("traction on the plates + on the tube = on every cell: %s\n",
              adds_up ? "PASS" : "FAIL");
  ok = ok && adds_up;
  ok = pneuma_test::check(
         "traction on the plates only (regions 1, 2) vs q x 32-gon area [N]",
         plates,
         q * 2. * 16. * R * R * std::sin(2. * M_PI / 32.),
         1e-9)
       && ok;
  ok = pneuma_test::check(
         "traction on the tube only (region 0) vs q x 32-gon tube area [N]",
         tube,
         q * L * 64. * R * std::sin(M_PI / 32.),
         1e-9)
       && ok;
  return ok ? 0 : 1;
}
