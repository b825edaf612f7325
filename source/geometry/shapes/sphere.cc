/**
 * @file
 * The sphere of radius R about the origin (material 0), on its spherical
 * manifold (V3 inflated sphere).
 */

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/surface_geometry.h>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      class Sphere : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Radius",
                            radius,
                            "Radius R [m]; > 0.",
                            Patterns::Double());
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_length(radius, path + "/Radius");
        }
        void
        create_coarse_mesh(Triangulation<2, 3> &coarse) const override
        {
          GridGenerator::hyper_sphere(coarse, Point<3>(), radius);
          for (const auto &cell : coarse.active_cell_iterators())
            cell->set_material_id(0);
        }
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          tria.set_all_manifold_ids(curved_manifold);
          tria.set_manifold(curved_manifold,
                            SphericalManifold<2, 3>(Point<3>()));
        }
        double
        orientation(const Point<3> &x, const Tensor<1, 3> &n) const override
        {
          return (x * n >= 0.) ? 1. : -1.;
        }
        bool
        is_closed() const override
        {
          return true;
        }

      private:
        double radius = 0.23;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            Sphere,
                            "sphere",
                            "sphere of Radius about the origin")
  } // namespace geometry
} // namespace pneuma
