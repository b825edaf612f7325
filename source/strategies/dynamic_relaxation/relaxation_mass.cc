#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <pneuma/core/capabilities.h>
#include <pneuma/core/model.h>
#include <pneuma/strategies/dynamic_relaxation/dynamic_relaxation.h>

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
      /// (@p sums: one per owned row, in order).
      void
      add_row_sums(const LA::SparseMatrix &K,
                   const IndexSet         &owned,
                   std::vector<double>    &sums)
      {
        unsigned int k = 0;
        for (const auto row : owned)
          {
            for (auto e = K.begin(row); e != K.end(row); ++e)
              sums[k] += std::abs(e->value());
            ++k;
          }
      }

      /**
       * The row sums of |B D^-1 C^T|, bounded by sum_kl |B_ik| |D^-1_kl|
       * |C_l|_1: the stiffness that the border unknowns add once they
       * follow the field (a gas chamber's dp/dV g g^T). Unknowns without
       * a field column or row (a prescribed pressure) add nothing.
       */
      void
      add_border_sums(const solvers::BorderCoupling &coupling,
                      const IndexSet                &owned,
                      std::vector<double>           &sums)
      {
        const unsigned int n = coupling.size();
        if (n == 0)
          return;
        FullMatrix<double> D_inverse(n, n);
        D_inverse.copy_from(coupling.D);
        try
          {
            D_inverse.gauss_jordan();
          }
        catch (...)
          {
            return; // a singular border block couples only through K
          }
        std::vector<double> c_norm(n, 0.);
        for (unsigned int l = 0; l < n; ++l)
          if (coupling.has_C[l])
            c_norm[l] = coupling.C[l].l1_norm();
        for (unsigned int k = 0; k < n; ++k)
          if (coupling.has_B[k])
            {
              double weight = 0.;
              for (unsigned int l = 0; l < n; ++l)
                weight += std::abs(D_inverse(k, l)) * c_norm[l];
              unsigned int j = 0;
              for (const auto row : owned)
                sums[j++] += std::abs(coupling.B[k][row]) * weight;
            }
      }
    } // namespace

    LA::Vector
    relaxation_mass(const Model &model, const double safety)
    {
      const IndexSet     &owned = model.locally_owned();
      std::vector<double> sums(owned.n_elements(), 0.);
      add_row_sums(model.tangent_matrix(), owned, sums);
      add_border_sums(model.border_coupling(), owned, sums);
      LA::Vector   m = model.make_field();
      unsigned int k = 0;
      for (const auto row : owned)
        m[row] = sums[k++];
      m.compress(VectorOperation::insert);
      for (const auto *i : model.with<Inertia>())
        i->largest_per_node(m);
      // A free dof without any stiffness yet (nothing holds it) moves
      // with the largest mass; a constrained one does not move.
      const double largest = m.linfty_norm();
      const auto  &c       = model.constraints();
      for (const auto row : owned)
        {
          const double s = m[row];
          m[row]         = c.is_constrained(row) ? 1.
                           : s > 0.              ? 0.25 * safety * s
                                                 : 0.25 * safety * largest;
        }
      m.compress(VectorOperation::insert);
      AssertThrow(largest > 0.,
                  ExcMessage("dynamic relaxation: the tangent is zero, so "
                             "no fictitious mass can be chosen"));
      return m;
    }
  } // namespace strategies
} // namespace pneuma
