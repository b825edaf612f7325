#pragma once

/**
 * @file
 * The gas law of a closed gas filling: the interface of the registered gas
 * laws (source paper, section 2.1, equations 1-2; doc/theory.md "Gas";
 * doc/architecture.md "Add a gas law").
 *
 * The gas amount is measured by its volume at ambient pressure,
 * \f$V_n\f$ (the "free air volume"). A law gives the absolute pressure
 * \f$p(V, V_n)\f$ of the amount \f$V_n\f$ in the volume \f$V\f$ at the
 * ambient pressure \f$p_a\f$, its inverse \f$V_n(p, V)\f$, and its
 * logarithmic slopes at a state \f$(p, V, V_n)\f$,
 * \f[ n_V = -\frac{V}{p}\frac{\partial p}{\partial V}\Big|_{V_n}, \qquad
 *     n_n = \frac{V_n}{p}\frac{\partial p}{\partial V_n}\Big|_{V}, \f]
 * with which chambers/gas_update.h evaluates the exact law or the source
 * paper's incremental update of it. The polytropic laws
 * \f$p V^\kappa = p_a V_n^\kappa\f$ (chambers/polytropic_gas_law.h:
 * "isothermal" \f$\kappa = 1\f$, "adiabatic" \f$\kappa = c_p/c_v\f$, 1.4 for
 * air) have \f$n_V = n_n = \kappa\f$ at every state.
 *
 * A law is one .cc file in source/chambers/gas_laws/ with one registration
 * line (core/registry.h); its constants live in the subsection of its name,
 * "Chambers/Chamber <k>/Gas/<name>", and "Chambers/Chamber <k>/Gas/Law"
 * selects it.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/registry.h>

#include <string>

namespace pneuma
{
  namespace chambers
  {
    /// A state of a gas filling.
    struct GasState
    {
      double pressure = 0.; ///< absolute [Pa]
      double volume   = 0.; ///< [m^3]
      double amount   = 0.; ///< V_n [m^3 at ambient pressure]
    };

    /// The logarithmic slopes n_V and n_n of a law at a state.
    struct GasSlopes
    {
      double volume; ///< n_V = -(V/p) dp/dV at fixed V_n
      double amount; ///< n_n = (V_n/p) dp/dV_n at fixed V
    };

    /// A gas law p(V, V_n): the interface of the registered gas laws.
    class GasLaw
    {
    public:
      virtual ~GasLaw() = default;

      /// Declare (and bind) the law's constants in the current subsection.
      virtual void
      declare_parameters(dealii::ParameterHandler &prm) = 0;
      /// Check the constants; messages name @p path.
      virtual void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path) = 0;

      /// Absolute pressure [Pa] of the amount @p amount in the volume
      /// @p volume at the absolute ambient pressure @p ambient.
      virtual double
      pressure(const double volume,
               const double amount,
               const double ambient) const = 0;

      /// The amount V_n that has the absolute pressure @p pressure in
      /// @p volume (used when a chamber is sealed).
      virtual double
      amount(const double pressure,
             const double volume,
             const double ambient) const = 0;

      /// The slopes n_V, n_n at @p state (absolute pressure).
      virtual GasSlopes
      slopes(const GasState &state, const double ambient) const = 0;

      /**
       * The quantity the law keeps constant while the amount is fixed, at
       * @p state: \f$p V^\kappa\f$ for a polytropic law. Reported per
       * chamber as pv_kappa, a check of the converged states.
       */
      virtual double
      invariant(const GasState &state) const = 0;
    };

    /// The registry of gas laws.
    using GasLawRegistry = Registry<GasLaw>;
  } // namespace chambers
} // namespace pneuma
