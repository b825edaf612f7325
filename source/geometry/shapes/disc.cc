/**
 * @file
 * A flat disc of radius a in the plane z = 0 (material 0, rim boundary 0):
 * the rim follows its circle, the interior is blended by transfinite
 * interpolation (V1 Hencky membrane).
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
      class Disc : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Radius",
                            radius,
                            "Radius a [m]; > 0.",
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
          Triangulation<2> flat;
          GridGenerator::hyper_ball_balanced(flat, Point<2>(), radius);
          GridGenerator::flatten_triangulation(flat, coarse);
          for (const auto &cell : coarse.active_cell_iterators())
            cell->set_material_id(0);
        }
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          tria.set_all_manifold_ids(2);
          tria.set_all_manifold_ids_on_boundary(curved_manifold);
          tria.set_manifold(curved_manifold,
                            SphericalManifold<2, 3>(Point<3>()));
          TransfiniteInterpolationManifold<2, 3> transfinite;
          transfinite.initialize(tria);
          tria.set_manifold(2, transfinite);
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
        double radius = 0.23;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            Disc,
                            "disc",
                            "flat disc of Radius in the plane z = 0, rim "
                            "boundary 0")
  } // namespace geometry
} // namespace pneuma
