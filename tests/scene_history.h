#pragma once

// Readings of a scene run's history (one row per converged step, as in
// history.csv) shared by the scene tests: taken on rank 0, where the
// history is complete, and broadcast, so every rank checks alike.

#include <deal.II/base/mpi.h>

#include <pneuma/simulator/simulator.h>

#include <cmath>
#include <string>

namespace pneuma_test
{
  /// @p value of the history row at pseudo time @p t (NaN if no step ended
  /// there), on every rank.
  template <typename Value>
  double
  at_time(const pneuma::RunResult &s, const double t, const Value &value)
  {
    double v = NAN;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      for (const auto &row : s.history)
        if (std::abs(row.get("time") - t) < 1e-9)
          v = value(row);
    return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, v);
  }

  /// Relative change of p_abs V_gas^kappa of chamber @p k from its seal at
  /// @p t_seal to the end of the run (zero for a sealed adiabatic gas), on
  /// every rank.
  inline double
  sealed_gas_change(const pneuma::RunResult &s,
                    const unsigned int       k,
                    const double             t_seal,
                    const double             kappa = 1.4)
  {
    const std::string c  = "c" + std::to_string(k);
    const auto        pv = [&](const pneuma::Statistics &row) {
      return row.get(c + "_absolute_pressure")
             * std::pow(row.get(c + "_gas_volume"), kappa);
    };
    const double sealed = at_time(s, t_seal, pv);
    double       end    = NAN;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      end = pv(s.history.back());
    end = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, end);
    return std::abs(end - sealed) / sealed;
  }
} // namespace pneuma_test
