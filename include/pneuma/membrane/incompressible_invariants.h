#pragma once

/**
 * @file
 * The invariants of an incompressible membrane in plane stress and their
 * derivatives with respect to the 2x2 right Cauchy-Green tensor C
 * (doc/theory.md "Membrane laws"): with the thickness stretch eliminated
 * exactly, \f$\lambda_3^2 = 1/\det C\f$,
 * \f$I_1 = \mathrm{tr}\,C + \lambda_3^2\f$ and
 * \f$I_2 = \det C + \lambda_3^2\,\mathrm{tr}\,C\f$. A law
 * \f$W(I_1, I_2)\f$ then has \f$S = 2(W_1 I_{1,C} + W_2 I_{2,C})\f$ and
 * \f$\mathbb{D} = 4(W_1 I_{1,CC} + W_2 I_{2,CC} + W_{11} I_{1,C}\otimes
 * I_{1,C} + \dots)\f$.
 */

#include <deal.II/base/symmetric_tensor.h>

namespace pneuma
{
  namespace membrane
  {
    /// I1, I2 of the incompressible plane-stress state and derivatives
    /// (the second ones only @p with_second: a stress without its tangent,
    /// as an explicit step needs, costs a third).
    struct IncompressibleInvariants
    {
      explicit IncompressibleInvariants(const dealii::SymmetricTensor<2, 2> &C,
                                        const bool with_second = true)
      {
        using namespace dealii;
        const SymmetricTensor<2, 2> I    = unit_symmetric_tensor<2>();
        const double                detC = determinant(C);
        const SymmetricTensor<2, 2> Ci   = invert(C);
        const double                trC  = trace(C);
        l3sq                             = 1. / detC;
        I1                               = trC + l3sq;
        I2                               = detC + l3sq * trC;
        dI1                              = I - l3sq * Ci;
        dI2 = detC * Ci + l3sq * I - trC * l3sq * Ci;
        if (!with_second)
          return;

        // (Ci (.) Ci)_{ijkl} = (Ci_ik Ci_jl + Ci_il Ci_jk)/2 = -dCi/dC.
        SymmetricTensor<4, 2> CioCi;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = i; j < 2; ++j)
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int l = k; l < 2; ++l)
                CioCi[i][j][k][l] =
                  0.5 * (Ci[i][k] * Ci[j][l] + Ci[i][l] * Ci[j][k]);
        const SymmetricTensor<4, 2> CixCi = outer_product(Ci, Ci);

        ddI1 = l3sq * (CixCi + CioCi);
        ddI2 = detC * (CixCi - CioCi)
               - l3sq * (outer_product(I, Ci) + outer_product(Ci, I))
               + trC * l3sq * (CixCi + CioCi);
      }

      double                        l3sq, I1, I2;
      dealii::SymmetricTensor<2, 2> dI1, dI2;
      /// Zero without the second derivatives.
      dealii::SymmetricTensor<4, 2> ddI1, ddI2;
    };
  } // namespace membrane
} // namespace pneuma
