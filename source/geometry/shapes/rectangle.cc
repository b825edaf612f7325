/**
 * @file
 * A flat rectangle of Length along x and Width along y centred at the
 * origin in the plane z = 0 (material 0; edges x-, x+, y-, y+ are
 * boundaries 0..3, as for the square), cut into nearly square coarse
 * cells: a sheet in shear (Wong & Pellegrino), a strip.
 */

#include <deal.II/grid/grid_generator.h>

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
      class Rectangle : public SurfaceGeometry
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Length",
                            length,
                            "Side along x [m]; > 0.",
                            Patterns::Double());
          prm.add_parameter("Width",
                            width,
                            "Side along y [m]; > 0.",
                            Patterns::Double());
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_length(length, path + "/Length");
          check_length(width, path + "/Width");
        }
        void
        create_coarse_mesh(Triangulation<2, 3> &coarse) const override
        {
          // The shorter side one cell, the longer as many as keep the
          // cells nearly square.
          const double       shorter = std::min(length, width);
          const unsigned int nx = std::max(1., std::round(length / shorter));
          const unsigned int ny = std::max(1., std::round(width / shorter));
          Triangulation<2>   flat;
          GridGenerator::subdivided_hyper_rectangle(
            flat,
            {nx, ny},
            Point<2>(-length / 2, -width / 2),
            Point<2>(length / 2, width / 2),
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
        double length = 3., width = 1.;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            Rectangle,
                            "rectangle",
                            "flat rectangle of Length (x) and Width (y) in "
                            "the plane z = 0; edges x-, x+, y-, y+ = "
                            "boundaries 0..3")
  } // namespace geometry
} // namespace pneuma
