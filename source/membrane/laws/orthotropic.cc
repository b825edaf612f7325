/**
 * @file
 * Orthotropic St. Venant-Kirchhoff in plane stress, the law of coated
 * fabrics (doc/theory.md "Membrane laws"): warp (1) and fill (2) in the
 * region's material frame, e_1 along "Warp direction" projected onto the
 * surface. In Voigt form on (E11, E22, 2 E12),
 * \f[ S_{11} = Q_{11}E_{11} + Q_{12}E_{22},\quad
 *     S_{22} = Q_{12}E_{11} + Q_{22}E_{22},\quad S_{12} = 2 G_{12} E_{12}, \f]
 * \f$Q_{11} = E_1/(1-\nu_{12}\nu_{21})\f$,
 * \f$Q_{22} = E_2/(1-\nu_{12}\nu_{21})\f$,
 * \f$Q_{12} = \nu_{12}E_2/(1-\nu_{12}\nu_{21})\f$,
 * \f$\nu_{21} = \nu_{12}E_2/E_1\f$ (Maxwell-Betti). Positive definite for
 * \f$E_1, E_2, G_{12} > 0\f$ and \f$\nu_{12}^2 < E_1/E_2\f$. The thickness
 * stretch is not modelled (1).
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
      class Orthotropic : public ConstitutiveLaw
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Warp modulus",
                            E1,
                            "E1 [Pa] along the warp (the region's Warp "
                            "direction); > 0.",
                            Patterns::Double());
          prm.add_parameter("Fill modulus",
                            E2,
                            "E2 [Pa] across it (the fill); > 0.",
                            Patterns::Double());
          prm.add_parameter("Poisson's ratio",
                            nu12,
                            "nu12 [-]: fill contraction under warp tension; "
                            "nu12^2 < E1/E2.",
                            Patterns::Double());
          prm.add_parameter("Shear modulus",
                            G12,
                            "G12 [Pa] in the warp-fill plane; > 0 (coated "
                            "fabrics: a hundredth of E1 or less).",
                            Patterns::Double());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          for (const auto &[name, value] :
               {std::pair<const char *, double>{"Warp modulus", E1},
                {"Fill modulus", E2},
                {"Shear modulus", G12}})
            check_input(value > 0.,
                        path + "/" + name,
                        "must be positive, got " + std::to_string(value));
          check_input(nu12 * nu12 < E1 / E2,
                      path + "/Poisson's ratio",
                      "nu12^2 must be below E1/E2 = " + std::to_string(E1 / E2)
                        + " (a positive definite law), got "
                        + std::to_string(nu12));
          const double nu21 = nu12 * E2 / E1;
          const double d    = 1. - nu12 * nu21;
          D                 = 0;
          D[0][0][0][0]     = E1 / d;
          D[1][1][1][1]     = E2 / d;
          // SymmetricTensor<4,2> has the minor symmetries only: set both
          // coupling entries.
          D[0][0][1][1] = nu12 * E2 / d;
          D[1][1][0][0] = nu12 * E2 / d;
          // S_12 = 2 G E_12 = D_1212 E_12 + D_1221 E_21.
          D[0][1][0][1] = G12;
        }

        void
        evaluate(const SymmetricTensor<2, 2> &C,
                 SymmetricTensor<2, 2>       &S,
                 SymmetricTensor<4, 2>       &dS_dE) const override
        {
          dS_dE = D;
          S     = D * (0.5 * (C - unit_symmetric_tensor<2>()));
        }

        double
        strain_energy(const SymmetricTensor<2, 2> &C) const override
        {
          const SymmetricTensor<2, 2> E =
            0.5 * (C - unit_symmetric_tensor<2>());
          return 0.5 * (E * (D * E));
        }

        double
        thickness_stretch(const SymmetricTensor<2, 2> &) const override
        {
          return 1.;
        }

        double
        initial_shear_modulus() const override
        {
          return G12;
        }

        bool
        isotropic() const override
        {
          return false;
        }

      private:
        double                E1 = 1e9, E2 = 1e9, nu12 = 0.3, G12 = 1e7;
        SymmetricTensor<4, 2> D;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ConstitutiveLaw,
                            Orthotropic,
                            "orthotropic",
                            "St. Venant-Kirchhoff with warp and fill moduli "
                            "E1, E2, nu12 and G12 in the region's material "
                            "frame (coated fabrics)")
  } // namespace membrane
} // namespace pneuma
