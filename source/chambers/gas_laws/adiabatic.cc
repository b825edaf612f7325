/**
 * @file
 * The adiabatic law \f$p V^\kappa = p_a V_n^\kappa\f$ (source paper,
 * section 2.1, equation 1; doc/theory.md "Gas"): a reversible change without
 * heat exchange, as in fast inflation or loading, with
 * \f$\kappa = c_p/c_v\f$ the ratio of the specific heats of the gas (1.4
 * for air and other diatomic gases, 5/3 for monatomic ones). Its one
 * constant is "Chambers/Chamber <k>/Gas/adiabatic/Exponent".
 */

#include <pneuma/chambers/polytropic_gas_law.h>

namespace pneuma
{
  namespace chambers
  {
    using namespace dealii;

    namespace
    {
      class Adiabatic : public PolytropicGasLaw
      {
      public:
        Adiabatic()
          : PolytropicGasLaw(1.4)
        {
        }

        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Exponent",
                            kappa,
                            "kappa = c_p/c_v of p V^kappa = const (1.4 for "
                            "air); >= 1 (1 is the isothermal law).",
                            Patterns::Double(1.));
        }

        void
        parse_parameters(ParameterHandler &, const std::string &) override
        {
          // The pattern bounds the exponent.
        }
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(GasLaw,
                            Adiabatic,
                            "adiabatic",
                            "p V^kappa = const, kappa = Exponent (fast "
                            "changes, no heat exchange)")
  } // namespace chambers
} // namespace pneuma
