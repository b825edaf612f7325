#pragma once

/**
 * @file
 * The membrane "law" of one form-finding step of the updated reference
 * strategy (Bletzinger & Ramm 1999; doc/theory.md "Form finding").
 *
 * The target is a prestress given as membrane forces n_1, n_2 [N/m] along
 * the region's warp and fill directions (n_1 = n_2: isotropic). Each step
 * solves, on the reference surface X_k (the shape of the step before),
 * \f[ \lambda \int_a \sigma : \nabla_x \delta u\, da
 *   + (1 - \lambda)\int_{A_k} S_0 : \delta E\, dA = 0, \f]
 * the homotopy of the true, Cauchy prestress on the unknown surface
 * (\f$\lambda = 1\f$, singular in the tangent plane) and the constant
 * second Piola-Kirchhoff prestress on the known one (\f$\lambda = 0\f$,
 * the continuum form of the force density method). Pulled back, the
 * Cauchy part is the second Piola-Kirchhoff stress
 * \f$J F^{-1}\sigma F^{-T}\f$ of \f$\sigma = n_1 t_1\otimes t_1 + n_2
 * t_2\otimes t_2\f$ with \f$t_1 = a_1/|a_1|\f$ and \f$t_2 \perp t_1\f$
 * in the current tangent plane; in the frame (e_1, e_2), with \f$d =
 * \det C\f$,
 * \f[ S_c = \begin{pmatrix} n_1\sqrt d/C_{11} + n_2 C_{12}^2/(C_{11}\sqrt
 *   d) & -n_2 C_{12}/\sqrt d\\ \cdot & n_2 C_{11}/\sqrt d\end{pmatrix},
 * \f]
 * which is \f$n J C^{-1}\f$ for \f$n_1 = n_2 = n\f$. At the fixed point
 * (X_{k+1} = X_k, so F = I) both parts equal the prescribed prestress,
 * whatever lambda: lambda only changes how the steps get there. The law
 * divides by the thickness H because the assembler multiplies by it.
 */

#include <pneuma/membrane/constitutive_law.h>

namespace pneuma
{
  namespace membrane
  {
    /// S(C) of one updated-reference form-finding step.
    class FormFindingLaw : public ConstitutiveLaw
    {
    public:
      /// Target membrane forces @p n1, @p n2 [N/m], homotopy factor
      /// @p lambda in [0, 1) (lambda > 0 needs n1 = n2), thickness @p H.
      FormFindingLaw(const double n1,
                     const double n2,
                     const double lambda,
                     const double H);

      /// Nothing to read: the constants come from the region.
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

      /// (1 - lambda) S_0 : E + lambda n (J - 1), per unit volume (the
      /// Cauchy part has this potential for isotropic prestress only,
      /// which is the only case with lambda > 0).
      double
      strain_energy(const SymmetricTensor<2, 2> &C) const override;

      double
      thickness_stretch(const SymmetricTensor<2, 2> &) const override
      {
        return 1.;
      }

      /// The stress scale max(n1, n2)/H.
      double
      initial_shear_modulus() const override
      {
        return std::max(n1, n2) / H;
      }

      bool
      isotropic() const override
      {
        return n1 == n2;
      }

    private:
      double n1, n2, lambda, H;
    };
  } // namespace membrane
} // namespace pneuma
