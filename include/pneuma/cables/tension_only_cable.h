#pragma once

/**
 * @file
 * The kernel of the tension-only cable (truss) at one point of the mid-line
 * (doc/theory.md §8.1); the element "cable" (elements/cable.cc) chains it
 * with the shape functions.
 *
 * With S the reference arc length, x' = dx/dS the current tangent and
 * rho = L_ref / L_0 the ratio of reference to unstressed length (rho > 1
 * for a prestressed cable, rho < 1 for a slack one), the stretch against
 * the unstressed state is lambda = rho |x'|, and the axial force follows
 * Hooke's law on the engineering strain (Irvine's elastic cable):
 * \f[ N = EA_\mathrm{eff}\,(\lambda - 1), \qquad
 *     EA_\mathrm{eff} = EA \text{ if } \lambda \ge 1,\ r\,EA \text{ else}, \f]
 * with the slack ratio r (1e-6 by default): a slack cable carries next to
 * nothing, but the matrix stays regular. The energy per reference length is
 * W = EA_eff (lambda - 1)^2 / (2 rho), so that the internal virtual work is
 * \f$\int N\,e\cdot\delta x'\,dS\f$ with e = x'/|x'|, and its consistent
 * tangent is
 * \f[ \frac{\partial (N e)}{\partial x'} = EA_\mathrm{eff}\,\rho\, e\otimes e
 *     + \frac{N}{|x'|}\,(I - e\otimes e). \f]
 */

#include <deal.II/base/tensor.h>

namespace pneuma
{
  namespace cables
  {
    using namespace dealii;

    /// Axial response of a tension-only cable at one point.
    struct CablePoint
    {
      /// Stretch against the unstressed length, and axial force [N].
      double stretch = 1., force = 0.;
      /// Force vector N e (the conjugate of x').
      Tensor<1, 3> force_vector;
      /// d(N e)/dx'.
      Tensor<2, 3> tangent;
    };

    /// The cable law of one cable.
    class TensionOnlyCable
    {
    public:
      TensionOnlyCable(const double axial_stiffness,
                       const double length_ratio,
                       const double slack_ratio);

      /// Response at current tangent @p dx_dS (reference arc length S).
      CablePoint
      evaluate(const Tensor<1, 3> &dx_dS) const;

    private:
      double EA, rho, slack;
    };
  } // namespace cables
} // namespace pneuma
