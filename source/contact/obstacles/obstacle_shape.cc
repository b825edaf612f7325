#include <deal.II/base/utilities.h>

#include <pneuma/contact/obstacles/obstacle_shape.h>
#include <pneuma/loads/loads.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace pneuma
{
  namespace contact
  {
    SignedDistance
    round_distance(const Tensor<1, 3> &projected,
                   const Tensor<1, 3> &axis,
                   const double        radius,
                   const bool          outside)
    {
      const double   sign = outside ? 1. : -1.;
      const double   r    = projected.norm();
      SignedDistance d;
      d.phi = sign * (r - radius);
      // Any unit direction normal to the axis where the radial one is
      // undefined (the point is then a radius deep in the obstacle).
      Tensor<1, 3> e;
      if (r > 1e-12 * radius)
        e = projected / r;
      else
        {
          Tensor<1, 3> trial;
          trial[std::abs(axis[0]) < 0.9 ? 0 : 1] = 1.;
          e = trial - (trial * axis) * axis;
          e /= e.norm();
        }
      d.normal = sign * e;
      if (r > 1e-12 * radius)
        {
          // d^2 r/dx^2 = (P - e e)/r with P the projector normal to the
          // axis (the identity for a sphere).
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              d.hessian[i][j] =
                sign * ((i == j ? 1. : 0.) - axis[i] * axis[j] - e[i] * e[j])
                / r;
        }
      return d;
    }

    Tensor<1, 3>
    parse_direction(const std::string &text, const std::string &path)
    {
      const Point<3> p      = loads::parse_point(text, path);
      const double   length = p.norm();
      check_input(length > 0. && std::isfinite(length),
                  path,
                  "'" + text + "' is not a direction (zero length)");
      return Tensor<1, 3>(p) / length;
    }

    std::string
    format_point(const Tensor<1, 3> &x)
    {
      std::ostringstream s;
      s << std::setprecision(4) << '(' << x[0] << ", " << x[1] << ", " << x[2]
        << ')';
      return s.str();
    }
  } // namespace contact
} // namespace pneuma
