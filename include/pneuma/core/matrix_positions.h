#pragma once

/**
 * @file
 * Cell matrices added straight into a Trilinos matrix's value array
 * (issue 17): the position of every (row, column) pair of a cell in the
 * compressed rows is found once per sparsity pattern by binary search, so
 * an assembly adds a cell matrix with one indexed addition per entry
 * instead of a global-to-local lookup and a search per entry
 * (AffineConstraints::distribute_local_to_global into
 * Epetra_FECrsMatrix::SumIntoGlobalValues).
 *
 * Only cells whose rows are all locally owned take this path, and the
 * caller must also check that none of their dofs is constrained; the
 * others go through the constraints as before. The positions are
 * rebuilt whenever the matrix's arrays change (a new sparsity pattern):
 * the key holds the addresses and sizes of the row offsets, column
 * indices and values and a checksum of the column indices.
 */

#include <deal.II/lac/affine_constraints.h>

#include <pneuma/core/linear_algebra.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pneuma
{
  namespace LA
  {
    class MatrixPositions
    {
    public:
      /**
       * Make the positions valid for @p matrix and the @p n_cells cells
       * whose @p n_dofs dof indices each follow each other in @p dofs
       * (recomputed only if the matrix's arrays changed). False if the
       * matrix does not keep its values in one array.
       */
      bool
      update(const SparseMatrix                    &matrix,
             const dealii::types::global_dof_index *dofs,
             const unsigned int                     n_cells,
             const unsigned int                     n_dofs);

      /**
       * The same, and with @p constraints (homogeneous where a cell's dofs
       * are constrained; closed) also the positions of the cells with
       * constrained dofs whose targets (their unconstrained dofs and the
       * masters of the constrained ones) and constrained dofs all have
       * owned rows: such a cell matrix K is added as C^T K C on the
       * targets (C: the constraints' weights) plus deal.II's diagonal
       * entry on each constrained row (AffineConstraints::
       * distribute_local_to_global, whose result it reproduces), without
       * a global-index lookup. The rigid end plates are a quarter of the
       * waterbeam's cells, each with its 12 unknowns on the plate's 9.
       */
      bool
      update(const SparseMatrix                      &matrix,
             const dealii::types::global_dof_index   *dofs,
             const unsigned int                       n_cells,
             const unsigned int                       n_dofs,
             const dealii::AffineConstraints<double> &constraints);

      /// Is cell @p k added condensed (see update())?
      bool
      condensed(const unsigned int k) const
      {
        return !condensed_of.empty() && condensed_of[k] >= 0;
      }

      /// Add the row-major cell matrix @p m of a condensed cell @p k.
      void
      add_condensed(const unsigned int k, const double *m) const;

      /// Are all targets of the condensed cell @p k owned here (may its
      /// vectors go to the local values)?
      bool
      condensed_owned(const unsigned int k) const
      {
        return condensed_cells[condensed_of[k]].owned;
      }

      /// Add the cell vector @p v of a condensed cell @p k whose targets
      /// are owned to @p local.
      void
      add_condensed_vector(const unsigned int k,
                           const double      *v,
                           double            *local) const;

      /**
       * Add the sums of the condensed entries in rows owned by other
       * ranks (a plate whose three nodes are there) to @p matrix through
       * its global indices, once per entry and assembly; call before the
       * matrix is compressed.
       */
      void
      flush(SparseMatrix &matrix) const;

      /// Are all rows of cell @p k owned here (direct path possible)?
      bool
      direct(const unsigned int k) const
      {
        return row_of[std::size_t(k) * n_dofs_per_cell] >= 0;
      }

      /// Add the n_dofs x n_dofs row-major cell matrix @p m of cell @p k.
      void
      add(const unsigned int k, const double *m) const
      {
        const int           *rows = &row_of[std::size_t(k) * n_dofs_per_cell];
        const std::uint16_t *off =
          &offset_of[std::size_t(k) * n_dofs_per_cell * n_dofs_per_cell];
        for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
          {
            double *row = values + row_start[rows[i]];
            for (unsigned int j = 0; j < n_dofs_per_cell; ++j)
              row[off[j]] += m[j];
            off += n_dofs_per_cell;
            m += n_dofs_per_cell;
          }
      }

      /**
       * The local values of @p vector if its owned entries are numbered
       * like the matrix's rows (then add_vector() may write to them),
       * else nullptr.
       */
      double *
      local_values(Vector &vector) const;

      /// Add the cell vector @p v of cell @p k to the @p local values.
      void
      add_vector(const unsigned int k, const double *v, double *local) const
      {
        const int *rows = &row_of[std::size_t(k) * n_dofs_per_cell];
        for (unsigned int i = 0; i < n_dofs_per_cell; ++i)
          local[rows[i]] += v[i];
      }

    private:
      struct Key
      {
        const void   *offsets = nullptr, *indices = nullptr, *values = nullptr;
        long long     n_rows = -1, n_entries = -1;
        std::uint64_t checksum = 0;
        unsigned int  n_cells = 0, n_dofs = 0;
        bool
        operator==(const Key &o) const
        {
          return offsets == o.offsets && indices == o.indices
                 && values == o.values && n_rows == o.n_rows
                 && n_entries == o.n_entries && checksum == o.checksum
                 && n_cells == o.n_cells && n_dofs == o.n_dofs;
        }
      };
      Key              key;
      unsigned int     n_dofs_per_cell = 0;
      double          *values          = nullptr;
      const int       *row_start       = nullptr;
      std::vector<int> row_of;
      /// Global indices of the matrix's local rows.
      std::vector<int>           matrix_rows;
      std::vector<std::uint16_t> offset_of;

      /// A cell added through its constraints.
      struct Condensed
      {
        /// Local rows of the targets; the cell dof's weights on them
        /// (n_dofs x n_targets, row-major).
        std::vector<int>    target_rows;
        bool                owned = true;
        std::vector<double> weights;
        /// Positions in the values of the target pairs (n_targets^2),
        /// or -(s + 1) for the nonlocal slot s.
        std::vector<std::ptrdiff_t> pair_positions;
        /// The constrained cell dofs and the positions of their diagonal.
        std::vector<unsigned int>   constrained;
        std::vector<std::ptrdiff_t> diagonal_positions;
      };
      /// The positions of a matrix's entries (matrix_positions.cc).
      class Lookup;
      /// The condensation @p c of the cell with @p cell_dofs through
      /// @p constraints; false if it has no constrained dof or cannot be
      /// condensed at fixed positions (an inhomogeneous or open line, an
      /// entry missing from the pattern).
      bool
      condense(const dealii::types::global_dof_index        *cell_dofs,
               const unsigned int                            n_dofs,
               const dealii::AffineConstraints<double>      &constraints,
               Lookup                                       &lookup,
               std::vector<dealii::types::global_dof_index> &targets,
               Condensed                                    &c) const;
      std::vector<int>       condensed_of;
      std::vector<Condensed> condensed_cells;
      const void            *constraints_address = nullptr;
      std::size_t            n_constraint_lines  = 0;
      /// Entries in rows owned elsewhere and their sums in this assembly.
      std::vector<std::pair<dealii::types::global_dof_index,
                            dealii::types::global_dof_index>>
                                  nonlocal_entries;
      mutable std::vector<double> nonlocal_values;
      /// K C of add_condensed() (the copier is serial).
      mutable std::vector<double> scratch;
    };
  } // namespace LA
} // namespace pneuma
