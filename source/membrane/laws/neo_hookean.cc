/**
 * @file
 * Incompressible neo-Hookean in plane stress (doc/theory.md "Membrane
 * laws"): \f$W = \tfrac{\mu}{2}(I_1 - 3)\f$, so
 * \f$S = \mu(I - \lambda_3^2 C^{-1})\f$.
 */

#include <pneuma/core/input_error.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/incompressible_invariants.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    namespace
    {
      class NeoHookean : public ConstitutiveLaw
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Shear modulus",
                            mu,
                            "mu [Pa] of W = mu/2 (I1-3); must be > 0.",
                            Patterns::Double());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(mu > 0.,
                      path + "/Shear modulus",
                      "must be positive, got " + std::to_string(mu));
        }

        void
        evaluate(const SymmetricTensor<2, 2> &C,
                 SymmetricTensor<2, 2>       &S,
                 SymmetricTensor<4, 2>       &D) const override
        {
          const IncompressibleInvariants inv(C);
          S = mu * inv.dI1;
          D = 2. * mu * inv.ddI1;
        }

        void
        stress(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S) const override
        {
          S = mu * IncompressibleInvariants(C, false).dI1;
        }

        double
        strain_energy(const SymmetricTensor<2, 2> &C) const override
        {
          return 0.5 * mu * (IncompressibleInvariants(C).I1 - 3.);
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
        double mu = 1e6;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ConstitutiveLaw,
                            NeoHookean,
                            "neo-Hookean",
                            "incompressible, W = mu/2 (I1-3)")
  } // namespace membrane
} // namespace pneuma
