/**
 * @file
 * A flat annulus a <= r <= b in the plane z = 0 (material 0; the inner
 * edge, a hub, boundary 0 and the outer edge boundary 1): the membrane of
 * Mikulas' hub-torsion problem. The coarse rings are spaced geometrically,
 * r_i = a (b/a)^(i/n), so every cell has the same aspect ratio however
 * large b/a is, and all cells follow the plane's polar manifold.
 */

#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/surface_geometry.h>

#include <algorithm>
#include <cmath>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      class Annulus : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Inner radius",
                            inner,
                            "Radius a of the inner edge (boundary 0) [m]; "
                            "> 0.",
                            Patterns::Double());
          prm.add_parameter("Outer radius",
                            outer,
                            "Radius b of the outer edge (boundary 1) [m]; "
                            "> a.",
                            Patterns::Double());
          prm.add_parameter("Cells around",
                            cells_around,
                            "Coarse cells around the annulus (>= 4); the "
                            "rings are spaced so that the cells are nearly "
                            "square.",
                            Patterns::Integer(4, 1000));
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_length(inner, path + "/Inner radius");
          check_input(outer > inner,
                      path + "/Outer radius",
                      "must be larger than the Inner radius");
          check_length(outer, path + "/Outer radius");
        }
        void
        create_coarse_mesh(Triangulation<2, 3> &coarse) const override
        {
          // Rings r_i = a q^i with q^n = b/a and n such that the radial
          // step r (q - 1) is near the circumferential one 2 pi r / n_t.
          const unsigned int n_t       = cells_around;
          const double       log_ratio = std::log(outer / inner);
          const unsigned int n_r =
            std::max(1u,
                     static_cast<unsigned int>(
                       std::round(log_ratio * n_t / (2. * M_PI))));
          std::vector<Point<3>> vertices;
          for (unsigned int i = 0; i <= n_r; ++i)
            for (unsigned int j = 0; j < n_t; ++j)
              {
                const double r =
                  inner * std::exp(log_ratio * static_cast<double>(i) / n_r);
                const double phi = 2. * M_PI * j / n_t;
                vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), 0.);
              }
          // Lexicographic vertex order (r, then phi): normals along +z.
          std::vector<CellData<2>> cells;
          for (unsigned int i = 0; i < n_r; ++i)
            for (unsigned int j = 0; j < n_t; ++j)
              {
                const unsigned int j1 = (j + 1) % n_t;
                CellData<2>        cell;
                cell.vertices    = {i * n_t + j,
                                    (i + 1) * n_t + j,
                                    i * n_t + j1,
                                    (i + 1) * n_t + j1};
                cell.material_id = 0;
                cells.push_back(cell);
              }
          coarse.create_triangulation(vertices, cells, SubCellData());
          const double middle = std::sqrt(inner * outer);
          for (const auto &cell : coarse.active_cell_iterators())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                cell->face(f)->set_boundary_id(
                  cell->face(f)->center().norm() < middle ? 0 : 1);
        }
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          // Points of the plane z = 0 on a sphere about the origin: its
          // geodesics there are the circles r = const and the rays.
          tria.set_all_manifold_ids(curved_manifold);
          tria.set_manifold(curved_manifold,
                            SphericalManifold<2, 3>(Point<3>()));
        }
        double
        orientation(const Point<3> &, const Tensor<1, 3> &) const override
        {
          return 1.;
        }
        bool
        is_closed() const override
        {
          return false;
        }

      private:
        double       inner = 0.1, outer = 0.5;
        unsigned int cells_around = 16;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            Annulus,
                            "annulus",
                            "flat ring between Inner radius (boundary 0, a "
                            "hub) and Outer radius (boundary 1) in the plane "
                            "z = 0")
  } // namespace geometry
} // namespace pneuma
