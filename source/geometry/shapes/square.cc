/**
 * @file
 * A flat square of side L centred at the origin in the plane z = 0
 * (material 0; edges x-, x+, y-, y+ are boundaries 0..3).
 */

#include <deal.II/grid/grid_generator.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/surface_geometry.h>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      class Square : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Side length",
                            side,
                            "Side L [m]; > 0.",
                            Patterns::Double());
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(side > 0., path + "/Side length", "must be positive");
        }
        void
        create_coarse_mesh(Triangulation<2, 3> &coarse) const override
        {
          Triangulation<2> flat;
          GridGenerator::hyper_rectangle(flat,
                                         Point<2>(-side / 2, -side / 2),
                                         Point<2>(side / 2, side / 2),
                                         true);
          GridGenerator::flatten_triangulation(flat, coarse);
          for (const auto &cell : coarse.active_cell_iterators())
            cell->set_material_id(0);
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
        double side = 2.;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            Square,
                            "square",
                            "flat square of Side length in the plane z = 0, "
                            "edges x-, x+, y-, y+ = boundaries 0..3")
  } // namespace geometry
} // namespace pneuma
