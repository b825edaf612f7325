#include <deal.II/base/numbers.h>

#include <pneuma/cables/circular_curve.h>
#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>

#include <cmath>

namespace pneuma
{
  namespace cables
  {
    void
    CircularCurve::declare_parameters(ParameterHandler &prm)
    {
      prm.add_parameter("Centre",
                        centre_text,
                        "A point on the axis [m]: a ring lies in the plane "
                        "through it, a helix starts there.",
                        Patterns::Anything());
      prm.add_parameter("Axis",
                        axis_text,
                        "Axis direction (need not be unit).",
                        Patterns::Anything());
      prm.add_parameter("Reference direction",
                        reference_text,
                        "The direction (projected normal to the axis) of "
                        "angle 0.",
                        Patterns::Anything());
      prm.add_parameter("Radius",
                        radius_,
                        "Radius of the mid-line [m]; > 0.",
                        Patterns::Double(0.));
      prm.add_parameter("Start angle",
                        start_angle_degrees,
                        "Angle of the first node from the reference "
                        "direction [degrees].",
                        Patterns::Double());
    }

    void
    CircularCurve::parse_parameters(const std::string &path)
    {
      centre = loads::parse_point(centre_text, path + "/Centre");
      const Tensor<1, 3> axis(loads::parse_point(axis_text, path + "/Axis"));
      const Tensor<1, 3> reference(
        loads::parse_point(reference_text, path + "/Reference direction"));
      check_input(axis.norm() > 0.,
                  path + "/Axis",
                  "the axis must not be zero");
      const Tensor<1, 3> e = axis / axis.norm();
      check_input((reference - (reference * e) * e).norm()
                    > 1e-12 * reference.norm(),
                  path + "/Reference direction",
                  "must not be parallel to the axis");
      check_input(radius_ > 0., path + "/Radius", "must be > 0");
      Tensor<1, 3> e1 = reference - (reference * e) * e;
      e1 /= e1.norm();
      frame       = {{e1, cross_product_3d(e, e1), e}};
      start_angle = start_angle_degrees * numbers::PI / 180.;
    }

    Point<3>
    CircularCurve::point(const double phi,
                         const double pitch,
                         const bool   right_handed) const
    {
      const double s     = right_handed ? 1. : -1.;
      const double angle = start_angle + s * phi;
      return centre + pitch * phi / (2. * numbers::PI) * frame[2]
             + radius_
                 * (std::cos(angle) * frame[0] + std::sin(angle) * frame[1]);
    }

    Tensor<1, 3>
    CircularCurve::radial_direction(const Point<3> &X) const
    {
      Tensor<1, 3> e1 = X - centre;
      e1 -= (e1 * frame[2]) * frame[2];
      return e1;
    }
  } // namespace cables
} // namespace pneuma
