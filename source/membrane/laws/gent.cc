/**
 * @file
 * The incompressible Gent law in plane stress (Gent 1996; doc/theory.md
 * "Membrane laws"): limiting chain extensibility, the standard law for
 * rubber balloons,
 * \f[ W = -\frac{\mu J_m}{2}\ln\Bigl(1 - \frac{I_1 - 3}{J_m}\Bigr), \f]
 * which tends to the neo-Hookean law \f$\frac{\mu}{2}(I_1-3)\f$ as
 * \f$J_m\to\infty\f$ and stiffens without bound as \f$I_1 - 3 \to J_m\f$.
 * With \f$f = J_m/(J_m - I_1 + 3)\f$, \f$W_1 = \frac{\mu}{2} f\f$ and
 * \f$W_{11} = \frac{\mu}{2} f^2/J_m\f$:
 * \f$S = 2W_1 I_{1,C}\f$,
 * \f$\mathbb{D} = 4(W_1 I_{1,CC} + W_{11} I_{1,C}\otimes I_{1,C})\f$.
 * A state at or beyond the limit \f$I_1 - 3 \ge J_m\f$ has no finite
 * energy: its stress is not finite, and Newton's line search steps back.
 *
 * Inflated sphere, equibiaxial stretch l (\f$I_1 = 2l^2 + l^{-4}\f$):
 * \f$pR/(\mu H) = 2(l^{-1} - l^{-7})\,J_m/(J_m - 2l^2 - l^{-4} + 3)\f$
 * (doc/theory.md; tests/gent_sphere).
 */

#include <pneuma/core/input_error.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/incompressible_invariants.h>

#include <cmath>
#include <limits>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    namespace
    {
      class Gent : public ConstitutiveLaw
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Shear modulus",
                            mu,
                            "mu [Pa], the small-strain shear modulus; > 0.",
                            Patterns::Double());
          prm.add_parameter("Limiting extensibility",
                            Jm,
                            "J_m [-]: the largest I1 - 3 (97.2 fits Treloar's "
                            "rubber); > 0.",
                            Patterns::Double());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(mu > 0.,
                      path + "/Shear modulus",
                      "must be positive, got " + std::to_string(mu));
          check_input(Jm > 0.,
                      path + "/Limiting extensibility",
                      "must be positive, got " + std::to_string(Jm));
        }

        void
        evaluate(const SymmetricTensor<2, 2> &C,
                 SymmetricTensor<2, 2>       &S,
                 SymmetricTensor<4, 2>       &D) const override
        {
          const IncompressibleInvariants inv(C);
          const double                   gap = Jm - (inv.I1 - 3.);
          const double                   f =
            gap > 0. ? Jm / gap : std::numeric_limits<double>::infinity();
          const double W1  = 0.5 * mu * f;
          const double W11 = 0.5 * mu * f * f / Jm;
          S                = 2. * W1 * inv.dI1;
          D = 4. * (W1 * inv.ddI1 + W11 * outer_product(inv.dI1, inv.dI1));
        }

        void
        stress(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S) const override
        {
          const IncompressibleInvariants inv(C, false);
          const double                   gap = Jm - (inv.I1 - 3.);
          const double                   f =
            gap > 0. ? Jm / gap : std::numeric_limits<double>::infinity();
          S = mu * f * inv.dI1;
        }

        double
        strain_energy(const SymmetricTensor<2, 2> &C) const override
        {
          const double x = (IncompressibleInvariants(C).I1 - 3.) / Jm;
          return x < 1. ? -0.5 * mu * Jm * std::log1p(-x)
                        : std::numeric_limits<double>::infinity();
        }

        double
        thickness_stretch(const SymmetricTensor<2, 2> &C) const override
        {
          return 1. / std::sqrt(determinant(C));
        }

        double
        initial_shear_modulus() const override
        {
          return mu;
        }

      private:
        double mu = 1e6, Jm = 97.2;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ConstitutiveLaw,
                            Gent,
                            "Gent",
                            "incompressible, limiting chain extensibility J_m "
                            "(rubber balloons)")
  } // namespace membrane
} // namespace pneuma
