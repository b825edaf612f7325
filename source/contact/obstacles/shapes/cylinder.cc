/**
 * @file
 * The infinite circular cylinder of Radius about the line through Point
 * along Axis: a roller or a loading saddle (the membrane outside,
 * phi = r - R with r the distance from the axis) or a pipe (inside,
 * phi = R - r).
 */

#include <pneuma/contact/obstacles/obstacle_shape.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/loads/loads.h>

#include <cmath>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      class Cylinder : public ObstacleShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Point",
                            point_text,
                            "x, y, z of a point of the axis [m].",
                            Patterns::Anything());
          prm.add_parameter("Axis",
                            axis_text,
                            "x, y, z of the axis direction (any length).",
                            Patterns::Anything());
          prm.add_parameter("Radius",
                            radius,
                            "Radius [m].",
                            Patterns::Double(0.));
          add_selection(prm,
                        "Side",
                        outside,
                        {{"outside", true}, {"inside", false}},
                        "Where the membrane stays: outside the cylinder (a "
                        "roller, a saddle) or inside it (a pipe).");
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          point = loads::parse_point(point_text, path + "/Point");
          axis  = parse_direction(axis_text, path + "/Axis");
          check_input(radius > 0. && std::isfinite(radius),
                      path + "/Radius",
                      "must be positive and finite");
        }

        SignedDistance
        distance(const Point<3> &x) const override
        {
          const Tensor<1, 3> d = x - point;
          return round_distance(d - (d * axis) * axis, axis, radius, outside);
        }

        std::string
        describe() const override
        {
          return "cylinder of radius " + std::to_string(radius)
                 + " m about the axis through " + format_point(point)
                 + " along " + format_point(axis) + ", membrane "
                 + (outside ? "outside" : "inside");
        }

      private:
        std::string  point_text = "0, 0, 0", axis_text = "0, 0, 1";
        double       radius  = 1.;
        bool         outside = true;
        Point<3>     point;
        Tensor<1, 3> axis;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ObstacleShape,
                            Cylinder,
                            "cylinder",
                            "the cylinder of Radius about the axis through "
                            "Point along Axis (a roller or saddle, or a pipe "
                            "with Side = inside)")
  } // namespace contact
} // namespace pneuma
