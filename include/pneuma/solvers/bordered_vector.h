#pragma once

/**
 * @file
 * The unknowns Newton iterates on: the distributed finite element field
 * (membrane displacements) bordered by a few global scalars (the chamber
 * pressures and free-surface levels, doc/theory.md "Chambers"). The scalars
 * are replicated on every rank; every rank computes the same values, so
 * norms need one reduction of the field part only.
 */

#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>

#include <cmath>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    /// A distributed field with a small replicated border.
    struct BorderedVector
    {
      LA::Vector     field;
      Vector<double> border;

      BorderedVector &
      operator=(const double s)
      {
        field  = s;
        border = s;
        return *this;
      }

      BorderedVector &
      operator*=(const double s)
      {
        field *= s;
        border *= s;
        return *this;
      }

      BorderedVector &
      operator-=(const BorderedVector &v)
      {
        field -= v.field;
        border -= v.border;
        return *this;
      }

      /// this += a v
      void
      add(const double a, const BorderedVector &v)
      {
        field.add(a, v.field);
        border.add(a, v.border);
      }

      /// Scalar product (field and border).
      double
      operator*(const BorderedVector &v) const
      {
        return field * v.field + border * v.border;
      }

      double
      l2_norm() const
      {
        const double f = field.l2_norm();
        return std::sqrt(f * f + border.norm_sqr());
      }
    };
  } // namespace solvers
} // namespace pneuma
