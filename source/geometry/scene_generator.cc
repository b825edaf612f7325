#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/gmsh_surface_reader.h>
#include <pneuma/geometry/junctions.h>
#include <pneuma/geometry/scene_generator.h>

#include <fstream>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      constexpr types::manifold_id curved_manifold = 1;
    }

    void
    SceneGenerator::declare_type(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Type",
                        "closed cylinder",
                        Patterns::Selection(
                          "disc|square|sphere|closed cylinder|gmsh|none"),
                        "Membrane surface: a built-in generator, a Gmsh "
                        "mesh file, or none (a scene of cables only).");
      prm.leave_subsection();
    }

    void
    SceneGenerator::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Radius",
                        "0.23",
                        Patterns::Double(),
                        "Radius [m] of disc, sphere or cylinder; must be > 0.");
      prm.declare_entry("Length",
                        "2",
                        Patterns::Double(),
                        "Cylinder length along x or square side [m]; > 0.");
      prm.declare_entry("Cells along length",
                        "0",
                        Patterns::Integer(0, 1000),
                        "Coarse cells along the cylinder axis; 0 chooses "
                        "nearly square cells.");
      prm.declare_entry("Global refinements",
                        "3",
                        Patterns::Integer(0, 12),
                        "Uniform refinements of the coarse mesh.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Gmsh .msh file (format 2 or 4.1 ASCII) for Type = "
                        "gmsh; relative to the working directory.");
      prm.declare_entry("Orientation",
                        "as meshed",
                        Patterns::Selection(
                          "as meshed|flipped|outward from interior point"),
                        "Gmsh meshes only: which side is the outside "
                        "(pressure pushes outward).");
      prm.declare_entry("Interior point",
                        "0,0,0",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "A point inside the closed surface [m] for "
                        "Orientation = outward from interior point.");
      prm.leave_subsection();
    }

    void
    SceneGenerator::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      geometry_type      = prm.get("Type");
      radius             = prm.get_double("Radius");
      length             = prm.get_double("Length");
      cells_along_length = prm.get_integer("Cells along length");
      refinements        = prm.get_integer("Global refinements");
      mesh_file          = prm.get("Mesh file");
      orientation_mode   = prm.get("Orientation");
      const auto p       = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Interior point")));
      interior_point = Point<3>(p[0], p[1], p[2]);
      prm.leave_subsection();

      check_input(radius > 0., "Geometry/Radius", "must be positive");
      check_input(length > 0., "Geometry/Length", "must be positive");
      if (geometry_type == "gmsh")
        {
          check_input(!mesh_file.empty(),
                      "Geometry/Mesh file",
                      "is empty but Type = gmsh");
          std::ifstream in(mesh_file);
          check_input(static_cast<bool>(in),
                      "Geometry/Mesh file",
                      "cannot open '" + mesh_file + "'");
        }
    }

    bool
    SceneGenerator::is_closed() const
    {
      return geometry_type == "sphere" || geometry_type == "closed cylinder"
             || (geometry_type == "gmsh" && orientation_mode != "as meshed");
    }

    double
    SceneGenerator::orientation(const Point<3> &x, const Tensor<1, 3> &n) const
    {
      if (geometry_type == "disc" || geometry_type == "square")
        return 1.;
      if (geometry_type == "gmsh")
        {
          if (orientation_mode == "as meshed")
            return 1.;
          if (orientation_mode == "flipped")
            return -1.;
          return ((x - interior_point) * n >= 0.) ? 1. : -1.;
        }
      const Point<3> centre = (geometry_type == "sphere")
                                ? Point<3>()
                                : Point<3>(0.5 * length, 0., 0.);
      return ((x - centre) * n >= 0.) ? 1. : -1.;
    }

    void
    SceneGenerator::create_triangulation(
      parallel::distributed::Triangulation<2, 3> &tria) const
    {
      Triangulation<2, 3> coarse;
      if (geometry_type == "disc")
        {
          Triangulation<2> flat;
          GridGenerator::hyper_ball_balanced(flat, Point<2>(), radius);
          GridGenerator::flatten_triangulation(flat, coarse);
        }
      else if (geometry_type == "square")
        {
          Triangulation<2> flat;
          GridGenerator::hyper_rectangle(flat,
                                         Point<2>(-length / 2, -length / 2),
                                         Point<2>(length / 2, length / 2),
                                         true);
          GridGenerator::flatten_triangulation(flat, coarse);
        }
      else if (geometry_type == "sphere")
        GridGenerator::hyper_sphere(coarse, Point<3>(), radius);
      else if (geometry_type == "closed cylinder")
        {
          // Surface of a solid cylinder: hull and two flat caps.
          const unsigned int n_axial =
            cells_along_length > 0
              ? cells_along_length
              : std::max(1u,
                         static_cast<unsigned int>(
                           std::round(length / (0.5 * M_PI * radius))));
          Triangulation<3> solid;
          GridGenerator::subdivided_cylinder(solid,
                                             n_axial,
                                             radius,
                                             length / 2);
          GridTools::shift(Tensor<1, 3>({length / 2, 0., 0.}), solid);
          GridGenerator::extract_boundary_mesh(solid, coarse);
        }
      else
        {
          // Read as lists, split the junction lines (more than two cells
          // on a line: dividers, shared seams) per fan for p4est, then
          // order and create (gmsh_surface_reader.h, junctions.h); the
          // copies are tied after the dofs exist.
          auto data = read_gmsh_surface(mesh_file, "Geometry/Mesh file");
          check_input(!data.cells.empty(),
                      "Geometry/Mesh file",
                      "'" + mesh_file + "' has no quadrilateral cells");
          split_junctions(data);
          create_from_surface_data(data, coarse);
          check_input(coarse.n_active_cells() > 0,
                      "Geometry/Mesh file",
                      "'" + mesh_file + "' has no surface cells");
        }

      // Material ids of the closed cylinder: hull 0, cap at x = 0 is 1,
      // cap at x = L is 2.
      if (geometry_type == "closed cylinder")
        for (const auto &cell : coarse.active_cell_iterators())
          {
            const double xc = cell->center()[0];
            cell->set_material_id(std::abs(xc) < 1e-8 * length            ? 1
                                  : std::abs(xc - length) < 1e-8 * length ? 2
                                                                          : 0);
          }
      else if (geometry_type != "gmsh")
        for (const auto &cell : coarse.active_cell_iterators())
          cell->set_material_id(0);

      tria.copy_triangulation(coarse);

      // Manifolds: curved surfaces and rims follow the true geometry.
      if (geometry_type == "sphere")
        {
          tria.set_all_manifold_ids(curved_manifold);
          tria.set_manifold(curved_manifold,
                            SphericalManifold<2, 3>(Point<3>()));
        }
      else if (geometry_type == "disc")
        {
          // Rim on a circle; interior blended by transfinite interpolation.
          tria.set_all_manifold_ids(2);
          tria.set_all_manifold_ids_on_boundary(curved_manifold);
          tria.set_manifold(curved_manifold,
                            SphericalManifold<2, 3>(Point<3>()));
          TransfiniteInterpolationManifold<2, 3> transfinite;
          transfinite.initialize(tria);
          tria.set_manifold(2, transfinite);
        }
      else if (geometry_type == "closed cylinder")
        {
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->material_id() == 0)
              cell->set_all_manifold_ids(curved_manifold);
          tria.set_manifold(
            curved_manifold,
            CylindricalManifold<2, 3>(Tensor<1, 3>({1., 0., 0.}), Point<3>()));
        }

      tria.refine_global(refinements);
    }
  } // namespace geometry
} // namespace pneuma
