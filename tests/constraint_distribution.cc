// ConstraintDistribution (core/constraint_distribution.h), the planned
// AffineConstraints::distribute() of the Newton updates, against deal.II's
// own distribute() on the same vector: 40 unknowns in contiguous blocks
// over the ranks, with constraints whose masters sit on other ranks (on 2
// ranks), an inhomogeneous one, one without masters (a prescribed value),
// a chain that close() resolves, and one on the last unknown. The two
// results must agree to round-off (the same sums in the same order: 0 in
// practice); a second call on a changed vector checks that the planned
// communication is reused correctly. A vector of another layout (all
// unknowns owned by rank 0) takes deal.II's way.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/affine_constraints.h>

#include <pneuma/core/constraint_distribution.h>

#include <cmath>
#include <cstdio>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm),
                     n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  const unsigned int n       = 40;
  dealii::IndexSet   owned(n), all(n);
  owned.add_range(rank * n / n_ranks, (rank + 1) * n / n_ranks);
  all.add_range(0, n);

  dealii::AffineConstraints<double> constraints;
  constraints.reinit(all);
  // x_3 = 0.5 x_30 + 0.5 x_31 + 1 (masters on the last rank).
  constraints.add_line(3);
  constraints.add_entry(3, 30, 0.5);
  constraints.add_entry(3, 31, 0.5);
  constraints.set_inhomogeneity(3, 1.);
  // x_5 = x_3: a chain, resolved by close().
  constraints.add_line(5);
  constraints.add_entry(5, 3, 1.);
  // x_25 = -x_2 (a master on the first rank).
  constraints.add_line(25);
  constraints.add_entry(25, 2, -1.);
  // x_10 = 2: no masters.
  constraints.add_line(10);
  constraints.set_inhomogeneity(10, 2.);
  // x_39 = 0.25 x_0 + 0.75 x_38.
  constraints.add_line(39);
  constraints.add_entry(39, 0, 0.25);
  constraints.add_entry(39, 38, 0.75);
  constraints.close();

  pneuma::ConstraintDistribution distribution;
  distribution.reinit(constraints, owned, comm);

  // max |x - x_deal.II| after both distributions of x; printed, judged.
  bool       ok         = true;
  const auto difference = [&](pneuma::LA::Vector &x) {
    pneuma::LA::Vector y(x);
    distribution.distribute(x);
    constraints.distribute(y);
    y -= x;
    return y.linfty_norm();
  };
  const auto report = [&](const char *label, const double value) {
    ok &= value <= 1e-15;
    if (rank == 0)
      std::printf("distribute, %s: max |x - x_deal.II| reference 0 value "
                  "%.1e tolerance 1e-15 %s\n",
                  label,
                  value,
                  value <= 1e-15 ? "PASS" : "FAIL");
  };

  double worst = 0.;
  for (unsigned int call = 0; call < 2; ++call)
    {
      pneuma::LA::Vector x(owned, comm);
      for (const auto i : owned)
        x[i] = std::sin(1. + i + 7. * call);
      x.compress(dealii::VectorOperation::insert);
      worst = std::max(worst, difference(x));
    }
  report("2 calls", worst);

  // All unknowns on rank 0: another layout, deal.II's way.
  dealii::IndexSet on_root(n);
  if (rank == 0)
    on_root.add_range(0, n);
  pneuma::LA::Vector x(on_root, comm);
  if (rank == 0)
    for (unsigned int i = 0; i < n; ++i)
      x[i] = std::cos(1. + i);
  x.compress(dealii::VectorOperation::insert);
  report("another layout", difference(x));
  return ok ? 0 : 1;
}
