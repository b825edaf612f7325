#pragma once

/**
 * @file
 * The inertia of a symmetric sparse matrix (the numbers of negative, zero
 * and positive eigenvalues) from MUMPS' LDL^T factorization, the
 * stability test of a converged state (Sylvester's law of inertia: the
 * inertia of A equals that of D in A = L D L^T).
 *
 * Trilinos' Amesos_Mumps always factorizes with SYM = 0 (LU, whose pivot
 * signs say nothing about eigenvalues), so this class calls MUMPS' C
 * interface itself (MUMPS 5.5 user guide, Sec. 5.2 and INFOG(12), (28)):
 * - SYM = 2 (general symmetric, 1x1 and 2x2 pivots; the count of negative
 *   eigenvalues of a 2x2 pivot block is exact: one if its determinant is
 *   negative, else two if its diagonal is),
 * - only the upper triangle, distributed by rows (ICNTL(18) = 3),
 * - ICNTL(13) = 1: no ScaLAPACK root, whose pivots INFOG(12) would not
 *   count in parallel,
 * - ICNTL(24) = 1: null pivot detection; INFOG(28) counts pivots below the
 *   threshold CNTL(3) (relative to the matrix norm), which are then
 *   neither negative nor positive.
 * The analysis is redone only when the sparsity pattern changes.
 *
 * **Reproducible on several ranks.** MUMPS' parallel factorization and
 * solve are asynchronous: contribution blocks and right-hand-side pieces
 * from other ranks are summed in the order they arrive, so on 2 ranks the
 * same matrix gives factors and solutions that differ in the last bits
 * from run to run (measured: 3 of 5 solves with one set of factors, and 2
 * of 15 determinants, differed; ICNTL(13) = 1, no scaling, or no type-2
 * nodes do not change that). By default the matrix is therefore gathered
 * to rank 0, which factorizes and solves alone (MUMPS on MPI_COMM_SELF,
 * the other ranks sleep meanwhile): the same input on the same ranks and
 * threads gives the same bits. set_distributed_factorization(true)
 * (Linear solver/direct/Distributed factorization) lets MUMPS use all
 * ranks instead: faster on many ranks, not reproducible in the last digits.
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>

#include <memory>
#include <vector>

namespace pneuma
{
  namespace solvers
  {
    /// Eigenvalue sign counts of a symmetric matrix.
    struct Inertia
    {
      dealii::types::global_dof_index negative = 0, zero = 0, positive = 0;
    };

    /// A MUMPS count such as INFOG(29), which is minus the count in
    /// millions when negative.
    double
    mumps_count(const int infog);

    /// Inertia by MUMPS' symmetric indefinite factorization.
    class SymmetricInertia
    {
    public:
      /// Factorize across all ranks (true) or on rank 0 alone (false, the
      /// default: reproducible), for the objects constructed from now on.
      static void
      set_distributed_factorization(const bool distributed);
      static bool
      distributed_factorization();

      /**
       * @p zero_pivot_threshold: a pivot below this times the matrix norm
       * counts as a zero eigenvalue (CNTL(3)); 0 turns the null pivot
       * detection off, so that a singular matrix fails to factorize (the
       * Newton solves, which regularize a singular tangent themselves).
       */
      explicit SymmetricInertia(const MPI_Comm comm,
                                const double   zero_pivot_threshold = 1e-12,
                                const bool     symmetric            = true);
      ~SymmetricInertia();

      /**
       * The inertia of @p A (symmetric; only its upper triangle is read).
       * Constructed with @p symmetric = false, the factorization is MUMPS'
       * LU (SYM = 0) of the whole matrix, for its solves; its "inertia"
       * then only counts zero pivots.
       */
      /// Throws std::runtime_error with MUMPS' error code if it fails.
      Inertia
      compute(const LA::SparseMatrix &A);

      /// x = A^{-1} b with the factorization of the last compute() (@p b
      /// and @p x: full vectors, the same on every rank).
      void
      solve(const dealii::Vector<double> &b, dealii::Vector<double> &x);

      /// The same for several right-hand sides at once (one MUMPS solve
      /// with NRHS = b.size(): one pass over the factors).
      void
      solve(const std::vector<dealii::Vector<double>> &b,
            std::vector<dealii::Vector<double>>       &x);

      /// x = A^{-1} b for distributed vectors (gathered to MUMPS' host
      /// and scattered back; @p x has the layout of @p b).
      void
      solve(const LA::Vector &b, LA::Vector &x);

      /// x_j = A^{-1} b_j for several distributed right-hand sides of one
      /// layout, in one MUMPS solve (NRHS = b.size(): one pass over the
      /// factors instead of one per vector).
      void
      solve(const std::vector<const LA::Vector *> &b,
            const std::vector<LA::Vector *>       &x);

      /// The inertia of the last compute().
      const Inertia &
      last() const
      {
        return last_inertia;
      }

      /// MUMPS' fill-reducing ordering, ICNTL(7) (default 2, approximate
      /// minimum fill), for the analyses from the next compute() on.
      void
      set_ordering(const int icntl7);

      /**
       * A fill-reducing pivot order: the position of each unknown in the
       * elimination (1-based, MUMPS' SYM_PERM; on the host, empty
       * elsewhere) and the flops MUMPS' analysis estimated for it on the
       * pattern it was computed for.
       *
       * When the pattern changes but not its size (contact's couplings
       * move from step to step), the next analysis first reuses this order
       * (ICNTL(7) = 1, no ordering run: at the waterbeam's 158k unknowns
       * the analysis takes 0.07 s instead of 0.95 s) and only computes a
       * new one if the reused order's estimated flops exceed the recorded
       * ones by more than 10 %.
       */
      struct PivotOrder
      {
        std::vector<int> position;
        double           flops = 0.;
      };
      const PivotOrder &
      pivot_order() const;
      /// Start from @p order (kept across a new SymmetricInertia; ignored
      /// if its size is not that of the next matrix).
      void
      set_pivot_order(PivotOrder order);

      /// Entries of the factors (INFOG(29)) and floating-point operations
      /// of the last factorization (RINFOG(3)).
      double
      factor_entries() const;
      double
      factorization_flops() const;

      /// Work done so far: analyses (one per sparsity pattern), those that
      /// computed a new pivot order, and the wall seconds of MUMPS' analysis,
      /// numeric factorization and solve phases (JOB = 1, 2, 3) on this rank.
      struct Work
      {
        unsigned int analyses              = 0;
        unsigned int orderings             = 0;
        double       analysis_seconds      = 0.;
        double       factorization_seconds = 0.;
        double       solve_seconds         = 0.;

        Work &
        operator+=(const Work &other)
        {
          analyses += other.analyses;
          orderings += other.orderings;
          analysis_seconds += other.analysis_seconds;
          factorization_seconds += other.factorization_seconds;
          solve_seconds += other.solve_seconds;
          return *this;
        }
      };
      const Work &
      work() const;

    private:
      struct Data;
      std::unique_ptr<Data> data;
      Inertia               last_inertia;
    };
  } // namespace solvers
} // namespace pneuma
