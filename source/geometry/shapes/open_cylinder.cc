/**
 * @file
 * The open cylinder (a tube without end caps) of radius R along the x axis
 * from 0 to L: material 0 on its cylindrical manifold, the ring edge at
 * x = 0 boundary 0 and the one at x = L boundary 1 (the catenoid between
 * two rings of form finding, a tube clamped at both ends).
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
      class OpenCylinder : public SurfaceGeometry
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
                            "Coarse cells along the axis (4 around); 0 "
                            "chooses nearly square cells.",
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
          // The hull (boundary 0) of a solid cylinder.
          Triangulation<3> solid;
          GridGenerator::subdivided_cylinder(solid,
                                             n_axial,
                                             radius,
                                             length / 2);
          GridTools::shift(Tensor<1, 3>({length / 2, 0., 0.}), solid);
          GridGenerator::extract_boundary_mesh(solid, coarse, {0});
          for (const auto &cell : coarse.active_cell_iterators())
            {
              cell->set_material_id(0);
              for (const auto f : cell->face_indices())
                if (cell->face(f)->at_boundary())
                  cell->face(f)->set_boundary_id(
                    cell->face(f)->center()[0] < 0.5 * length ? 0 : 1);
            }
        }
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          tria.set_all_manifold_ids(curved_manifold);
          tria.set_manifold(
            curved_manifold,
            CylindricalManifold<2, 3>(Tensor<1, 3>({1., 0., 0.}), Point<3>()));
        }
        double
        orientation(const Point<3> &x, const Tensor<1, 3> &n) const override
        {
          const Tensor<1, 3> radial({0., x[1], x[2]});
          return radial * n >= 0. ? 1. : -1.;
        }
        bool
        is_closed() const override
        {
          return false;
        }

      private:
        double       radius = 1., length = 1.;
        unsigned int cells_along_length = 0;
        /// The coarse cells along the axis (parse_parameters()).
        unsigned int n_axial = 1;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            OpenCylinder,
                            "open cylinder",
                            "tube of Radius and Length along x from 0 without "
                            "caps; material 0, ring edges boundaries 0 "
                            "(x = 0) and 1 (x = L)")
  } // namespace geometry
} // namespace pneuma
