#include <pneuma/solvers/linear_solver.h>

namespace pneuma
{
  namespace solvers
  {
    void
    LinearSolver::add_statistics(Statistics &row) const
    {
      const auto             run    = StatisticsGroup::run();
      constexpr unsigned int counts = Statistics::summary;
      row.add_count(run, "factorizations", n_factorizations(), counts);
      row.add_count(run, "krylov_iterations", n_krylov_iterations(), counts);
      if (type() != LinearSolverType::direct)
        return;
      // The last factorization: LDL^T (1) or LU (0), its size and work.
      row.add_count(run,
                    "factorization_symmetric",
                    factorized_ldlt() ? 1. : 0.,
                    counts);
      row.add_count(run, "factor_entries", factor_entries(), counts);
      row.add(
        run, "factorization_gflop", "", 1e-9 * factorization_flops(), counts);
      // Where the LDL^T's time went (MUMPS' phases on rank 0).
      const auto work = symmetric_work();
      row.add_count(run, "ldlt_analyses", work.analyses, counts);
      row.add_count(run, "ldlt_orderings", work.orderings, counts);
      row.add(run, "ldlt_analysis_seconds", "s", work.analysis_seconds, counts);
      row.add(run,
              "ldlt_factorization_seconds",
              "s",
              work.factorization_seconds,
              counts);
      row.add(run, "ldlt_solve_seconds", "s", work.solve_seconds, counts);
    }
  } // namespace solvers
} // namespace pneuma
