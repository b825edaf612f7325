#pragma once

/**
 * @file
 * AffineConstraints::distribute() for the model's owned field vectors,
 * with its communication planned once per set of constraints.
 *
 * deal.II's distribute() of a Trilinos vector builds, on every call, the
 * index set of the masters the owned constrained dofs need, a vector with
 * those ghosts and an Epetra import (AffineConstraints::distribute in
 * affine_constraints.templates.h). A Newton iteration distributes every
 * update, and the path following two per iteration: at the waterbeam of
 * Figure 11 on 2 ranks (158k unknowns, about 10k of them on the rigid end
 * plates) this took 4.9 % of the run. Here the owned constraint lines are
 * kept with the local positions of their masters in a ghosted buffer and
 * its Epetra_Import, so that a call is one import and one indexed sum per
 * line.
 *
 * The result is that of AffineConstraints::distribute(): x_i = b_i +
 * sum_j c_ij x_j on every owned constrained dof i (closed constraints, so
 * no master is itself constrained). The constraints must outlive this
 * object and not change after reinit().
 */

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>

#include <pneuma/core/linear_algebra.h>

#include <memory>
#include <vector>

class Epetra_Import;

namespace pneuma
{
  class ConstraintDistribution
  {
  public:
    ConstraintDistribution();
    ~ConstraintDistribution();

    /**
     * Plan the distribution of @p constraints (closed) on vectors with the
     * owned entries @p owned. Collective.
     */
    void
    reinit(const dealii::AffineConstraints<double> &constraints,
           const dealii::IndexSet                  &owned,
           const MPI_Comm                           comm);

    /**
     * Set the constrained entries of @p x (owned, without ghosts, of the
     * layout of reinit()) from their masters. Collective.
     */
    void
    distribute(LA::Vector &x) const;

  private:
    /// Owned constrained entries: local index in x, inhomogeneity, and
    /// the range of their masters in master_position/weight.
    std::vector<int>    line_local;
    std::vector<double> inhomogeneity;
    std::vector<int>    line_start;
    /// Masters' local positions in the ghosted buffer, and the weights.
    std::vector<int>    master_position;
    std::vector<double> weight;
    /// The owned entries and the masters of owned lines.
    mutable LA::Vector             buffer;
    std::unique_ptr<Epetra_Import> importer;
    bool                           any = false;
    /// The constraints of reinit() (kept by the caller).
    const dealii::AffineConstraints<double> *constraints = nullptr;
  };
} // namespace pneuma
