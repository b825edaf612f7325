/**
 * @file
 * The sphere of Radius about Centre: an indenter (the membrane outside,
 * phi = |x - C| - R) or a spherical cup (inside, phi = R - |x - C|).
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
      class Sphere : public ObstacleShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Centre",
                            centre_text,
                            "x, y, z of the centre [m].",
                            Patterns::Anything());
          prm.add_parameter("Radius",
                            radius,
                            "Radius [m].",
                            Patterns::Double(0.));
          add_selection(prm,
                        "Side",
                        outside,
                        {{"outside", true}, {"inside", false}},
                        "Where the membrane stays: outside the ball (an "
                        "indenter) or inside the spherical surface (a "
                        "cup).");
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          centre = loads::parse_point(centre_text, path + "/Centre");
          check_input(radius > 0. && std::isfinite(radius),
                      path + "/Radius",
                      "must be positive and finite");
        }

        SignedDistance
        distance(const Point<3> &x) const override
        {
          return round_distance(x - centre, Tensor<1, 3>(), radius, outside);
        }

        std::string
        describe() const override
        {
          return "sphere of radius " + std::to_string(radius) + " m about "
                 + format_point(centre) + ", membrane "
                 + (outside ? "outside" : "inside");
        }

      private:
        std::string centre_text = "0, 0, 0";
        double      radius      = 1.;
        bool        outside     = true;
        Point<3>    centre;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ObstacleShape,
                            Sphere,
                            "sphere",
                            "the sphere of Radius about Centre (an indenter, "
                            "or a cup with Side = inside)")
  } // namespace contact
} // namespace pneuma
