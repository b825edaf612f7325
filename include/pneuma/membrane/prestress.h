#pragma once

/**
 * @file
 * Membrane prestress in the reference state (doc/theory.md "Prestress"):
 * a constant second Piola-Kirchhoff stress \f$S_0\f$ added to a law,
 * \f[ S = S_0 + S_{law}(C),\qquad W = S_0 : E + W_{law}(C), \f]
 * so the reference state carries the membrane forces \f$H S_0\f$ (N/m) and
 * the tangent is the law's. \f$S_0 = (n_1 e_1\otimes e_1 + n_2 e_2\otimes
 * e_2)/H\f$ in the region's material frame (warp, fill); with
 * \f$n_1 = n_2\f$ it is isotropic and needs no frame. Wrapped by the
 * tension field law, a prestressed point goes slack only once shortened to
 * the law's stress-free metric.
 */

#include <pneuma/membrane/constitutive_law.h>

#include <memory>

namespace pneuma
{
  namespace membrane
  {
    /// A law with a constant reference-state stress S_0.
    class PrestressedLaw : public ConstitutiveLaw
    {
    public:
      PrestressedLaw(std::shared_ptr<const ConstitutiveLaw> law,
                     const SymmetricTensor<2, 2>           &S0)
        : law(std::move(law))
        , S0(S0)
      {
      }

      /// The constants belong to the wrapped law.
      void
      declare_parameters(dealii::ParameterHandler &) override
      {
      }
      void
      parse_parameters(dealii::ParameterHandler &, const std::string &) override
      {
      }

      void
      evaluate(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S,
               SymmetricTensor<4, 2>       &dS_dE) const override
      {
        law->evaluate(C, S, dS_dE);
        S += S0;
      }

      double
      strain_energy(const SymmetricTensor<2, 2> &C) const override
      {
        return law->strain_energy(C)
               + S0 * (0.5 * (C - dealii::unit_symmetric_tensor<2>()));
      }

      double
      thickness_stretch(const SymmetricTensor<2, 2> &C) const override
      {
        return law->thickness_stretch(C);
      }

      double
      initial_shear_modulus() const override
      {
        return law->initial_shear_modulus();
      }

      bool
      isotropic() const override
      {
        return law->isotropic() && S0[0][0] == S0[1][1] && S0[0][1] == 0.;
      }

    private:
      std::shared_ptr<const ConstitutiveLaw> law;
      SymmetricTensor<2, 2>                  S0;
    };
  } // namespace membrane
} // namespace pneuma
