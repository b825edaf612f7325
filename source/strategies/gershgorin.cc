#include <deal.II/lac/full_matrix.h>

#include <Epetra_CrsMatrix.h>

#include <pneuma/core/model.h>
#include <pneuma/strategies/gershgorin.h>

#include <cmath>
#include <vector>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    namespace
    {
      /// Row sums of |K| over the owned rows of the tangent's field block
      /// (@p sums: one per owned row, in order), read in place from the
      /// Epetra rows (deal.II's row iterator copies every row it visits).
      void
      add_row_sums(const LA::SparseMatrix &K,
                   const IndexSet         &owned,
                   std::vector<double>    &sums)
      {
        const Epetra_CrsMatrix &M = K.trilinos_matrix();
        for (int r = 0; r < M.NumMyRows(); ++r)
          {
            int     n       = 0;
            double *entries = nullptr;
            int    *columns = nullptr;
            M.ExtractMyRowView(r, n, entries, columns);
            double &sum = sums[owned.index_within_set(M.GRID64(r))];
            for (int k = 0; k < n; ++k)
              sum += std::abs(entries[k]);
          }
      }

      /// The border's bound (see stiffness_row_sums()) over the unknowns
      /// that follow the field (a nonzero diagonal in D). Unknowns without
      /// a field column or row (a prescribed pressure) add nothing; the
      /// multipliers of constraints (a prescribed volume, D_jj = 0) remove
      /// a motion rather than stiffen one, which lowers no bound.
      void
      add_border_sums(const solvers::BorderCoupling &coupling,
                      const IndexSet                &owned,
                      std::vector<double>           &sums)
      {
        std::vector<unsigned int> follow;
        for (unsigned int k = 0; k < coupling.size(); ++k)
          if (coupling.D(k, k) != 0.)
            follow.push_back(k);
        const unsigned int n = follow.size();
        if (n == 0)
          return;
        FullMatrix<double> D_inverse(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            D_inverse(i, j) = coupling.D(follow[i], follow[j]);
        D_inverse.gauss_jordan();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            if (!std::isfinite(D_inverse(i, j)))
              return; // a singular border block couples only through K
        std::vector<double> c_norm(n, 0.);
        for (unsigned int l = 0; l < n; ++l)
          if (coupling.has_C[follow[l]])
            c_norm[l] = coupling.C[follow[l]].l1_norm();
        for (unsigned int k = 0; k < n; ++k)
          if (coupling.has_B[follow[k]])
            {
              double weight = 0.;
              for (unsigned int l = 0; l < n; ++l)
                weight += std::abs(D_inverse(k, l)) * c_norm[l];
              const LA::Vector &B = coupling.B[follow[k]];
              unsigned int      j = 0;
              for (const auto row : owned)
                sums[j++] += std::abs(B[row]) * weight;
            }
      }
    } // namespace

    LA::Vector
    stiffness_row_sums(const Model &model)
    {
      const IndexSet     &owned = model.locally_owned();
      std::vector<double> sums(owned.n_elements(), 0.);
      add_row_sums(model.tangent_matrix(), owned, sums);
      add_border_sums(model.border_coupling(), owned, sums);
      LA::Vector   g = model.make_field();
      unsigned int k = 0;
      for (const auto row : owned)
        g[row] = sums[k++];
      g.compress(VectorOperation::insert);
      return g;
    }
  } // namespace strategies
} // namespace pneuma
