/**
 * @file
 * The isothermal law \f$p V = p_a V_n\f$ (Boyle-Mariotte; doc/theory.md
 * "Gas"): changes slow enough for the gas to stay at the ambient
 * temperature. The polytropic law with \f$\kappa = 1\f$; it has no
 * constants.
 */

#include <pneuma/chambers/polytropic_gas_law.h>

namespace pneuma
{
  namespace chambers
  {
    using namespace dealii;

    namespace
    {
      class Isothermal : public PolytropicGasLaw
      {
      public:
        Isothermal()
          : PolytropicGasLaw(1.)
        {
        }

        void
        declare_parameters(ParameterHandler &) override
        {
        }

        void
        parse_parameters(ParameterHandler &, const std::string &) override
        {
        }
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(GasLaw,
                            Isothermal,
                            "isothermal",
                            "p V = const (slow changes at ambient temperature)")
  } // namespace chambers
} // namespace pneuma
