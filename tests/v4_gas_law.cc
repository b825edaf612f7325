// V4 (doc/verification.md): the adiabatic gas law p V^kappa = const. Halving a
// volume gives p/p0 = 2^1.4 = 2.639016 with the exact law. The source
// paper's incremental update p = p_old - kappa p_old (V - V_old)/V_old is
// first order in the step: with N equal volume steps p/p0 = 1.7000 (N=1),
// 2.2259 (4), 2.5114 (16), 2.6051 (64), 2.6368 (1000).

#include <pneuma/chambers/gas_law.h>

#include "test_tools.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using pneuma::chambers::GasLaw;
  const double p_a = 1e5, V0 = 1.;
  bool         ok  = true;

  const GasLaw       exact(1.4, false);
  GasLaw::Reference  none;
  const double       amount = V0; // at ambient pressure initially
  ok = pneuma_test::check("exact law, V0/2: p/p0",
                          exact.pressure(0.5 * V0, amount, p_a, none) / p_a,
                          2.639016,
                          1e-6) &&
       ok;

  const GasLaw incremental(1.4, true);
  const std::vector<std::pair<unsigned int, double>> table = {
    {1, 1.7000}, {4, 2.2259}, {16, 2.5114}, {64, 2.6051}, {1000, 2.6368}};
  for (const auto &[n, reference] : table)
    {
      GasLaw::Reference old{p_a, V0, amount};
      for (unsigned int k = 1; k <= n; ++k)
        {
          const double V = V0 * (1. - 0.5 * k / n);
          const double p = incremental.pressure(V, amount, p_a, old);
          old            = {p, V, amount};
        }
      ok = pneuma_test::check("incremental law, " + std::to_string(n) +
                                " steps: p/p0",
                              old.pressure / p_a,
                              reference,
                              1e-4) &&
           ok;
    }
  return ok ? 0 : 1;
}
