#pragma once

/**
 * @file
 * Quadrature for the wetted part of a cell cut by a liquid's free surface
 * (doc/theory.md "Liquid").
 *
 * On the reference cell the level-set function
 * \f$\psi(\xi) = z(x(\xi)) - h\f$ (height above the free surface, z
 * against gravity) is a polynomial of the element degree, since the mapped
 * reference position and the displacement are. It is interpolated exactly
 * by FE_Q at its support points, and deal.II's NonMatching
 * QuadratureGenerator (Saye's algorithm, high order) integrates the part
 * \f$\psi < 0\f$. The wetted integrals are therefore continuous in the
 * level and in the nodal positions, which Newton needs when the free
 * surface moves across cells; counting quadrature points would make them
 * jump.
 */

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/non_matching/quadrature_generator.h>

#include <vector>

namespace pneuma
{
  namespace chambers
  {
    using namespace dealii;

    /// Wetted-part quadrature of cells of one element degree.
    class FreeSurfaceQuadrature
    {
    public:
      /// @p degree: element degree; @p n_points: 1D Gauss points.
      FreeSurfaceQuadrature(const unsigned int degree,
                            const unsigned int n_points);

      /// Where a cell lies relative to the free surface.
      enum class Location
      {
        dry,
        wet,
        cut
      };

      /// Reference points at which psi must be given to classify().
      const std::vector<Point<2>> &
      support_points() const
      {
        return points;
      }

      /**
       * Classify a cell by the heights @p psi (one per support point) of
       * its current position above the free surface; for a cut cell
       * wet_quadrature() then holds the rule for its wetted part.
       */
      Location
      classify(const std::vector<double> &psi_in);

      const Quadrature<2> &
      wet_quadrature() const
      {
        return generator.get_inside_quadrature();
      }

    private:
      FE_Q<2>               fe;
      std::vector<Point<2>> points;
      std::vector<double>   psi;
      /// Must outlive the generator, which keeps a pointer to it.
      hp::QCollection<1>                  quadrature_1d;
      NonMatching::QuadratureGenerator<2> generator;
    };
  } // namespace chambers
} // namespace pneuma
