#pragma once

/**
 * @file
 * The one place that names the distributed linear-algebra types. Everything
 * else in pneuma uses these aliases (Trilinos/Epetra through deal.II).
 */

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
  } // namespace LA
} // namespace pneuma
