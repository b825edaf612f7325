#include <pneuma/chambers/gas_law.h>

#include <cmath>

namespace pneuma
{
  namespace chambers
  {
    double
    GasLaw::pressure(const double     volume,
                     const double     amount,
                     const double     ambient,
                     const Reference &old) const
    {
      if (incremental)
        return old.pressure
               * (1. - kappa * (volume - old.volume) / old.volume
                  + kappa * (amount - old.amount) / old.amount);
      return ambient * std::pow(amount / volume, kappa);
    }

    double
    GasLaw::pressure_derivative(const double     volume,
                                const double     amount,
                                const double     ambient,
                                const Reference &old) const
    {
      if (incremental)
        return -kappa * old.pressure / old.volume;
      return -kappa * pressure(volume, amount, ambient, old) / volume;
    }

    double
    GasLaw::amount(const double p,
                   const double volume,
                   const double ambient) const
    {
      return volume * std::pow(p / ambient, 1. / kappa);
    }
  } // namespace chambers
} // namespace pneuma
