#pragma once

/**
 * @file
 * The polytropic gas law \f$p V^\kappa = p_a V_n^\kappa\f$, i.e.
 * \f$p = p_a (V_n/V)^\kappa\f$ (absolute pressure; source paper, section
 * 2.1, equation 1; doc/theory.md "Gas"): the common part of the registered
 * laws "isothermal" (\f$\kappa = 1\f$, slow changes at constant temperature)
 * and "adiabatic" (\f$\kappa = c_p/c_v\f$, fast changes without heat
 * exchange; 1.4 for air), source/chambers/gas_laws/.
 *
 * Both slopes are \f$\kappa\f$: \f$\partial p/\partial V = -\kappa p/V\f$,
 * \f$\partial p/\partial V_n = \kappa p/V_n\f$, and \f$p V^\kappa\f$ stays
 * constant while the amount is fixed.
 */

#include <pneuma/chambers/gas_law.h>

namespace pneuma
{
  namespace chambers
  {
    /// p = p_a (V_n/V)^kappa with the exponent of the derived law.
    class PolytropicGasLaw : public GasLaw
    {
    public:
      double
      pressure(const double volume,
               const double amount,
               const double ambient) const override;

      double
      amount(const double pressure,
             const double volume,
             const double ambient) const override;

      GasSlopes
      slopes(const GasState &state, const double ambient) const override;

      double
      invariant(const GasState &state) const override;

      /// The exponent kappa.
      double
      exponent() const
      {
        return kappa;
      }

    protected:
      /// @p kappa: the exponent, and the default of a law that declares it.
      explicit PolytropicGasLaw(const double kappa)
        : kappa(kappa)
      {
      }

      double kappa;
    };
  } // namespace chambers
} // namespace pneuma
