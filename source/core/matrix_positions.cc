#include <pneuma/core/matrix_positions.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <limits>

namespace pneuma
{
  namespace LA
  {
    bool
    MatrixPositions::update(const SparseMatrix                    &matrix,
                            const dealii::types::global_dof_index *dofs,
                            const unsigned int                     n_cells,
                            const unsigned int                     n_dofs)
    {
      const Epetra_CrsMatrix &A       = matrix.trilinos_matrix();
      int                    *offsets = nullptr, *indices = nullptr;
      double                 *vals = nullptr;
      if (!A.StorageOptimized()
          || A.ExtractCrsDataPointers(offsets, indices, vals) != 0)
        return false;
      Key k;
      k.offsets   = offsets;
      k.indices   = indices;
      k.values    = vals;
      k.n_rows    = A.NumMyRows();
      k.n_entries = A.NumMyNonzeros();
      k.n_cells   = n_cells;
      k.n_dofs    = n_dofs;
      // The checksum tells a new pattern in reused memory from the old.
      for (long long e = 0; e < k.n_entries; ++e)
        k.checksum = k.checksum * 1099511628211ull
                     + static_cast<std::uint64_t>(indices[e]) + 1;
      values    = vals;
      row_start = offsets;
      if (k == key)
        return true;

      key             = k;
      n_dofs_per_cell = n_dofs;
      row_of.assign(std::size_t(n_cells) * n_dofs, -1);
      offset_of.assign(std::size_t(n_cells) * n_dofs * n_dofs, 0);
      const Epetra_Map &rows = A.RowMap();
      matrix_rows.assign(rows.MyGlobalElements(),
                         rows.MyGlobalElements() + rows.NumMyElements());
      const Epetra_BlockMap &cols = A.ColMap();
      std::vector<int>       lrow(n_dofs), lcol(n_dofs);
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          const auto *cell_dofs = dofs + std::size_t(c) * n_dofs;
          bool        owned     = true;
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const auto gid =
                static_cast<dealii::TrilinosWrappers::types::int_type>(
                  cell_dofs[i]);
              lrow[i] = rows.LID(gid);
              lcol[i] = cols.LID(gid);
              owned   = owned && lrow[i] >= 0 && lcol[i] >= 0;
            }
          if (!owned)
            continue;
          bool found = true;
          for (unsigned int i = 0; i < n_dofs && found; ++i)
            {
              const int *begin = indices + offsets[lrow[i]];
              const int *end   = indices + offsets[lrow[i] + 1];
              // Rows are sorted after FillComplete with optimized storage,
              // but do not rely on it.
              const bool sorted = std::is_sorted(begin, end);
              for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  const int *p = sorted ? std::lower_bound(begin, end, lcol[j])
                                        : std::find(begin, end, lcol[j]);
                  if (p == end || *p != lcol[j]
                      || p - begin > std::numeric_limits<std::uint16_t>::max())
                    {
                      found = false;
                      break;
                    }
                  offset_of[(std::size_t(c) * n_dofs + i) * n_dofs + j] =
                    static_cast<std::uint16_t>(p - begin);
                }
            }
          if (found)
            for (unsigned int i = 0; i < n_dofs; ++i)
              row_of[std::size_t(c) * n_dofs + i] = lrow[i];
        }
      return true;
    }
    double *
    MatrixPositions::local_values(Vector &vector) const
    {
      if (key.n_rows < 0)
        return nullptr;
      Epetra_FEVector &v    = vector.trilinos_vector();
      const auto      &vmap = v.Map();
      const auto      &rmap = matrix_rows;
      if (static_cast<std::size_t>(vmap.NumMyElements()) != rmap.size()
          || !std::equal(rmap.begin(), rmap.end(), vmap.MyGlobalElements()))
        return nullptr;
      return v[0];
    }
  } // namespace LA
} // namespace pneuma
