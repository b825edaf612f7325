#pragma once

/**
 * @file
 * The stability of a converged state (doc/theory.md "Stability"): the
 * number of negative eigenvalues of the tangent of the total potential,
 * with the chamber terms.
 *
 * The field block K (membrane, cables, contact; with follower-pressure
 * stiffness) is factorized by LDL^T (solvers/symmetric_inertia.h): its
 * inertia is that of the same state under prescribed pressures and
 * volumes. The coupled chamber unknowns lambda (gas pressure, liquid
 * level) enter by columns B = dr/dlambda and rows C = dg/du. In the
 * energy form the columns lie in the span of the rows, B = C^T X for an
 * m x m matrix X (X = diag(alpha_j) when each row is its own column, as
 * for a gas, B_j = -C_j^T, or a liquid level, B_j = -rho g C_j^T). The
 * rows X^T [C D] are then an equivalent linearization of the chamber
 * equations and
 * \f[ M = \begin{pmatrix} K & B \\ B^T & X^T D \end{pmatrix} \f]
 * is symmetric. For a gas of stiffness kappa = -dp/dV (amount control)
 * X^T D = -1/kappa, for a liquid level -rho g A_fs, for a volume
 * constraint 0. Liquid and gas in one chamber couple the two: the gas row
 * is C_p = kappa (q - q_l) with D_ph = -kappa A_fs (its volume is the
 * chamber's less the liquid's), the level row C_h = q_l, and
 * X = [[-1/kappa, 0], [-1, -rho g]] gives X^T D = diag(-1/kappa,
 * -rho g A_fs). Eliminating lambda (X^T D < 0) or restricting to the
 * constraint (X^T D = 0) leaves one negative eigenvalue of M per chamber
 * unknown, so by Haynsworth's inertia additivity
 * \f[ n_-(\text{state}) = n_-(K) + n_-(S) - m,\qquad
 *     S = X^T D - B^T K^{-1} B, \f]
 * with m the coupled chamber unknowns (a prescribed pressure is not
 * coupled and drops out). S is m x m and costs m substitutions.
 *
 * MUMPS reads the upper triangle of K. With friction in slip, or a follower
 * pressure on an open surface with free edges, K is not symmetric and
 * Sylvester's law does not apply: the count is then that of the negative
 * real parts among the 6 eigenvalues nearest zero of the non-symmetric
 * tangent (Arnoldi on its LU, solvers/eigen_analysis.h; an eigenvalue far
 * from zero with a negative real part would be missed), and the report
 * says so (asymmetry, relative).
 */

#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/symmetric_inertia.h>

#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace solvers
  {
    struct BorderCoupling;

    /// The stability of one converged state.
    struct StabilityReport
    {
      bool computed = false;
      /// Negative eigenvalues of the state (chamber terms included).
      long long negative = 0;
      /// Of K alone: the state under prescribed pressures and volumes.
      long long negative_field = 0;
      /// Zero pivots of K (a singular tangent: the counts are not exact).
      long long zero = 0;
      /// The chamber terms are of energy form, so that @p negative is the
      /// count of the state (false: only negative_field is known).
      bool energy_form = true;
      /// |y.Kx - x.Ky| / (|Kx| |y|) for two fixed vectors.
      double asymmetry = 0.;
      /// The counts came from Newton's last LDL^T factorization (no extra
      /// factorization).
      bool from_newton = false;
      /// Why the count is not exact (empty: it is).
      std::string note;
    };

    /**
     * The coupled chamber unknowns of @p c in energy form: the kept
     * unknowns j (a column B_j and a row C_j), X with B = C^T X (least
     * squares over the kept rows) and A D = X^T D (see above);
     * energy_form is false if B is not in the span of the rows, X^T D is
     * not symmetric or -X^T D has a negative eigenvalue.
     */
    struct EnergyBorder
    {
      std::vector<unsigned int>  kept;
      dealii::FullMatrix<double> X;
      dealii::FullMatrix<double> AD;
      bool                       energy_form = true;
      /// Kept unknowns that are not primal (each adds one negative
      /// direction to the bordered matrix).
      unsigned int n_dual = 0;
      unsigned int
      size() const
      {
        return kept.size();
      }
    };
    EnergyBorder
    energy_border(const BorderCoupling &c);

    /// |y.Kx - x.Ky| / (|Kx| |y|) for two fixed vectors (0: symmetric).
    double
    asymmetry(const LA::SparseMatrix &K, const dealii::IndexSet &owned);

    /// Number of negative eigenvalues of the symmetric part of @p S
    /// (entries below 1e-8 of the largest count as zero).
    long long
    negative_eigenvalues(const dealii::FullMatrix<double> &S);

    /// Computes StabilityReport for converged states of a model.
    class StabilityCheck
    {
    public:
      explicit StabilityCheck(const MPI_Comm comm);

      /// Count at @p state at pseudo time @p t (assembled there unless the
      /// model's tangent is of that state). Newton's last LDL^T
      /// factorization counts if it is close enough (doc/theory.md section
      /// 11), unless @p exact.
      StabilityReport
      check(Model                &model,
            const BorderedVector &state,
            const double          t,
            const bool            exact = false);

    private:
      SymmetricInertia inertia;
    };
  } // namespace solvers
} // namespace pneuma
