#pragma once

/**
 * @file
 * Eigen analysis of a converged state (doc/theory.md "Eigen analysis"):
 * the lowest eigenvalues (around a shift) and their modes, by ARPACK's
 * implicitly restarted Lanczos method (deal.II's PArpackSolver, distributed
 * vectors) on MUMPS' LDL^T factorization of the shifted tangent.
 *
 * The tangent is the bordered one of the state, with its chamber unknowns
 * condensed in energy form (solvers/stability.h): a gas adds its
 * stiffness -B (A D)^{-1} B^T, a volume or liquid constraint (A D = 0)
 * restricts the modes to B^T phi = 0. Three problems:
 * - **tangent**: K_c phi = lambda phi on the free dofs (prescribed and
 *   dependent dofs carry no metric): the stiffness spectrum of the state,
 *   negative eigenvalues for unstable directions;
 * - **modal**: K_c phi = omega^2 M phi with the consistent mass of the
 *   membrane (density x thickness) and of the cables (density x area) about
 *   the prestressed state; frequencies f = omega / (2 pi);
 * - **buckling**: linear buckling of the state, (K_c + lambda K') phi = 0,
 *   with K' = dK_c/dt the change of the tangent along the linear response
 *   to the loads' rate at the state (the perturbation load of Abaqus'
 *   *BUCKLE): K' by a difference of two tangents at u and u - h du/dt.
 *   The critical pseudo time is t + lambda (loads extrapolated linearly).
 *
 * Shift-and-invert (ARPACK mode 3, tangent and modal): the operator
 * (K_c - sigma B)^{-1} B is applied by one MUMPS substitution and the
 * m x m chamber Schur complement; Sylvester's law on the same
 * factorization counts the n_below eigenvalues below sigma. Those are the
 * most negative values of 1/(lambda - sigma) and are found first (ARPACK
 * "SA" for n_below pairs), the rest as the largest positive ones ("LA"):
 * with sigma = 0, the lowest eigenvalues of an unstable state include its
 * negative ones however large they are. Buckling uses mode 2 (operator
 * K_c^{-1} (-K'), K_c-inner product), which needs a stable state.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/solvers/bordered_vector.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace solvers
  {
    /// The eigenproblem (see the file's description).
    enum class EigenProblem
    {
      none,
      tangent,
      modal,
      buckling
    };

    /// How the eigenproblem is solved.
    enum class EigenSolver
    {
      /// Lanczos on LDL^T where the tangent is symmetric, else Arnoldi.
      automatic,
      symmetric,
      non_symmetric
    };

    /// What to compute (strategies/eigen_analysis reads it from "Eigen
    /// analysis").
    struct EigenParameters
    {
      EigenProblem type    = EigenProblem::none;
      unsigned int n_modes = 6;
      /// Tangent: eigenvalue shift [N/m]; modal: frequency shift [Hz].
      double       shift          = 0.;
      double       tolerance      = 1e-10;
      unsigned int max_iterations = 300;
      EigenSolver  solver         = EigenSolver::automatic;
    };

    /// The outcome of one eigen analysis.
    struct EigenResult
    {
      bool         computed = false;
      EigenProblem type     = EigenProblem::none;
      /// Ascending: lambda (tangent), omega^2 (modal), the buckling
      /// factor lambda (buckling: the load change per unit pseudo time
      /// that buckles, negative for reversed loads).
      std::vector<double> values;
      /// The modes (owned vectors, largest component +1).
      std::vector<LA::Vector> modes;
      /// Modal: the effective mass of each mode along x, y, z,
      /// (phi^T M r)^2 / (phi^T M phi) with r the rigid translation [kg],
      /// and the model's mass r^T M r.
      std::vector<std::array<double, 3>> effective_mass;
      double                             total_mass = 0.;
      /// Solved as a non-symmetric problem (Arnoldi on an LU
      /// factorization; no count below the shift), and the largest
      /// |Im lambda| / |lambda| of its values (0 for real ones).
      bool   non_symmetric = false;
      double imaginary     = 0.;
      /// |y.Kx - x.Ky| / (|Kx| |y|) of the tangent (solvers/stability.h).
      double asymmetry = 0.;
      /// Eigenvalues of the pencil below the shift (Sylvester; -1: not
      /// known), and the pseudo time of the state.
      long long below_shift = -1;
      double    time        = 0.;
      /// ARPACK's restarts, and the largest relative residual
      /// |A phi - lambda B phi| / (|A phi| + |lambda B phi|) of the modes.
      unsigned int iterations = 0;
      double       residual   = 0.;
      /// Substitutions with the factorization (ARPACK's operator
      /// applications and the residual check), the wall time of the
      /// factorization (with the chamber Schur complement) and of the
      /// whole analysis [s].
      unsigned int substitutions         = 0;
      double       factorization_seconds = 0.;
      double       seconds               = 0.;
      /// Why it was not computed (empty: it was).
      std::string error;
      /// It was not computed because the shifted tangent is singular (an
      /// eigenvalue at the shift, or a free rigid motion).
      bool singular = false;
    };

    /// Runs the eigen analysis of a converged state.
    class EigenAnalysis
    {
    public:
      /**
       * The analysis @p p of @p state at pseudo time @p t (converged
       * there). Failures (a singular shifted tangent, no
       * convergence, an unstable state for buckling) are returned in
       * EigenResult::error, never thrown. With @p assembled the model's
       * tangent and border are already those of @p state (the stability
       * check's), and are not assembled again.
       */
      static EigenResult
      run(Model                 &model,
          const BorderedVector  &state,
          const double           t,
          const EigenParameters &p,
          const bool             assembled = false);

      /// The frequency [Hz] of omega^2 = @p omega_squared: omega/(2 pi),
      /// negative (-sqrt(-omega^2)/(2 pi)) for an unstable mode.
      static double
      frequency(const double omega_squared)
      {
        return (omega_squared < 0. ? -1. : 1.)
               * std::sqrt(std::abs(omega_squared)) / (2. * M_PI);
      }

      /// After the model's setup: InputError naming "Eigen analysis/Number
      /// of modes" if the problem has too few free unknowns for
      /// @p n_modes.
      static void
      check_size(const Model &model, const unsigned int n_modes);
    };
  } // namespace solvers
} // namespace pneuma
