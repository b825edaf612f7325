#pragma once

/**
 * @file
 * Total-Lagrangian kinematics of a membrane on a codimension-one mesh.
 *
 * At a point of the reference surface with unit normal N we pick an
 * orthonormal tangent basis (e_1, e_2, N). deal.II's shape gradients on a
 * `FEValues<2,3>` are surface gradients, so the surface deformation gradient
 * is \f$F = P + \nabla_S u\f$ (\f$P = I - N\otimes N\f$) and the deformed
 * tangent vectors are \f$a_\alpha = F e_\alpha = e_\alpha + (\nabla_S u)
 * e_\alpha\f$. The membrane metric is \f$C_{\alpha\beta} = a_\alpha\cdot
 * a_\beta\f$ and the current area element is \f$n\,da = a_1\times a_2\,dA\f$.
 * For an isotropic law the choice of e_1 in the tangent plane does not
 * matter; an anisotropic one takes e_1 along the region's warp direction.
 */

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    using dealii::SymmetricTensor;
    using dealii::Tensor;

    /// Orthonormal reference frame (e_1, e_2, N) at a surface point.
    struct TangentFrame
    {
      std::array<Tensor<1, 3>, 2> e;
      Tensor<1, 3>                N;
    };

    /// A right-handed frame with e_1 x e_2 = @p normal (unit length).
    inline TangentFrame
    tangent_frame(const Tensor<1, 3> &normal)
    {
      TangentFrame f;
      f.N = normal / normal.norm();
      // Start from the axis least aligned with N.
      unsigned int k = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(f.N[d]) < std::abs(f.N[k]))
          k = d;
      Tensor<1, 3> t;
      t[k]   = 1.;
      t      = t - (t * f.N) * f.N;
      f.e[0] = t / t.norm();
      f.e[1] = dealii::cross_product_3d(f.N, f.e[0]);
      return f;
    }

    /**
     * The material frame of an anisotropic region: e_1 along the
     * projection of @p warp onto the tangent plane, e_2 = N x e_1. A zero
     * @p warp, or one along the normal, gives tangent_frame(normal);
     * anisotropic regions are checked at setup to have at least 0.1 of
     * the warp in the surface everywhere.
     */
    inline TangentFrame
    tangent_frame(const Tensor<1, 3> &normal, const Tensor<1, 3> &warp)
    {
      TangentFrame       f = tangent_frame(normal);
      const Tensor<1, 3> t = warp - (warp * f.N) * f.N;
      if (t.norm() <= 1e-3 * warp.norm() || warp.norm() == 0.)
        return f;
      f.e[0] = t / t.norm();
      f.e[1] = dealii::cross_product_3d(f.N, f.e[0]);
      return f;
    }

    /// The deformed tangent vectors a_alpha = e_alpha + grad_u e_alpha.
    inline std::array<Tensor<1, 3>, 2>
    deformed_tangents(const TangentFrame &frame, const Tensor<2, 3> &grad_u)
    {
      return {
        {frame.e[0] + grad_u * frame.e[0], frame.e[1] + grad_u * frame.e[1]}};
    }

    /// The 2x2 right Cauchy-Green tensor C_ab = a_a . a_b.
    inline SymmetricTensor<2, 2>
    right_cauchy_green(const std::array<Tensor<1, 3>, 2> &a)
    {
      SymmetricTensor<2, 2> C;
      C[0][0] = a[0] * a[0];
      C[1][1] = a[1] * a[1];
      C[0][1] = a[0] * a[1];
      return C;
    }

    /**
     * Cauchy membrane force tensor per unit current length,
     * \f$n = \frac{H}{j}\sum_{\alpha\beta} S_{\alpha\beta}\,a_\alpha\otimes
     * a_\beta\f$ with the area stretch \f$j = |a_1\times a_2|\f$.
     */
    inline SymmetricTensor<2, 3>
    membrane_forces(const std::array<Tensor<1, 3>, 2> &a,
                    const SymmetricTensor<2, 2>       &S,
                    const double                       thickness)
    {
      const double          j = dealii::cross_product_3d(a[0], a[1]).norm();
      SymmetricTensor<2, 3> n;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int k = i; k < 3; ++k)
          {
            double v = 0;
            for (unsigned int al = 0; al < 2; ++al)
              for (unsigned int be = 0; be < 2; ++be)
                v += S[al][be] * a[al][i] * a[be][k];
            n[i][k] = thickness / j * v;
          }
      return n;
    }
  } // namespace membrane
} // namespace pneuma
