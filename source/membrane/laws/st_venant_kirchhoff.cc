/**
 * @file
 * St. Venant-Kirchhoff in plane stress (doc/theory.md "Membrane laws"):
 * \f$S = \bar\lambda\,\mathrm{tr}E\,I + 2\mu E\f$ with the reduced
 * plane-stress modulus \f$\bar\lambda = E\nu/(1-\nu^2)\f$ and
 * \f$\mu = E/(2(1+\nu))\f$; the thickness stretch from
 * \f$E_{33} = -\nu/(1-\nu)\,\mathrm{tr}E\f$.
 */

#include <pneuma/core/input_error.h>
#include <pneuma/membrane/constitutive_law.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    namespace
    {
      class StVenantKirchhoff : public ConstitutiveLaw
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Young's modulus",
                            youngs_modulus,
                            "E [Pa]; must be > 0.",
                            Patterns::Double());
          prm.add_parameter("Poisson's ratio",
                            poisson,
                            "nu [-], -1 < nu < 0.5.",
                            Patterns::Double());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(youngs_modulus > 0.,
                      path + "/Young's modulus",
                      "must be positive, got "
                        + std::to_string(youngs_modulus));
          check_input(poisson > -1. && poisson < 0.5,
                      path + "/Poisson's ratio",
                      "must lie in (-1, 0.5), got " + std::to_string(poisson));
          lambda_bar = youngs_modulus * poisson / (1. - poisson * poisson);
          mu         = youngs_modulus / (2. * (1. + poisson));
        }

        void
        evaluate(const SymmetricTensor<2, 2> &C,
                 SymmetricTensor<2, 2>       &S,
                 SymmetricTensor<4, 2>       &D) const override
        {
          const SymmetricTensor<2, 2> I = unit_symmetric_tensor<2>();
          const SymmetricTensor<2, 2> E = 0.5 * (C - I);
          S = lambda_bar * trace(E) * I + 2. * mu * E;
          D = lambda_bar * outer_product(I, I) + 2. * mu * identity_tensor<2>();
        }

        double
        strain_energy(const SymmetricTensor<2, 2> &C) const override
        {
          const SymmetricTensor<2, 2> E =
            0.5 * (C - unit_symmetric_tensor<2>());
          return 0.5 * lambda_bar * trace(E) * trace(E) + mu * (E * E);
        }

        double
        thickness_stretch(const SymmetricTensor<2, 2> &C) const override
        {
          // Plane stress in the 3D law: E_33 = -nu/(1-nu) tr(E).
          const double E33 = -poisson / (1. - poisson) * 0.5 * (trace(C) - 2.);
          return std::sqrt(std::max(1. + 2. * E33, 0.));
        }

        double
        initial_shear_modulus() const override
        {
          return mu;
        }

      private:
        double youngs_modulus = 7.6e9, poisson = 0.3;
        double lambda_bar = 0., mu = 0.;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ConstitutiveLaw,
                            StVenantKirchhoff,
                            "Saint Venant-Kirchhoff",
                            "linear in the Green-Lagrange strain (fabrics, "
                            "foils, steel plates)")
  } // namespace membrane
} // namespace pneuma
