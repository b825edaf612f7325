#pragma once

/**
 * @file
 * The border of the coupled system: a few global unknowns \f$\lambda\f$
 * (chamber pressures and free-surface levels today; a load factor for
 * path following) that couple to every dof of a large sparse field block
 * (doc/theory.md "The bordered system"):
 * \f[ \begin{pmatrix} K & B\\ C^T & D\end{pmatrix}
 *     \begin{pmatrix}\delta u\\ \delta\lambda\end{pmatrix} =
 *     \begin{pmatrix} r_u\\ r_\lambda\end{pmatrix}. \f]
 * The dense columns B and rows C never enter the sparse matrix. The system
 * is solved by the Schur complement \f$S = D - C^T K^{-1} B\f$ on the
 * border, with one factorization of K and one substitution per coupled
 * unknown; unknowns whose row involves neither u nor another unknown (a
 * prescribed pressure) are eliminated first and cost nothing.
 *
 * Unknowns and residual rows are scaled: the border vector holds
 * \f$\lambda_j / s_j\f$ (unknown_scale) and the residual rows are
 * \f$g_j\,t_j\f$ (residual_scale), so that Newton's norms mix forces and
 * constraints of comparable size. Each subsystem with border unknowns fills
 * its rows (B, C and D in physical units) of one BorderCoupling.
 */

#include <deal.II/lac/full_matrix.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/solvers/bordered_vector.h>

#include <vector>

namespace pneuma
{
  namespace solvers
  {
    class LinearSolver;

    /// The border blocks B, C, D of the last assembly, with the scales.
    struct BorderCoupling
    {
      /// Size the blocks for @p n unknowns (all zero, scales one); the
      /// field vectors get the layout of @p field.
      void
      reinit(const unsigned int n, const LA::Vector &field);

      /// Zero the blocks, keep sizes and scales.
      void
      clear();

      unsigned int
      size() const
      {
        return D.m();
      }

      /// Column j of B = dR/dlambda_j (if has_B[j]) and row j of
      /// C = dg_j/du (if has_C[j]), physical units.
      std::vector<LA::Vector> B, C;
      std::vector<bool>       has_B, has_C;
      /// Unknowns that are coordinates of the potential (a force-driven
      /// obstacle's position: B = C, D its own stiffness), not
      /// multipliers of a constraint or a chamber's pressure: the stability
      /// count takes their Schur complement as it is.
      std::vector<bool> primal;
      /// dg/dlambda, physical units.
      FullMatrix<double>  D;
      std::vector<double> unknown_scale, residual_scale;

      /**
       * Solve the bordered system with the factorized field block: the
       * caller has called solver.factorize(K). @p rhs and @p dx are scaled.
       */
      void
      solve(LinearSolver           &solver,
            const LA::SparseMatrix &K,
            const BorderedVector   &rhs,
            BorderedVector         &dx) const;

      /// y = J x with the bordered Jacobian (scaled vectors).
      void
      vmult(const LA::SparseMatrix &K,
            const BorderedVector   &x,
            BorderedVector         &y) const;
    };
  } // namespace solvers
} // namespace pneuma
