/**
 * @file
 * A 2D-in-3D Gmsh mesh (MSH 2.2 or 4.1 ASCII, quadrilaterals): physical
 * surfaces become material ids, physical curves boundary ids. Lines shared
 * by more than two cells (dividers, seams) are split by fans and tied
 * again after the dofs exist (geometry/junctions.h). The outside is as
 * meshed, flipped, or away from an interior point. Regions declared
 * curved (a sphere or a cylinder) get a manifold: refinement puts new
 * vertices on the true surface and a degree-2 mapping follows it.
 */

#include <deal.II/grid/manifold_lib.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/geometry/gmsh_surface_reader.h>
#include <pneuma/geometry/junctions.h>
#include <pneuma/geometry/surface_geometry.h>
#include <pneuma/loads/loads.h>

#include <fstream>
#include <memory>
#include <sstream>

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
          add_selection(prm,
                        "Orientation",
                        orientation_mode,
                        {{"as meshed", Orientation::as_meshed},
                         {"flipped", Orientation::flipped},
                         {"outward from interior point",
                          Orientation::outward_from_interior_point}},
                        "Which side is the outside (pressure pushes "
                        "outward).");
          prm.add_parameter(
            "Curved regions",
            curved_text,
            "Regions whose surface is a sphere or a cylinder, so that "
            "refinement and the degree-2 mapping follow it instead of the "
            "flat facets of the file: 'ids: sphere cx, cy, cz' or 'ids: "
            "cylinder px, py, pz, dx, dy, dz' (a point on the axis and its "
            "direction), separated by ';' (empty: all flat). The vertices "
            "of each region must lie on its surface (to 1e-3 of its radius); "
            "a line shared by two regions follows the later one.",
            Patterns::Anything());
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
          parse_curved(path + "/Curved regions");
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
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          for (unsigned int k = 0; k < curved.size(); ++k)
            {
              const Curved &c = curved[k];
              // The coarse mesh is on every rank: all check alike.
              double lo = std::numeric_limits<double>::max(), hi = 0.;
              for (const auto &cell : tria.active_cell_iterators())
                if (c.ids.count(cell->material_id()))
                  {
                    cell->set_all_manifold_ids(first_manifold + k);
                    for (const auto v : cell->vertex_indices())
                      {
                        const double r = c.radius(cell->vertex(v));
                        lo             = std::min(lo, r);
                        hi             = std::max(hi, r);
                      }
                  }
              check_input(hi > 0.,
                          curved_path,
                          "the mesh has no cells in the regions of item "
                            + std::to_string(k + 1));
              std::ostringstream where;
              where << "item " << k + 1 << ": the vertices lie between " << lo
                    << " and " << hi << " m from the "
                    << (c.sphere ? "centre" : "axis") << ", not on one "
                    << (c.sphere ? "sphere" : "cylinder");
              check_input(hi - lo <= 1e-3 * hi, curved_path, where.str());
              if (c.sphere)
                tria.set_manifold(first_manifold + k,
                                  SphericalManifold<2, 3>(c.point));
              else
                tria.set_manifold(first_manifold + k,
                                  CylindricalManifold<2, 3>(c.direction,
                                                            c.point));
            }
        }
        double
        orientation(const Point<3> &x, const Tensor<1, 3> &n) const override
        {
          if (orientation_mode == Orientation::as_meshed)
            return 1.;
          if (orientation_mode == Orientation::flipped)
            return -1.;
          const Point<3> c(interior[0], interior[1], interior[2]);
          return ((x - c) * n >= 0.) ? 1. : -1.;
        }
        bool
        is_closed() const override
        {
          return orientation_mode != Orientation::as_meshed;
        }

        Tensor<1, 3>
        coarse_cell_direction(const unsigned int index) const override
        {
          return index < cell_warp.size() ? cell_warp[index] : Tensor<1, 3>();
        }

      private:
        /// One item of "Curved regions".
        struct Curved
        {
          std::set<unsigned int> ids;
          bool                   sphere = true;
          Point<3>               point;
          Tensor<1, 3>           direction;
          /// Distance from the centre or the axis.
          double
          radius(const Point<3> &x) const
          {
            const Tensor<1, 3> r = x - point;
            return sphere ? r.norm() : (r - (r * direction) * direction).norm();
          }
        };
        static constexpr types::manifold_id first_manifold = 1;

        void
        parse_curved(const std::string &path)
        {
          curved.clear();
          curved_path = path;
          for (const auto &item :
               Utilities::split_string_list(curved_text, ';'))
            {
              const auto colon = item.find(':');
              check_input(colon != std::string::npos,
                          path,
                          "'" + item
                            + "' is not 'ids: sphere ...' or 'ids: "
                              "cylinder ...'");
              Curved c;
              c.ids = loads::parse_id_list(item.substr(0, colon), path);
              std::istringstream rest(item.substr(colon + 1));
              std::string        kind;
              rest >> kind;
              std::string numbers;
              std::getline(rest, numbers);
              const auto values = Utilities::split_string_list(numbers, ',');
              check_input((kind == "sphere" && values.size() == 3)
                            || (kind == "cylinder" && values.size() == 6),
                          path,
                          "'" + item
                            + "': give 'sphere cx, cy, cz' or "
                              "'cylinder px, py, pz, dx, dy, dz'");
              std::vector<double> x;
              for (const auto &v : values)
                {
                  try
                    {
                      x.push_back(Utilities::string_to_double(v));
                    }
                  catch (...)
                    {
                      throw InputError(path, "'" + v + "' is not a number");
                    }
                }
              c.sphere = kind == "sphere";
              c.point  = Point<3>(x[0], x[1], x[2]);
              if (!c.sphere)
                {
                  c.direction = Tensor<1, 3>({x[3], x[4], x[5]});
                  check_input(c.direction.norm() > 0.,
                              path,
                              "'" + item + "': the axis direction is zero");
                  c.direction /= c.direction.norm();
                }
              curved.push_back(c);
            }
        }

        std::string         curved_text, curved_path;
        std::vector<Curved> curved;
        /// The "warp" $ElementData vector of every cell (empty: none).
        mutable std::vector<Tensor<1, 3>> cell_warp;
        /// Which side is the outside.
        enum class Orientation
        {
          as_meshed,
          flipped,
          outward_from_interior_point
        };
        std::string         mesh_file;
        Orientation         orientation_mode = Orientation::as_meshed;
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
