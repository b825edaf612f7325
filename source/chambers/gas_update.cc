#include <deal.II/base/exceptions.h>

#include <pneuma/chambers/gas_update.h>
#include <pneuma/core/selection_parameter.h>

namespace pneuma
{
  namespace chambers
  {
    using namespace dealii;

    void
    GasUpdate::declare_parameters(ParameterHandler &prm)
    {
      const auto &registry = GasLawRegistry::instance();
      prm.add_parameter("Law",
                        name,
                        "Gas law; its constants are in the subsection of "
                        "its name. "
                          + registry.descriptions() + ".",
                        Patterns::Selection(registry.names()));
      add_selection(prm,
                    "Update",
                    incremental,
                    {{"exact", false}, {"incremental", true}},
                    "exact: the law itself; incremental: the source "
                    "paper's first-order update about the last converged "
                    "step (its equation 2).");
      laws = registry.declare_all(prm);
    }

    void
    GasUpdate::parse_parameters(ParameterHandler &prm, const std::string &path)
    {
      // The other laws stay: the handler keeps their bound members.
      selected =
        GasLawRegistry::instance().take(laws, prm, name, path + "/Law", path);
    }

    const GasLaw &
    GasUpdate::law() const
    {
      Assert(selected, ExcMessage("parse_parameters() first"));
      return *selected;
    }

    double
    GasUpdate::pressure(const double    volume,
                        const double    amount,
                        const double    ambient,
                        const GasState &old) const
    {
      if (incremental)
        {
          const GasSlopes n = law().slopes(old, ambient);
          return old.pressure
                 * (1. - n.volume * (volume - old.volume) / old.volume
                    + n.amount * (amount - old.amount) / old.amount);
        }
      return law().pressure(volume, amount, ambient);
    }

    double
    GasUpdate::pressure_derivative(const double    volume,
                                   const double    amount,
                                   const double    ambient,
                                   const GasState &old) const
    {
      if (incremental)
        return -law().slopes(old, ambient).volume * old.pressure / old.volume;
      const double p = law().pressure(volume, amount, ambient);
      return -law().slopes({p, volume, amount}, ambient).volume * p / volume;
    }
  } // namespace chambers
} // namespace pneuma
