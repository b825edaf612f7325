#pragma once

/**
 * @file
 * The gas law of one chamber as the chamber system evaluates it: the law
 * that "Gas/Law" selects (a registered variant, chambers/gas_law.h, its
 * constants in "Gas/<law>") and how it is applied, "Gas/Update"
 * (source paper, section 2.1, equation 2; doc/theory.md "Gas").
 *
 * - exact: the law itself, \f$p = p(V, V_n)\f$ and its derivative
 *   \f$\partial p/\partial V = -n_V\,p/V\f$.
 * - incremental: the paper's update, the law linearised about the last
 *   converged state \f$(p_{old}, V_{old}, V_{n,old})\f$,
 *   \f$p = p_{old}\,[1 - n_V (V - V_{old})/V_{old}
 *   + n_n (V_n - V_{n,old})/V_{n,old}]\f$ with the slopes at that state
 *   (\f$n_V = n_n = \kappa\f$ for the polytropic laws). It is first order
 *   in the step (doc/verification.md, V4), offered for comparison with
 *   codes that use it.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/chambers/gas_law.h>

#include <map>
#include <memory>
#include <string>

namespace pneuma
{
  namespace chambers
  {
    /// The law of a chamber's gas, exact or incremental.
    class GasUpdate
    {
    public:
      /**
       * Declare "Law", "Update" and the subsection of every registered law
       * in the current subsection ("Chambers/Chamber <k>/Gas"), bound to
       * this object (which must outlive the parsing of @p prm).
       */
      void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Select the law named by "Law" and check its constants; messages
      /// name @p path ("Chambers/Chamber <k>/Gas").
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /// Absolute pressure of the amount @p amount in @p volume; @p old is
      /// the last converged state (used by the incremental update).
      double
      pressure(const double    volume,
               const double    amount,
               const double    ambient,
               const GasState &old) const;

      /// d pressure / d volume at fixed amount.
      double
      pressure_derivative(const double    volume,
                          const double    amount,
                          const double    ambient,
                          const GasState &old) const;

      /// The amount with absolute pressure @p p in @p volume (the law
      /// itself; used when a chamber is sealed).
      double
      amount(const double p, const double volume, const double ambient) const
      {
        return law().amount(p, volume, ambient);
      }

      /// The selected law (after parse_parameters()).
      const GasLaw &
      law() const;

      /// The name of the selected law.
      const std::string &
      law_name() const
      {
        return name;
      }

      bool
      is_incremental() const
      {
        return incremental;
      }

    private:
      /// "Law" and "Update", bound; their initial values are the defaults.
      std::string name        = "adiabatic";
      bool        incremental = false;
      /// Every law's constants, bound (the selected one moved out).
      std::map<std::string, std::unique_ptr<GasLaw>> laws;
      /// The selected law.
      std::unique_ptr<GasLaw> selected;
    };
  } // namespace chambers
} // namespace pneuma
