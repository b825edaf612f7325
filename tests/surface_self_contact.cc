// Self-contact of a wall (parameter_files/tube_pinched.prm): a tube slice
// in plane strain, inflated to 10 kPa, is pinched by two rollers until
// its top lies on its bottom, then pressed 0.2 mm more; the wall is one
// region and bears on itself (Surface contact without Opposite regions).
// Checks:
//  - the two sheets stay apart: at the end the mid-surfaces of the top and
//    the bottom (the vertices under the rollers) are at least t less the
//    penalty gap the run reports apart (no penetration beyond the offset
//    plus the penalty gap), and that gap is below 10 % of t;
//  - the same run with a penalty of 1 Pa/m (a pair that cannot hold the
//    wall) lets the rollers squeeze the sheets' faces into each other: the
//    check above (with the first run's penalty gap) fails there, so it
//    can fail;
//  - the rollers' forces are equal and opposite, and once the sheets
//    touch every further newton of the rollers goes through the contact:
//    the rise of the roller force from the first state in contact to the
//    end equals the rise of the contact force (1e-3);
//  - Newton takes at most 3 iterations per step in contact;
//  - 1 and 2 ranks print the same.

#include "scene_history.h"
#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  constexpr double t_wall = 1e-3;

  /// Distance between the mid-surfaces of the tube's top and bottom
  /// (monitors 0 and 1, at z = +-0.2 m) at the end of @p s.
  double
  separation(const pneuma::RunResult &s)
  {
    return (0.2 + s.get("m0_u_z")) - (-0.2 + s.get("m1_u_z"));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root = pneuma_test::root();
  const std::string                        file =
    std::string(PNEUMA_SOURCE_DIR) + "/parameter_files/tube_pinched.prm";
  const pneuma_test::Settings common = {
    {"Output/Quiet", "true"},
    {"Output/Write VTU", "false"},
    {"Newton/Print convergence table", "false"},
    {"Geometry/gmsh/Mesh file",
     std::string(PNEUMA_SOURCE_DIR) + "/meshes/tube_slice.msh"}};
  const auto            s    = pneuma_test::make(common, file)->run();
  pneuma_test::Settings soft = common;
  soft.push_back({"Surface contact/Pair 1/Penalty", "1"});
  const auto through = pneuma_test::make(soft, file)->run();
  if (pneuma_test::failed(s, "the pinch")
      | pneuma_test::failed(through, "the pinch with 1 Pa/m"))
    {
      if (root)
        std::printf("FAILED\n");
      return 1;
    }
  const double gap = s.get("surface1_penetration"), d = separation(s);
  const bool   apart     = d >= t_wall - gap && gap < 0.1 * t_wall;
  const double d_through = separation(through);
  const bool passes = d_through < t_wall - through.get("surface1_penetration");
  if (root)
    std::printf("top and bottom mid-surfaces %.4e m apart, t less the "
                "penalty gap %.4e m: %s; penalty gap / t = %.3f (< 0.1)\n"
                "with a penalty of 1 Pa/m they are %.4e m apart (their "
                "faces squeezed into each other): the check %s\n",
                d,
                t_wall - gap,
                apart ? "PASS" : "FAIL",
                gap / t_wall,
                d_through,
                passes ? "fails there, PASS" : "holds there, FAIL");
  bool ok = apart && passes;

  const double top    = s.get("obstacle1_force_z"),
               bottom = s.get("obstacle2_force_z");
  ok = pneuma_test::check("bottom roller's force vs minus the top's [N]",
                          -bottom,
                          top,
                          1e-10)
       && ok;
  // From the first state in contact to the end.
  double       roller0 = NAN, contact0 = NAN;
  unsigned int most = 0;
  if (root)
    for (unsigned int i = 0; i < s.history.size(); ++i)
      if (s.history[i].get("surface1_total_force") > 0.)
        {
          if (std::isnan(roller0))
            {
              roller0  = s.history[i].get("obstacle1_force_z");
              contact0 = s.history[i].get("surface1_total_force");
            }
          most = std::max(most, s.step_iterations[i - 1]);
        }
  roller0  = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, roller0);
  contact0 = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, contact0);
  most     = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, most);
  ok = pneuma_test::check("rise of the contact force vs rise of the roller "
                          "force, once in contact [N]",
                          s.get("surface1_total_force") - contact0,
                          top - roller0,
                          1e-3)
       && ok;
  if (root)
    std::printf("contact area %.4e m^2; Newton iterations per step in "
                "contact at most %u (<= 3) %s\n",
                s.get("surface1_contact_area"),
                most,
                most <= 3 ? "PASS" : "FAIL");
  ok = ok && most <= 3;
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
