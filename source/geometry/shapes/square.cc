/**
 * @file
 * A square of side L centred at the origin (material 0; edges x-, x+, y-,
 * y+ are boundaries 0..3): flat in the plane z = 0, or with a Rise h the
 * hyperbolic paraboloid z = 4 h x y / L^2 through the corners
 * (L/2, L/2, h), (-L/2, -L/2, h), (L/2, -L/2, -h), (-L/2, L/2, -h), whose
 * edges are straight (the four-point sail's start surface).
 */

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/surface_geometry.h>

#include <cmath>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      /// The chart (x, y) -> (x, y, k x y) of a hyperbolic paraboloid.
      class Hypar : public ChartManifold<2, 3, 2>
      {
      public:
        explicit Hypar(const double k)
          : k(k)
        {
        }
        std::unique_ptr<Manifold<2, 3>>
        clone() const override
        {
          return std::make_unique<Hypar>(k);
        }
        Point<2>
        pull_back(const Point<3> &x) const override
        {
          return Point<2>(x[0], x[1]);
        }
        Point<3>
        push_forward(const Point<2> &c) const override
        {
          return Point<3>(c[0], c[1], k * c[0] * c[1]);
        }
        DerivativeForm<1, 2, 3>
        push_forward_gradient(const Point<2> &c) const override
        {
          DerivativeForm<1, 2, 3> d;
          d[0][0] = 1.;
          d[1][1] = 1.;
          d[2][0] = k * c[1];
          d[2][1] = k * c[0];
          return d;
        }

      private:
        double k;
      };

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
          prm.add_parameter("Rise",
                            rise,
                            "Height h [m] of the corners (L/2, L/2) and "
                            "(-L/2, -L/2) above the centre, the other two "
                            "as far below: the hyperbolic paraboloid "
                            "z = 4 h x y / L^2 with straight edges; 0: flat.",
                            Patterns::Double());
        }
        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_length(side, path + "/Side length");
          check_input(std::abs(rise) <= 1e6,
                      path + "/Rise",
                      "must be finite and at most 1e6 m");
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
          if (rise != 0.)
            {
              const Hypar hypar(4. * rise / (side * side));
              GridTools::transform(
                [&](const Point<3> &x) {
                  return hypar.push_forward(Point<2>(x[0], x[1]));
                },
                coarse);
            }
        }
        void
        attach_manifolds(
          parallel::distributed::Triangulation<2, 3> &tria) const override
        {
          if (rise == 0.)
            return;
          tria.set_all_manifold_ids(curved_manifold);
          tria.set_manifold(curved_manifold, Hypar(4. * rise / (side * side)));
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
        double side = 2., rise = 0.;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(SurfaceGeometry,
                            Square,
                            "square",
                            "square of Side length, flat in the plane z = 0 "
                            "or a hyperbolic paraboloid of Rise h; edges x-, "
                            "x+, y-, y+ = boundaries 0..3")
  } // namespace geometry
} // namespace pneuma
