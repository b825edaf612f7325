// The material frame read from Gmsh (doc/user-guide.md "Materials",
// Warp direction = gmsh): meshes/warp_panels.msh is a flat strip of
// length L = 1 m and width W = 0.25 m whose "warp" $ElementData view runs
// along x in the left half and along y in the right half (two panels of
// the same orthotropic fabric, E1 = 1 GPa, E2 = 0.25 GPa, nu12 = 0,
// G12 = 10 MPa, H = 1 mm, seamed across the strip). A dead line force
// q = 10 kN/m pulls the right edge along x, the left edge is held in x.
// With nu12 = 0 each half is in exact uniaxial stress: the stretch of a
// half whose modulus along x is E solves lambda (lambda^2 - 1) E / 2 =
// q / H (St. Venant-Kirchhoff, dead load), so the end moves
// L/2 (lambda(E1) - 1) + L/2 (lambda(E2) - 1). With the warp along x
// everywhere (Warp direction = 1, 0, 0) the end moves L (lambda(E1) - 1).
// A mesh without the view is an input error naming the entry.

#include "test_tools.h"

#include <pneuma/core/input_error.h>

#include <cmath>

namespace
{
  const double L = 1., H = 1e-3, E1 = 1e9, E2 = 2.5e8, q = 1e4;

  /// The uniaxial stretch of modulus E under q/H (Newton).
  double
  stretch(const double E)
  {
    double l = 1.;
    for (unsigned int k = 0; k < 50; ++k)
      l -= (0.5 * E * l * (l * l - 1.) - q / H) / (0.5 * E * (3. * l * l - 1.));
    return l;
  }

  pneuma_test::Settings
  strip(const std::string &mesh, const std::string &warp)
  {
    return {{"Geometry/Type", "gmsh"},
            {"Geometry/gmsh/Mesh file",
             std::string(PNEUMA_SOURCE_DIR) + "/meshes/" + mesh},
            {"Geometry/Global refinements", "1"},
            {"Materials/Region 1/Thickness", "1e-3"},
            {"Materials/Region 1/Law", "orthotropic"},
            {"Materials/Region 1/Warp direction", warp},
            {"Materials/Region 1/orthotropic/Warp modulus", "1e9"},
            {"Materials/Region 1/orthotropic/Fill modulus", "2.5e8"},
            {"Materials/Region 1/orthotropic/Poisson's ratio", "0"},
            {"Materials/Region 1/orthotropic/Shear modulus", "1e7"},
            {"Boundary conditions/Fixed boundaries", "1: xz"},
            {"Boundary conditions/Fixed points", "0, 0, 0: y; 1, 0, 0: z"},
            {"Loads/Line load boundaries", "2"},
            {"Loads/Line load/Function constants", "q=1e4"},
            {"Loads/Line load/Function expression", "q*t; 0; 0"},
            {"Load stepping/Stage end times", "1"},
            {"Load stepping/Initial increment", "0.5"},
            {"Output/Monitor points", "1, 0.125, 0"}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;

  const auto panels = pneuma_test::run(strip("warp_panels.msh", "gmsh"));
  ok = pneuma_test::check("two panels (warp from Gmsh): end displacement [m]",
                          panels.summary.get_vector("m0_u")[0],
                          0.5 * L * (stretch(E1) - 1.)
                            + 0.5 * L * (stretch(E2) - 1.),
                          1e-8)
       && ok;
  const auto along = pneuma_test::run(strip("warp_panels.msh", "1, 0, 0"));
  ok = pneuma_test::check("warp along x everywhere: end displacement [m]",
                          along.summary.get_vector("m0_u")[0],
                          L * (stretch(E1) - 1.),
                          1e-8)
       && ok;

  // A mesh file without the "warp" view.
  bool named = false;
  try
    {
      pneuma_test::make(
        {{"Geometry/Type", "gmsh"},
         {"Geometry/gmsh/Mesh file",
          std::string(PNEUMA_SOURCE_DIR) + "/meshes/square_plate.msh"},
         {"Materials/Region 0/Law", "orthotropic"},
         {"Materials/Region 0/Warp direction", "gmsh"},
         {"Boundary conditions/Fixed boundaries", "1: xyz"}});
    }
  catch (const pneuma::InputError &e)
    {
      named = std::string(e.what()).find("Warp direction") != std::string::npos;
    }
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("a mesh without \"warp\" data: input error naming the Warp "
                "direction: %s\n",
                named ? "yes" : "no (FAIL)");
  ok = ok && named;
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
