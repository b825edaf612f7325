#pragma once

// Shared helpers of the pneuma verification tests: run a scene configured
// entry by entry, and compare a value with its reference, printing the
// reference, the value and the relative error at fixed precision.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <pneuma/core/simulator.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace pneuma_test
{
  using Settings = std::vector<std::pair<std::string, std::string>>;

  /// Apply "Path/To/Entry" = value settings to a declared handler.
  inline void
  apply(dealii::ParameterHandler &prm, const Settings &settings)
  {
    for (const auto &s : settings)
      {
        const auto path = dealii::Utilities::split_string_list(s.first, '/');
        for (unsigned int i = 0; i + 1 < path.size(); ++i)
          prm.enter_subsection(path[i]);
        prm.set(path.back(), s.second);
        for (unsigned int i = 0; i + 1 < path.size(); ++i)
          prm.leave_subsection();
      }
  }

  /// Run pneuma quietly with @p settings on top of the defaults.
  inline pneuma::RunSummary
  run(const Settings &settings, const MPI_Comm comm = MPI_COMM_WORLD)
  {
    dealii::ParameterHandler prm;
    pneuma::Simulator::declare_parameters(prm);
    apply(prm,
          {{"Output/Quiet", "true"},
           {"Output/Directory", "run-output"},
           {"Output/Write VTU", "false"},
           {"Newton/Print convergence table", "false"}});
    apply(prm, settings);
    pneuma::Simulator simulator(comm);
    simulator.parse_parameters(prm);
    simulator.setup();
    return simulator.run();
  }

  /// Print "name: reference r, value v, relative error e" and return
  /// whether |e| <= tolerance. Values at 4 significant digits.
  inline bool
  check(const std::string &name,
        const double       value,
        const double       reference,
        const double       tolerance)
  {
    const double error = (value - reference) / std::abs(reference);
    const bool   ok    = std::abs(error) <= tolerance && std::isfinite(value);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: reference %.4e value %.4e relative error %.1e "
                  "(tolerance %.1e) %s\n",
                  name.c_str(),
                  reference,
                  value,
                  std::abs(error) < 5e-6 ? 0. : error,
                  tolerance,
                  ok ? "PASS" : "FAIL");
    return ok;
  }

  /// |reactions + applied loads| / |applied vertical load| of a run: zero
  /// up to round-off when every force reaches the supports.
  inline double
  load_imbalance(const pneuma::RunSummary &s)
  {
    double sum = 0.;
    for (unsigned int c = 0; c < 3; ++c)
      sum += std::pow(s.reaction[c] + s.applied_load[c], 2);
    return std::sqrt(sum) / std::abs(s.applied_load[2]);
  }
} // namespace pneuma_test
