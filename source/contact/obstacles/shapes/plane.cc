/**
 * @file
 * The plane through Point with unit Normal pointing to the membrane's
 * side: phi = (x - P).n, the ground or a loading plate.
 */

#include <pneuma/contact/obstacles/obstacle_shape.h>
#include <pneuma/loads/loads.h>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      class Plane : public ObstacleShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Point",
                            point_text,
                            "x, y, z of a point of the plane [m].",
                            Patterns::Anything());
          prm.add_parameter("Normal",
                            normal_text,
                            "x, y, z of the plane's normal, pointing to the "
                            "side where the membrane stays (any length).",
                            Patterns::Anything());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          point  = loads::parse_point(point_text, path + "/Point");
          normal = parse_direction(normal_text, path + "/Normal");
        }

        SignedDistance
        distance(const Point<3> &x) const override
        {
          SignedDistance d;
          d.phi    = (x - point) * normal;
          d.normal = normal;
          return d;
        }

        std::string
        describe() const override
        {
          return "plane through " + format_point(point) + " with normal "
                 + format_point(normal);
        }

      private:
        std::string  point_text = "0, 0, 0", normal_text = "0, 0, 1";
        Point<3>     point;
        Tensor<1, 3> normal;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ObstacleShape,
                            Plane,
                            "plane",
                            "the plane through Point with Normal towards the "
                            "membrane (the ground, a loading plate)")
  } // namespace contact
} // namespace pneuma
