/**
 * @file
 * A 2D-in-3D Gmsh mesh (MSH 2.2 or 4.1 ASCII, quadrilaterals): physical
 * surfaces become material ids, physical curves boundary ids. Lines shared
 * by more than two cells (dividers, seams) are split by fans and tied
 * again after the dofs exist (geometry/junctions.h). The outside is as
 * meshed, flipped, or away from an interior point.
 */

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/gmsh_surface_reader.h>
#include <pneuma/geometry/junctions.h>
#include <pneuma/geometry/surface_geometry.h>

#include <fstream>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      class GmshMesh : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Mesh file",
                            mesh_file,
                            "Gmsh .msh file (format 2 or 4.1 ASCII), "
                            "relative to the working directory.",
                            Patterns::Anything());
          prm.add_parameter("Orientation",
                            orientation_mode,
                            "Which side is the outside (pressure pushes "
                            "outward).",
                            Patterns::Selection(
                              "as meshed|flipped|outward from interior point"));
          prm.add_parameter("Interior point",
                            interior,
                            "A point inside the closed surface [m] for "
                            "Orientation = outward from interior point.",
                            Patterns::List(Patterns::Double(), 3, 3));
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(!mesh_file.empty(), path + "/Mesh file", "is empty");
          std::ifstream in(mesh_file);
          check_input(static_cast<bool>(in),
                      path + "/Mesh file",
                      "cannot open '" + mesh_file + "'");
          parameter = path + "/Mesh file";
        }
        void
        create_coarse_mesh(Triangulation<2, 3> &coarse) const override
        {
          // Read as lists, split the junction lines per fan for p4est, then
          // order and create (gmsh_surface_reader.h, junctions.h).
          auto data = read_gmsh_surface(mesh_file, parameter);
          check_input(!data.cells.empty(),
                      parameter,
                      "'" + mesh_file + "' has no quadrilateral cells");
          split_junctions(data);
          create_from_surface_data(data, coarse);
          cell_warp = data.cell_warp;
          check_input(coarse.n_active_cells() > 0,
                      parameter,
                      "'" + mesh_file + "' has no surface cells");
        }
        double
        orientation(const Point<3> &x, const Tensor<1, 3> &n) const override
        {
          if (orientation_mode == "as meshed")
            return 1.;
          if (orientation_mode == "flipped")
            return -1.;
          const Point<3> c(interior[0], interior[1], interior[2]);
          return ((x - c) * n >= 0.) ? 1. : -1.;
        }
        bool
        is_closed() const override
        {
          return orientation_mode != "as meshed";
        }

        Tensor<1, 3>
        coarse_cell_direction(const unsigned int index) const override
        {
          return index < cell_warp.size() ? cell_warp[index] : Tensor<1, 3>();
        }

      private:
        /// The "warp" $ElementData vector of every cell (empty: none).
        mutable std::vector<Tensor<1, 3>> cell_warp;
        std::string         mesh_file, orientation_mode = "as meshed";
        std::vector<double> interior{0., 0., 0.};
        std::string         parameter = "Geometry/gmsh/Mesh file";
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            GmshMesh,
                            "gmsh",
                            "a Gmsh .msh surface: physical surfaces are "
                            "material ids, physical curves boundary ids")
  } // namespace geometry
} // namespace pneuma
