#pragma once

/**
 * @file
 * The circle about an axis that the ring and helix shapes share
 * (shapes/ring.cc, shapes/helix.cc; doc/theory.md §8): with the unit axis
 * \f$e_3\f$, the reference direction projected normal to it \f$e_1\f$,
 * \f$e_2 = e_3\times e_1\f$, the centre C, radius R and start angle
 * \f$\phi_0\f$, the point at the parameter angle \f$\varphi\f$ is
 * \f[ X(\varphi) = C + \frac{h\varphi}{2\pi}\,e_3
 *     + R\,(\cos\phi\,e_1 + \sin\phi\,e_2),\qquad
 *     \phi = \phi_0 \pm \varphi, \f]
 * with the pitch h (zero for a ring) and + for a right-handed turn about
 * \f$e_3\f$.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>

namespace pneuma
{
  namespace cables
  {
    using namespace dealii;

    /// Centre, axis, reference direction, radius and start angle.
    class CircularCurve
    {
    public:
      /// Declare (and bind) Centre, Axis, Reference direction, Radius and
      /// Start angle in the current subsection.
      void
      declare_parameters(ParameterHandler &prm);
      /// Read and check them; messages name @p path (the shape's
      /// subsection).
      void
      parse_parameters(const std::string &path);

      /// X at the parameter angle @p phi for the pitch @p pitch, turning
      /// right-handed about the axis if @p right_handed.
      Point<3>
      point(const double phi,
            const double pitch,
            const bool   right_handed = true) const;

      /// The outward radial direction at @p X: X - C without its axial
      /// part (not normalised).
      Tensor<1, 3>
      radial_direction(const Point<3> &X) const;

      /// Radius R [m].
      double
      radius() const
      {
        return radius_;
      }

    private:
      std::string centre_text = "0, 0, 0", axis_text = "1, 0, 0",
                  reference_text = "0, 0, 1";
      double radius_ = 1., start_angle_degrees = 0.;

      Point<3> centre;
      /// e1, e2, e3 (the unit axis).
      std::array<Tensor<1, 3>, 3> frame;
      double                      start_angle = 0.;
    };
  } // namespace cables
} // namespace pneuma
