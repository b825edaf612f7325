/**
 * @file
 * Incompressible Mooney-Rivlin in plane stress (doc/theory.md "Membrane
 * laws"): \f$W = C_{10}(I_1 - 3) + C_{01}(I_2 - 3)\f$ with the invariants of
 * membrane/incompressible_invariants.h.
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
      class MooneyRivlin : public ConstitutiveLaw
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("C10",
                            c10,
                            "C10 [Pa] of W = C10 (I1-3) + C01 (I2-3).",
                            Patterns::Double());
          prm.add_parameter("C01", c01, "C01 [Pa].", Patterns::Double());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(c10 + c01 > 0. && c10 >= 0. && c01 >= 0.,
                      path + "/C10",
                      "C10 and C01 must be >= 0 with C10 + C01 > 0");
        }

        void
        evaluate(const SymmetricTensor<2, 2> &C,
                 SymmetricTensor<2, 2>       &S,
                 SymmetricTensor<4, 2>       &D) const override
        {
          const IncompressibleInvariants inv(C);
          S = 2. * (c10 * inv.dI1 + c01 * inv.dI2);
          D = 4. * (c10 * inv.ddI1 + c01 * inv.ddI2);
        }

        void
        stress(const SymmetricTensor<2, 2> &C,
               SymmetricTensor<2, 2>       &S) const override
        {
          const IncompressibleInvariants inv(C, false);
          S = 2. * (c10 * inv.dI1 + c01 * inv.dI2);
        }

        double
        strain_energy(const SymmetricTensor<2, 2> &C) const override
        {
          const IncompressibleInvariants inv(C);
          return c10 * (inv.I1 - 3.) + c01 * (inv.I2 - 3.);
        }

        double
        thickness_stretch(const SymmetricTensor<2, 2> &C) const override
        {
          return 1. / std::sqrt(determinant(C));
        }

        double
        initial_shear_modulus() const override
        {
          return 2. * (c10 + c01);
        }

      private:
        double c10 = 4e5, c01 = 1e5;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ConstitutiveLaw,
                            MooneyRivlin,
                            "Mooney-Rivlin",
                            "incompressible, W = C10 (I1-3) + C01 (I2-3)")
  } // namespace membrane
} // namespace pneuma
