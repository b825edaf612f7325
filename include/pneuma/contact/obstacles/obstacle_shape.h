#pragma once

/**
 * @file
 * The surface of a rigid obstacle (doc/theory.md "Rigid obstacles"): one
 * variant per shape, each one .cc file in source/contact/obstacles/shapes/
 * with one registration line (core/registry.h). The input chooses it with
 * "Obstacles/Obstacle <k>/Shape"; its constants live in the subsection of
 * its name, e.g. "Obstacles/Obstacle 1/sphere/Radius".
 *
 * A shape gives the signed distance \f$\varphi(x)\f$ of a point from its
 * surface, positive on the side where the membrane stays, with its
 * gradient \f$n = \nabla\varphi\f$ (the unit normal at the nearest point
 * of the surface) and its second derivative \f$\nabla\nabla\varphi\f$
 * (the curvature term of the contact tangent), for the obstacle in its
 * reference position; the caller applies the obstacle's motion.
 *
 * The registered shapes: "plane" (\f$\varphi = (x - P)\cdot n\f$),
 * "sphere" and "cylinder" (\f$\varphi = \pm(r - R)\f$ with r the distance
 * from the centre or the axis; + with the membrane outside).
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <pneuma/core/registry.h>

#include <string>

namespace pneuma
{
  namespace contact
  {
    using namespace dealii;

    /// The signed distance of a point from an obstacle's surface.
    struct SignedDistance
    {
      /// phi(x) [m], positive on the membrane's side.
      double phi = 0.;
      /// d phi / dx (unit length).
      Tensor<1, 3> normal;
      /// d^2 phi / dx^2 [1/m] (zero for a plane).
      SymmetricTensor<2, 3> hessian;
    };

    /// One kind of rigid obstacle surface.
    class ObstacleShape
    {
    public:
      virtual ~ObstacleShape() = default;

      /// Declare (and bind) the shape's constants in the current
      /// subsection.
      virtual void
      declare_parameters(ParameterHandler &prm) = 0;
      /// Check the constants; messages name @p path.
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &path) = 0;

      /// The signed distance of @p x from the surface in its reference
      /// position.
      virtual SignedDistance
      distance(const Point<3> &x) const = 0;

      /// One line for the log ("sphere of radius 0.2 m about (0, 0, 1),
      /// membrane outside").
      virtual std::string
      describe() const = 0;
    };

    /// The registry of obstacle shapes.
    using ObstacleShapeRegistry = Registry<ObstacleShape>;

    /**
     * The signed distance from a round surface: the points at distance
     * @p radius from a centre (a sphere, @p projected = x - C) or from an
     * axis (a cylinder, @p projected = the part of x - C normal to the
     * unit @p axis; pass a zero axis for a sphere). @p outside: the
     * membrane stays outside. At the centre or on the axis the normal is
     * undefined; there the point is deep inside the obstacle and an
     * arbitrary direction normal to the axis is taken.
     */
    SignedDistance
    round_distance(const Tensor<1, 3> &projected,
                   const Tensor<1, 3> &axis,
                   const double        radius,
                   const bool          outside);

    /// "x, y, z" of a unit direction given as text; InputError naming
    /// @p path if it is not three finite numbers of positive length.
    Tensor<1, 3>
    parse_direction(const std::string &text, const std::string &path);

    /// "(x, y, z)" with 4 significant digits, for messages.
    std::string
    format_point(const Tensor<1, 3> &x);
  } // namespace contact
} // namespace pneuma
