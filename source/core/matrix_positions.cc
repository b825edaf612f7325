#include <pneuma/core/matrix_positions.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

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
    /// Where (global row i, global column j) is summed in a matrix: its
    /// position in the values (owned row; `missing` if the pattern lacks
    /// it), or -(s + 1) for the slot s of a row owned elsewhere (added in
    /// flush()), the slot appended to @p nonlocal.
    class MatrixPositions::Lookup
    {
    public:
      static constexpr std::ptrdiff_t missing =
        std::numeric_limits<std::ptrdiff_t>::min();

      Lookup(const SparseMatrix                                      &matrix,
             std::vector<std::pair<dealii::types::global_dof_index,
                                   dealii::types::global_dof_index>> &nonlocal)
        : rows(matrix.trilinos_matrix().RowMap())
        , cols(matrix.trilinos_matrix().ColMap())
        , nonlocal(nonlocal)
      {
        double *vals = nullptr;
        matrix.trilinos_matrix().ExtractCrsDataPointers(offsets, indices, vals);
      }

      std::ptrdiff_t
      operator()(const dealii::types::global_dof_index i,
                 const dealii::types::global_dof_index j)
      {
        const int r = row(i);
        if (r < 0)
          {
            const auto it = slots.emplace(std::make_pair(i, j), slots.size());
            if (it.second)
              nonlocal.emplace_back(i, j);
            return -(it.first->second + 1);
          }
        const int c = cols.LID(static_cast<int_type>(j));
        if (c < 0)
          return missing;
        const int *begin = indices + offsets[r];
        const int *end   = indices + offsets[r + 1];
        const int *p     = std::is_sorted(begin, end)
                             ? std::lower_bound(begin, end, c)
                             : std::find(begin, end, c);
        return p == end || *p != c ? missing : std::ptrdiff_t(p - indices);
      }

      /// The local row of global row @p i (negative: not owned).
      int
      row(const dealii::types::global_dof_index i) const
      {
        return rows.LID(static_cast<int_type>(i));
      }

    private:
      using int_type = dealii::TrilinosWrappers::types::int_type;
      const Epetra_BlockMap &rows;
      const Epetra_BlockMap &cols;
      int                   *offsets = nullptr, *indices = nullptr;
      std::map<std::pair<dealii::types::global_dof_index,
                         dealii::types::global_dof_index>,
               std::ptrdiff_t>
                                                               slots;
      std::vector<std::pair<dealii::types::global_dof_index,
                            dealii::types::global_dof_index>> &nonlocal;
    };

    bool
    MatrixPositions::condense(
      const dealii::types::global_dof_index        *cell_dofs,
      const unsigned int                            n_dofs,
      const dealii::AffineConstraints<double>      &constraints,
      Lookup                                       &position,
      std::vector<dealii::types::global_dof_index> &targets,
      Condensed                                    &c) const
    {
      // The cell's targets: its unconstrained dofs and the masters of its
      // constrained ones (closed, homogeneous lines only).
      bool any = false, usable = true;
      targets.clear();
      for (unsigned int i = 0; i < n_dofs && usable; ++i)
        {
          const auto d = cell_dofs[i];
          if (!constraints.is_constrained(d))
            {
              targets.push_back(d);
              continue;
            }
          any = true;
          if (constraints.is_inhomogeneously_constrained(d))
            usable = false;
          else
            for (const auto &entry : *constraints.get_constraint_entries(d))
              {
                if (constraints.is_constrained(entry.first))
                  usable = false; // not closed
                targets.push_back(entry.first);
              }
        }
      if (!any || !usable)
        return false;
      std::sort(targets.begin(), targets.end());
      targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
      const unsigned int n_t = targets.size();
      c.target_rows.resize(n_t);
      c.weights.assign(std::size_t(n_dofs) * n_t, 0.);
      c.pair_positions.resize(std::size_t(n_t) * n_t);
      const auto target = [&](const dealii::types::global_dof_index d) {
        return static_cast<unsigned int>(
          std::lower_bound(targets.begin(), targets.end(), d)
          - targets.begin());
      };
      for (unsigned int a = 0; a < n_t && usable; ++a)
        {
          c.target_rows[a] = position.row(targets[a]);
          c.owned          = c.owned && c.target_rows[a] >= 0;
          for (unsigned int b = 0; b < n_t && usable; ++b)
            {
              const auto p = position(targets[a], targets[b]);
              usable       = p != Lookup::missing;
              c.pair_positions[std::size_t(a) * n_t + b] = p;
            }
        }
      for (unsigned int i = 0; i < n_dofs && usable; ++i)
        {
          const auto d = cell_dofs[i];
          if (!constraints.is_constrained(d))
            {
              c.weights[std::size_t(i) * n_t + target(d)] = 1.;
              continue;
            }
          for (const auto &entry : *constraints.get_constraint_entries(d))
            c.weights[std::size_t(i) * n_t + target(entry.first)] +=
              entry.second;
          const auto p = position(d, d);
          usable       = p != Lookup::missing;
          c.constrained.push_back(i);
          c.diagonal_positions.push_back(p);
        }
      return usable;
    }

    bool
    MatrixPositions::update(
      const SparseMatrix                      &matrix,
      const dealii::types::global_dof_index   *dofs,
      const unsigned int                       n_cells,
      const unsigned int                       n_dofs,
      const dealii::AffineConstraints<double> &constraints)
    {
      const Key old = key;
      if (!update(matrix, dofs, n_cells, n_dofs))
        return false;
      std::fill(nonlocal_values.begin(), nonlocal_values.end(), 0.);
      if (key == old && constraints_address == &constraints
          && n_constraint_lines == constraints.n_constraints()
          && condensed_of.size() == n_cells)
        return true;
      constraints_address = &constraints;
      n_constraint_lines  = constraints.n_constraints();
      condensed_of.assign(n_cells, -1);
      condensed_cells.clear();
      nonlocal_entries.clear();
      Lookup lookup(matrix, nonlocal_entries);
      std::vector<dealii::types::global_dof_index> targets;
      for (unsigned int k = 0; k < n_cells; ++k)
        {
          Condensed c;
          if (!condense(dofs + std::size_t(k) * n_dofs,
                        n_dofs,
                        constraints,
                        lookup,
                        targets,
                        c))
            continue;
          condensed_of[k] = condensed_cells.size();
          condensed_cells.push_back(std::move(c));
        }
      nonlocal_values.assign(nonlocal_entries.size(), 0.);
      return true;
    }

    void
    MatrixPositions::add_condensed(const unsigned int k, const double *m) const
    {
      const Condensed   &c   = condensed_cells[condensed_of[k]];
      const unsigned int n   = n_dofs_per_cell;
      const unsigned int n_t = c.target_rows.size();
      const double      *C   = c.weights.data();
      const auto         add = [&](const std::ptrdiff_t p, const double value) {
        if (p >= 0)
          values[p] += value;
        else
          nonlocal_values[-p - 1] += value;
      };
      {
        // K C (n x n_t), then C^T (K C).
        scratch.assign(std::size_t(n) * n_t, 0.);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const double kij = m[std::size_t(i) * n + j];
              if (kij == 0.)
                continue;
              const double *Cj  = C + std::size_t(j) * n_t;
              double       *row = &scratch[std::size_t(i) * n_t];
              for (unsigned int b = 0; b < n_t; ++b)
                row[b] += kij * Cj[b];
            }
        for (unsigned int a = 0; a < n_t; ++a)
          for (unsigned int b = 0; b < n_t; ++b)
            {
              double sum = 0.;
              for (unsigned int i = 0; i < n; ++i)
                sum += C[std::size_t(i) * n_t + a]
                       * scratch[std::size_t(i) * n_t + b];
              add(c.pair_positions[std::size_t(a) * n_t + b], sum);
            }
        // deal.II's diagonal of the constrained rows: |K_ii|, or where
        // K_ii is 0 the mean of |K_jj| (if that is 0, the l1 norm of K
        // over n; if that is 0, 1).
        double average = 0.;
        for (unsigned int i = 0; i < n; ++i)
          average += std::abs(m[std::size_t(i) * n + i]);
        average /= n;
        if (average == 0.)
          {
            for (unsigned int j = 0; j < n; ++j)
              {
                double column = 0.;
                for (unsigned int i = 0; i < n; ++i)
                  column += std::abs(m[std::size_t(i) * n + j]);
                average = std::max(average, column);
              }
            average /= n;
            if (average == 0.)
              average = 1.;
          }
        for (unsigned int q = 0; q < c.constrained.size(); ++q)
          {
            const unsigned int i = c.constrained[q];
            const double       d = std::abs(m[std::size_t(i) * n + i]);
            add(c.diagonal_positions[q], d != 0. ? d : average);
          }
      }
    }

    void
    MatrixPositions::add_condensed_vector(const unsigned int k,
                                          const double      *v,
                                          double            *local) const
    {
      const Condensed   &c   = condensed_cells[condensed_of[k]];
      const unsigned int n   = n_dofs_per_cell;
      const unsigned int n_t = c.target_rows.size();
      const double      *C   = c.weights.data();
      Assert(c.owned, dealii::ExcInternalError());
      for (unsigned int a = 0; a < n_t; ++a)
        {
          double sum = 0.;
          for (unsigned int i = 0; i < n; ++i)
            sum += C[std::size_t(i) * n_t + a] * v[i];
          local[c.target_rows[a]] += sum;
        }
    }

    void
    MatrixPositions::flush(SparseMatrix &matrix) const
    {
      for (std::size_t s = 0; s < nonlocal_entries.size(); ++s)
        if (nonlocal_values[s] != 0.)
          {
            matrix.add(nonlocal_entries[s].first,
                       nonlocal_entries[s].second,
                       nonlocal_values[s]);
            nonlocal_values[s] = 0.;
          }
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
