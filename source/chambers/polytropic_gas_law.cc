#include <pneuma/chambers/polytropic_gas_law.h>

#include <cmath>

namespace pneuma
{
  namespace chambers
  {
    double
    PolytropicGasLaw::pressure(const double volume,
                               const double amount,
                               const double ambient) const
    {
      return ambient * std::pow(amount / volume, kappa);
    }

    double
    PolytropicGasLaw::amount(const double pressure,
                             const double volume,
                             const double ambient) const
    {
      return volume * std::pow(pressure / ambient, 1. / kappa);
    }

    GasSlopes
    PolytropicGasLaw::slopes(const GasState &, const double) const
    {
      return {kappa, kappa};
    }

    double
    PolytropicGasLaw::invariant(const GasState &state) const
    {
      return state.pressure * std::pow(state.volume, kappa);
    }
  } // namespace chambers
} // namespace pneuma
