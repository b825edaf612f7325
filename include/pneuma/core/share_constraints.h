#pragma once

/**
 * @file
 * Making chains of constraints agree across MPI ranks.
 *
 * A junction copy is tied to a master, a rigid plate's nodes follow three
 * master nodes, and a master may itself be constrained (a plate node, a
 * support). The rank that owns such a master knows its constraint; a rank
 * that only holds a dependent dof may see no cell around the master and
 * would otherwise resolve the chain as if the master were free. It would
 * then condense its cell terms into the master's row and distribute
 * updates from the master's unconstrained value, and the two ranks would
 * disagree (Newton stalls, ties tear).
 */

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>

namespace pneuma
{
  using namespace dealii;

  /**
   * For every dof of @p shared (the same set on every rank) that its owner
   * has constrained, copy the owner's line (entries and inhomogeneity) into
   * @p constraints on every rank that can store it and has no line of its
   * own for it. Call before close().
   */
  void
  share_constraint_lines(AffineConstraints<double> &constraints,
                         const IndexSet            &shared,
                         const IndexSet            &locally_owned,
                         const MPI_Comm             comm);
} // namespace pneuma
