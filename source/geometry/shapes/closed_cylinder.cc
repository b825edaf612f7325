/**
 * @file
 * The closed cylinder of radius R along the x axis from 0 to L with flat
 * end caps: hull material 0 (on its cylindrical manifold), cap at x = 0
 * material 1, cap at x = L material 2 (the paper's airbeam tube, V2).
 */

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/surface_geometry.h>

#include <cmath>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      class ClosedCylinder : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Radius",
                            radius,
                            "Radius R [m]; > 0.",
                            Patterns::Double());
          prm.add_parameter("Length",
                            length,
                            "Length L along x [m]; > 0.",
                            Patterns::Double());
          prm.add_parameter("Cells along length",
                            cells_along_length,
                            "Coarse cells along the axis; 0 chooses nearly "
                            "square cells.",
                            Patterns::Integer(0, 1000));
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_length(radius, path + "/Radius");
          check_length(length, path + "/Length");
          n_axial =
            cylinder_cells_along(length, radius, cells_along_length, path);
        }
        void
        create_coarse_mesh(Triangulation<2, 3> &coarse) const override
        {
          // Surface of a solid cylinder: hull and two flat caps.
          Triangulation<3> solid;
          GridGenerator::subdivided_cylinder(solid,
                                             n_axial,
                                             radius,
                                             length / 2);
          GridTools::shift(Tensor<1, 3>({length / 2, 0., 0.}), solid);
          GridGenerator::extract_boundary_mesh(solid, coarse);
          for (const auto &cell : coarse.active_cell_iterators())
            {
              const double xc = cell->center()[0];
              cell->set_material_id(std::abs(xc) < 1e-8 * length ? 1
                                    : std::abs(xc - length) < 1e-8 * length
                                      ? 2
                                      : 0);
            }
        }
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->material_id() == 0)
              cell->set_all_manifold_ids(curved_manifold);
          tria.set_manifold(
            curved_manifold,
            CylindricalManifold<2, 3>(Tensor<1, 3>({1., 0., 0.}), Point<3>()));
        }
        double
        orientation(const Point<3> &x, const Tensor<1, 3> &n) const override
        {
          return ((x - Point<3>(0.5 * length, 0., 0.)) * n >= 0.) ? 1. : -1.;
        }
        bool
        is_closed() const override
        {
          return true;
        }

      private:
        double       radius = 0.23, length = 2.;
        unsigned int cells_along_length = 0;
        /// The coarse cells along the axis (parse_parameters()).
        unsigned int n_axial = 1;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            ClosedCylinder,
                            "closed cylinder",
                            "Radius and Length along x from 0 with flat caps; "
                            "hull material 0, caps 1 (x = 0) and 2 (x = L)")
  } // namespace geometry
} // namespace pneuma
