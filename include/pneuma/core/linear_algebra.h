#pragma once

/**
 * @file
 * The one place that names the distributed linear-algebra types. Everything
 * else in pneuma uses these aliases (Trilinos/Epetra through deal.II).
 */

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

namespace pneuma
{
  namespace LA
  {
    /// Distributed vector (owned entries, or owned + ghosts when read).
    using Vector = dealii::TrilinosWrappers::MPI::Vector;
    /// Distributed sparse matrix.
    using SparseMatrix = dealii::TrilinosWrappers::SparseMatrix;
    /// Distributed sparsity pattern.
    using SparsityPattern = dealii::TrilinosWrappers::SparsityPattern;

    /**
     * Add a cell's (or element's) matrix and vector to the global
     * @p matrix and @p vector through @p constraints; either target may be
     * nullptr, and both are filled in one pass when both are given.
     */
    inline void
    distribute(const dealii::AffineConstraints<double>            &constraints,
               const dealii::FullMatrix<double>                   &cell_matrix,
               const dealii::Vector<double>                       &cell_vector,
               const std::vector<dealii::types::global_dof_index> &dofs,
               SparseMatrix                                       *matrix,
               Vector                                             *vector)
    {
      if (matrix && vector)
        constraints.distribute_local_to_global(
          cell_matrix, cell_vector, dofs, *matrix, *vector);
      else if (matrix)
        constraints.distribute_local_to_global(cell_matrix, dofs, *matrix);
      else if (vector)
        constraints.distribute_local_to_global(cell_vector, dofs, *vector);
    }
  } // namespace LA
} // namespace pneuma
