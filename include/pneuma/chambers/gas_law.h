#pragma once

/**
 * @file
 * The gas law of a closed gas filling (source paper, section 2.1,
 * equations 1-2; doc/theory.md "Gas").
 *
 * The gas amount is measured by its volume at ambient pressure,
 * \f$V_n\f$ (the "free air volume"). The exact polytropic law is
 * \f$p V^\kappa = p_a V_n^\kappa\f$, i.e. \f$p = p_a (V_n/V)^\kappa\f$
 * (absolute pressure; \f$\kappa = 1\f$ isothermal, 1.4 adiabatic air).
 * The paper's incremental update linearises it about the last converged
 * state: \f$p = p_{old}\,[1 - \kappa (V - V_{old})/V_{old}
 * + \kappa (V_n - V_{n,old})/V_{n,old}]\f$; it is first order in the step
 * (doc/verification.md, V4), offered for comparison with codes that use it.
 */

#include <string>

namespace pneuma
{
  namespace chambers
  {
    /// The polytropic gas law, exact or incremental.
    class GasLaw
    {
    public:
      /// @p kappa: 1 isothermal, e.g. 1.4 adiabatic; @p incremental:
      /// the paper's first-order update instead of the exact law.
      GasLaw(const double kappa = 1.4, const bool incremental = false)
        : kappa(kappa)
        , incremental(incremental)
      {
      }

      /// The state the incremental law expands about (last converged step).
      struct Reference
      {
        double pressure = 0.; ///< absolute
        double volume   = 0.;
        double amount   = 0.; ///< V_n
      };

      /// Absolute pressure of gas amount @p amount in volume @p volume.
      double
      pressure(const double     volume,
               const double     amount,
               const double     ambient,
               const Reference &old) const;

      /// d pressure / d volume at fixed amount.
      double
      pressure_derivative(const double     volume,
                          const double     amount,
                          const double     ambient,
                          const Reference &old) const;

      /// The amount V_n that has absolute pressure @p p in volume @p V
      /// (exact law; used when a chamber is sealed).
      double
      amount(const double p, const double volume, const double ambient) const;

      double
      exponent() const
      {
        return kappa;
      }

      bool
      is_incremental() const
      {
        return incremental;
      }

    private:
      double kappa;
      bool   incremental;
    };
  } // namespace chambers
} // namespace pneuma
