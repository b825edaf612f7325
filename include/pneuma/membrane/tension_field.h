#pragma once

/**
 * @file
 * Wrinkling by tension field theory as a relaxed strain energy (Pipkin
 * 1986), wrapped around any membrane law (doc/theory.md "Wrinkling").
 *
 * A membrane buckles at once under compression into fine wrinkles; on the
 * scale of the mesh the wrinkled sheet has a mean metric C smaller than the
 * metric C* of its material. The relaxed energy is
 * \f[
 *   W_r(C) = \min_{C^* \succeq C} W(C^*),
 * \f]
 * the least energy of any material metric that wrinkles down to C
 * (\f$C^*-C\f$ positive semi-definite). Its stress is \f$S_r = S(C^*)\f$
 * and the three states are the three ranks of the optimality condition:
 * - taut: \f$S(C) \succeq 0\f$, \f$C^* = C\f$;
 * - slack: the stress-free metric \f$C_0\f$ (S(C_0) = 0) satisfies
 *   \f$C_0 \succeq C\f$; \f$S_r = 0\f$;
 * - wrinkled: \f$C^* = C + \beta\, m\otimes m\f$ with \f$\beta > 0\f$ and
 *   \f$S(C^*) m = 0\f$, i.e. uniaxial tension \f$S_r = t\, p\otimes p\f$
 *   along \f$p \perp m\f$ (the direction of the wrinkles' crests).
 * This is the mixed stress-strain criterion of Roddeman et al. (1987) and
 * Raible et al. (2005): taut when the minor principal stress is positive,
 * slack when the major principal strain is not, wrinkled otherwise; for an
 * anisotropic law the wrinkle angle is solved for, not assumed along the
 * principal strains. The two unknowns (beta, angle of m) are found by
 * Newton's method on \f$(m\cdot S^* m,\; p\cdot S^* m) = 0\f$, and the
 * tangent \f$\partial S_r/\partial E\f$ follows by implicit
 * differentiation; it is the symmetric second derivative of \f$W_r\f$.
 *
 * \f$W_r\f$ is once continuously differentiable: the stress is continuous
 * across state changes, the tangent jumps (as in plasticity). A fraction
 * \f$\varepsilon\f$ of the plain law is kept, \f$W_r + \varepsilon W\f$
 * ("Wrinkling residual stiffness"), so a wholly slack patch still has a
 * regular tangent; it carries \f$\varepsilon\f$ of the plain law's
 * compression and is part of the model.
 *
 * With a smoothing width zeta > 0 ("Wrinkling smoothing") the relaxed
 * energy is replaced by its interior-point smoothing
 * \f$W_\delta(C) = \min_{B \succ 0} W(C + B) - \delta \ln\det B\f$,
 * \f$\delta = d\zeta^2/4\f$: the complementarity \f$S(C^*) B = 0\f$ becomes
 * \f$S(C^*) B = 2\delta I\f$, and stress and tangent are continuous
 * through the state changes (doc/theory.md §2.1, "Smoothing").
 */

#include <pneuma/membrane/constitutive_law.h>

#include <deal.II/base/tensor.h>

#include <memory>

namespace pneuma
{
  namespace membrane
  {
    /// The wrinkling state of a membrane point.
    struct WrinklingState
    {
      /// 0 taut, 1 wrinkled, 2 slack (the VTU field's values).
      enum Kind : unsigned int
      {
        taut     = 0,
        wrinkled = 1,
        slack    = 2
      };
      Kind kind = taut;
      /// The material metric C* (C where taut).
      SymmetricTensor<2, 2> C_star;
      /// Unit tension direction p in the reference tangent basis (the
      /// wrinkles' crests), where wrinkled.
      dealii::Tensor<1, 2> tension_direction;
      /// The smaller principal value of the plain law's S(C): where
      /// negative, the compression relaxed away.
      double plain_minor_stress = 0.;
    };

    /**
     * A membrane law relaxed by tension field theory: the wrapped law's
     * stress where the point is taut, uniaxial tension where wrinkled,
     * none where slack.
     */
    class TensionFieldLaw : public ConstitutiveLaw
    {
    public:
      /// Wrap @p law; keep the fraction @p residual_stiffness of it;
      /// smooth the relaxed energy over the strain width @p smoothing
      /// (0: the exact relaxed energy).
      TensionFieldLaw(std::shared_ptr<const ConstitutiveLaw> law,
                      double                                 residual_stiffness,
                      double                                 smoothing = 0.);

      /// The constants belong to the wrapped law: nothing to declare.
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
               SymmetricTensor<4, 2>       &dS_dE) const override;

      /// The relaxed energy W(C*) + eps W(C).
      double
      strain_energy(const SymmetricTensor<2, 2> &C) const override;

      /// The thickness stretch of the material, at C*.
      double
      thickness_stretch(const SymmetricTensor<2, 2> &C) const override;

      double
      initial_shear_modulus() const override
      {
        return law->initial_shear_modulus();
      }

      bool
      isotropic() const override
      {
        return law->isotropic();
      }

      /// The state at C (taut, wrinkled or slack) with C*.
      WrinklingState
      state(const SymmetricTensor<2, 2> &C) const;

      /// The wrapped law.
      const ConstitutiveLaw &
      plain_law() const
      {
        return *law;
      }

    private:
      /// The state at C with the plain law's stress and tangent at C, and
      /// the relaxed ones: stress and tangent at C*, beta and the direction
      /// m (where wrinkled).
      WrinklingState
      solve(const SymmetricTensor<2, 2> &C,
            SymmetricTensor<2, 2>       &S_plain,
            SymmetricTensor<4, 2>       &D_plain,
            SymmetricTensor<2, 2>       &S_star,
            SymmetricTensor<4, 2>       &D_star,
            double                      &beta,
            dealii::Tensor<1, 2>        &m) const;

      /**
       * The smoothed relaxed stress S and tangent D at C: the minimiser B of
       * W(C + B) - delta ln det B over positive definite B (Newton's
       * method from the exact relaxed state), S = S(C + B); with the plain
       * law's stress and tangent at C. Returns false if the inner Newton
       * did not converge.
       */
      bool
      smoothed(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S_plain,
               SymmetricTensor<4, 2>       &D_plain,
               SymmetricTensor<2, 2>       &S,
               SymmetricTensor<4, 2>       &D,
               SymmetricTensor<2, 2>       &B) const;

      std::shared_ptr<const ConstitutiveLaw> law;
      double                                 residual_stiffness;
      /// The barrier weight delta = d zeta^2 / 4 of the smoothing, d the
      /// law's stiffest direct modulus (0: no smoothing).
      double delta = 0.;
      /// -delta ln det B at C_0, so that the smoothed energy is zero there.
      double energy_offset = 0.;
      /// The stress-free metric C_0 of the wrapped law (I unless the law
      /// carries a prestress).
      SymmetricTensor<2, 2> C_free;
    };
  } // namespace membrane
} // namespace pneuma
