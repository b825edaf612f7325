#pragma once

/**
 * @file
 * The operators of the eigen solver (private to solvers/eigen_analysis.cc,
 * doc/theory.md section 13): the tangent with the chamber border
 * condensed, the shifted inverse on MUMPS' factorization with Sylvester's
 * count, the metric of the tangent problem, the tangent's rate of linear
 * buckling, ARPACK's partition of the unknowns, the residual of the
 * eigenpairs and the normalization of the modes.
 */

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/solvers/border.h>
#include <pneuma/solvers/stability.h>
#include <pneuma/solvers/symmetric_inertia.h>

#include <stdexcept>
#include <vector>

namespace pneuma
{
  namespace solvers
  {
    namespace eigen
    {
      using namespace dealii;

      /// Relative size below which an entry of A D counts as zero.
      constexpr double round_off = 1e-12;

      /**
       * The tangent with the chamber unknowns condensed (see the header):
       * y = K x - B (A D)^+ B^T x, where the unknowns with a diagonal in
       * A D (gas, liquid level) are eliminated and those without (volume
       * constraints) restrict x instead (the inverse keeps B^T x = 0).
       */
      class CondensedTangent
      {
      public:
        CondensedTangent(const LA::SparseMatrix &K,
                         const BorderCoupling   &c,
                         const EnergyBorder     &e)
          : K(K)
        {
          const unsigned int m = e.size();
          for (unsigned int j = 0; j < m; ++j)
            B.push_back(c.B[e.kept[j]]);
          double scale = 0.;
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              scale = std::max(scale, std::abs(e.AD(i, j)));
          std::vector<unsigned int> eliminated;
          std::vector<bool>         is_eliminated(m, false);
          for (unsigned int i = 0; i < m; ++i)
            if (std::abs(e.AD(i, i)) > round_off * scale)
              {
                eliminated.push_back(i);
                is_eliminated[i] = true;
              }
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              if (is_eliminated[i] != is_eliminated[j]
                  && std::abs(e.AD(i, j)) > round_off * scale)
                throw std::runtime_error(
                  "a chamber constraint is coupled to a compressible "
                  "chamber unknown; the eigen analysis does not condense "
                  "such a border");
          const unsigned int g = eliminated.size();
          FullMatrix<double> sub(g, g);
          for (unsigned int i = 0; i < g; ++i)
            for (unsigned int j = 0; j < g; ++j)
              sub(i, j) = e.AD(eliminated[i], eliminated[j]);
          if (g > 0)
            sub.gauss_jordan();
          pseudo_inverse.reinit(m, m);
          for (unsigned int i = 0; i < g; ++i)
            for (unsigned int j = 0; j < g; ++j)
              pseudo_inverse(eliminated[i], eliminated[j]) = sub(i, j);
        }

        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          K.vmult(y, x);
          const unsigned int m = B.size();
          if (m == 0)
            return;
          Vector<double> w(m), mu(m);
          for (unsigned int j = 0; j < m; ++j)
            w[j] = B[j] * x;
          pseudo_inverse.vmult(mu, w);
          for (unsigned int j = 0; j < m; ++j)
            y.add(-mu[j], B[j]);
        }

      private:
        const LA::SparseMatrix &K;
        std::vector<LA::Vector> B;
        FullMatrix<double>      pseudo_inverse;
      };

      /**
       * x = (K_c - sigma B)^{-1} y by the bordered solve on MUMPS' LDL^T
       * factorization of the shifted field block A = K - sigma B:
       * [A B; B^T AD] [x; mu] = [y; 0], mu = -S^{-1} B^T A^{-1} y with
       * S = AD - B^T A^{-1} B. Counts the eigenvalues below the shift.
       */
      class ShiftedInverse
      {
      public:
        ShiftedInverse(const MPI_Comm          comm,
                       const LA::SparseMatrix &A,
                       const BorderCoupling   &c,
                       const EnergyBorder     &e,
                       const IndexSet         &owned,
                       const bool              symmetric = true)
          : factorization(comm, 1e-12, symmetric)
          , owned(owned)
        {
          const Inertia k      = factorization.compute(A);
          zero_pivots          = k.zero;
          const unsigned int m = e.size();
          FullMatrix<double> S(m, m);
          for (unsigned int j = 0; j < m; ++j)
            B.emplace_back(c.B[e.kept[j]]);
          for (unsigned int j = 0; j < m; ++j)
            {
              Z.emplace_back(B[j].size());
              factorization.solve(B[j], Z[j]);
            }
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              S(i, j) = e.AD(i, j) - B[i] * Z[j];
          // Sylvester's count (an LU's pivots count nothing).
          negative  = symmetric ? static_cast<long long>(k.negative)
                                   + negative_eigenvalues(S)
                                   - static_cast<long long>(e.n_dual)
                                : -1;
          S_inverse = S;
          if (m > 0)
            S_inverse.gauss_jordan();
        }

        void
        vmult(LA::Vector &x, const LA::Vector &y) const
        {
          ++solves;
          const Vector<double> b(y); // every entry, on every rank
          Vector<double>       z(b.size());
          factorization.solve(b, z);
          const unsigned int m = B.size();
          if (m > 0)
            {
              Vector<double> w(m), mu(m);
              for (unsigned int j = 0; j < m; ++j)
                w[j] = B[j] * z;
              S_inverse.vmult(mu, w);
              for (unsigned int j = 0; j < m; ++j)
                z.add(mu[j], Z[j]);
            }
          for (const auto i : owned)
            x[i] = z[i];
          x.compress(VectorOperation::insert);
        }

        /// x_j = (K_c - sigma B)^{-1} y_j for all j in one MUMPS solve.
        void
        vmult(std::vector<LA::Vector>       &x,
              const std::vector<LA::Vector> &y) const
        {
          std::vector<Vector<double>> b, z;
          for (const auto &v : y)
            b.emplace_back(v); // every entry, on every rank
          solves += y.size();
          factorization.solve(b, z);
          const unsigned int m = B.size();
          for (unsigned int k = 0; k < y.size(); ++k)
            {
              if (m > 0)
                {
                  Vector<double> w(m), mu(m);
                  for (unsigned int j = 0; j < m; ++j)
                    w[j] = B[j] * z[k];
                  S_inverse.vmult(mu, w);
                  for (unsigned int j = 0; j < m; ++j)
                    z[k].add(mu[j], Z[j]);
                }
              for (const auto i : owned)
                x[k][i] = z[k][i];
              x[k].compress(VectorOperation::insert);
            }
        }

        long long               negative    = 0;
        types::global_dof_index zero_pivots = 0;
        /// Substitutions done (ARPACK's operator applications).
        mutable unsigned int solves = 0;

      private:
        mutable SymmetricInertia    factorization;
        const IndexSet             &owned;
        std::vector<Vector<double>> B, Z;
        FullMatrix<double>          S_inverse;
      };

      /// The metric of the tangent problem: the identity on free dofs.
      class FreeIdentity
      {
      public:
        explicit FreeIdentity(const AffineConstraints<double> &constraints)
          : constraints(constraints)
        {
        }
        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          y = x;
          constraints.set_zero(y);
        }

      private:
        const AffineConstraints<double> &constraints;
      };

      /**
       * -K' on the free dofs, K' = dK_c/dt along the linear response
       * (u + s v, t + s) by the second-order one-sided difference
       * K' = (-3 K_c(0) + 4 K_c(h) - K_c(2h)) / (2h).
       */
      class TangentRate
      {
      public:
        TangentRate(const CondensedTangent          &K0,
                    const CondensedTangent          &K1,
                    const CondensedTangent          &K2,
                    const double                     h,
                    const AffineConstraints<double> &constraints,
                    const TangentRate               *plus = nullptr)
          : K0(K0)
          , K1(K1)
          , K2(K2)
          , h(h)
          , constraints(constraints)
          , plus(plus)
        {
        }
        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          LA::Vector free(x), y1(x), y2(x);
          constraints.set_zero(free);
          K0.vmult(y, free);
          K1.vmult(y1, free);
          K2.vmult(y2, free);
          y *= -3.;
          y.add(4., y1, -1., y2);
          y *= -1. / (2. * h);
          if (plus)
            {
              plus->vmult(y1, x);
              y += y1;
            }
          constraints.set_zero(y);
        }

      private:
        const CondensedTangent          &K0, &K1, &K2;
        const double                     h;
        const AffineConstraints<double> &constraints;
        /// Another rate added to this one (the state's and the loads'
        /// parts of a split derivative).
        const TangentRate *plus;
      };

      /**
       * The largest relative residual of the eigenpairs (mu_k, x_k) of
       * A x = mu B x, measured as the solver sees it (through the inverse
       * C = (K_c - sigma B)^{-1} of the shifted tangent, so that stiff and
       * soft dofs weigh alike): |C (A x - mu B x)| / (s |x|), s = 1 for
       * shift-and-invert (C (A - mu B) x = x - (mu - sigma) C B x) and
       * s = |mu| for buckling's mode 2 (C = A_metric^{-1}). One MUMPS solve
       * for all pairs.
       */
      template <typename OperatorA, typename OperatorB>
      double
      relative_residual(const OperatorA               &A,
                        const OperatorB               &B,
                        const ShiftedInverse          &inverse,
                        const std::vector<double>     &mu,
                        const std::vector<LA::Vector> &modes,
                        const bool                     scale_by_mu)
      {
        std::vector<LA::Vector> r(modes), cr(modes);
        for (unsigned int k = 0; k < modes.size(); ++k)
          {
            LA::Vector b(modes[k]);
            A.vmult(r[k], modes[k]);
            B.vmult(b, modes[k]);
            r[k].add(-mu[k], b);
          }
        inverse.vmult(cr, r);
        double worst = 0.;
        for (unsigned int k = 0; k < modes.size(); ++k)
          {
            const double scale =
              (scale_by_mu ? std::abs(mu[k]) : 1.) * modes[k].l2_norm();
            worst = std::max(worst, cr[k].l2_norm() / std::max(scale, 1e-300));
          }
        return worst;
      }

      /**
       * ARPACK's vectors: the model's partition, or, when some rank owns
       * no unknowns (PARPACK needs local ones on every rank: a scene of
       * cables alone, which one rank owns), a balanced one; the operators
       * then see the model's partition through this map.
       */
      class ArpackPartition
      {
      public:
        ArpackPartition(const IndexSet &model_owned, const MPI_Comm comm)
          : model_owned(model_owned)
          , comm(comm)
        {
          const types::global_dof_index empty =
            Utilities::MPI::min(static_cast<types::global_dof_index>(
                                  model_owned.n_elements()),
                                comm);
          repartitioned = empty == 0;
          if (!repartitioned)
            owned = model_owned;
          else
            {
              const types::global_dof_index n = model_owned.size();
              const unsigned int rank = Utilities::MPI::this_mpi_process(comm),
                                 p    = Utilities::MPI::n_mpi_processes(comm);
              owned                   = IndexSet(n);
              owned.add_range(n * rank / p, n * (rank + 1) / p);
            }
        }
        /// A vector of partition @p to with the entries of @p v.
        LA::Vector
        convert(const LA::Vector &v, const IndexSet &to) const
        {
          LA::Vector           result(to, comm);
          const Vector<double> all(v); // every entry, on every rank
          for (const auto i : to)
            result[i] = all[i];
          result.compress(VectorOperation::insert);
          return result;
        }
        LA::Vector
        to_model(const LA::Vector &v) const
        {
          return repartitioned ? convert(v, model_owned) : v;
        }
        LA::Vector
        to_arpack(const LA::Vector &v) const
        {
          return repartitioned ? convert(v, owned) : v;
        }

        const IndexSet &model_owned;
        const MPI_Comm  comm;
        IndexSet        owned;
        bool            repartitioned = false;
      };

      /// An operator of the model seen in ARPACK's partition.
      template <typename Operator>
      class InPartition
      {
      public:
        InPartition(const Operator &op, const ArpackPartition &partition)
          : op(op)
          , partition(partition)
        {
        }
        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          if (!partition.repartitioned)
            {
              op.vmult(y, x);
              return;
            }
          const LA::Vector x_model = partition.to_model(x);
          LA::Vector       y_model(x_model);
          op.vmult(y_model, x_model);
          y = partition.to_arpack(y_model);
        }

      private:
        const Operator        &op;
        const ArpackPartition &partition;
      };

      template <typename Operator>
      InPartition<Operator>
      in_partition(const Operator &op, const ArpackPartition &partition)
      {
        return InPartition<Operator>(op, partition);
      }

      /// Scale @p v to a largest component of +1 (the first such entry
      /// in the global numbering decides the sign: the same on any number
      /// of ranks).
      inline void
      normalize(LA::Vector &v, const IndexSet &owned, const MPI_Comm comm)
      {
        const double largest = v.linfty_norm();
        if (largest == 0.)
          return;
        types::global_dof_index first = numbers::invalid_dof_index;
        double                  sign  = 1.;
        for (const auto i : owned)
          if (std::abs(v[i]) >= (1. - 1e-9) * largest)
            {
              first = i;
              sign  = v[i] > 0. ? 1. : -1.;
              break;
            }
        const types::global_dof_index winner = Utilities::MPI::min(first, comm);
        const double s = Utilities::MPI::sum(first == winner ? sign : 0., comm);
        v *= s / largest;
      }
    } // namespace eigen
  }   // namespace solvers
} // namespace pneuma
