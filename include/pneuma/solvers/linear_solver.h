#pragma once

/**
 * @file
 * The linear solver of each Newton step: a parallel direct solver (MUMPS
 * through Trilinos Amesos, the default) or AMG-preconditioned GMRES
 * (Trilinos ML) for large meshes (doc/theory.md "Linear solver").
 * "Linear solver/Type" selects it; each type's entries are in the
 * subsection of its name, "Linear solver/direct/..." and
 * "Linear solver/amg/...".
 *
 * The direct solver factorizes a symmetric tangent (no friction in slip,
 * no follower pressure on free edges) by MUMPS' LDL^T (SYM = 2, called
 * directly: solvers/symmetric_inertia.h), half the work and memory of the
 * LU that Amesos_Mumps always does; "direct/Factorization = automatic"
 * measures the asymmetry of each tangent and picks the factorization.
 *
 * The direct solver can reuse a factorization across Newton iterations
 * (off by default): near convergence the tangent barely changes, and a few
 * GMRES iterations preconditioned by the factors of an earlier tangent
 * solve the current system to the Newton forcing term. On membrane meshes
 * a numeric factorization costs only about six substitutions, so this does
 * not pay there (doc/theory.md §6); it may for stiffer, denser systems.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/statistics.h>
#include <pneuma/solvers/symmetric_inertia.h>

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    /// Entry "Linear solver/Type".
    enum class LinearSolverType
    {
      /// Sparse LDL^T or LU (MUMPS, or KLU).
      direct,
      /// GMRES with Trilinos ML algebraic multigrid.
      amg
    };

    /// Entry "Linear solver/direct/Package".
    enum class DirectPackage
    {
      /// Amesos_Mumps.
      mumps,
      /// Amesos_Klu.
      klu
    };

    /// Entry "Linear solver/direct/Factorization".
    enum class FactorizationChoice
    {
      /// LU where a tangent is not symmetric, else LDL^T.
      automatic,
      ldlt,
      lu
    };

    /// "Linear solver" subsection and the solve itself.
    class LinearSolver
    {
    public:
      /// Declare the entries, bound to this object (which must outlive
      /// the parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Near-null space for AMG: one entry per displacement component.
      void
      set_constant_modes(const std::vector<std::vector<bool>> &modes);

      /**
       * Near-null space for AMG as values over the locally owned dofs (in
       * their order): the three translations and three rotations of a
       * membrane. Replaces the constant modes when given.
       */
      void
      set_rigid_body_modes(const std::vector<std::vector<double>> &modes);

      /**
       * Whether the matrices may be symmetric: false (a subsystem's
       * tangent is not symmetric by construction) keeps the direct solver
       * on the LU path unless `Factorization = LDLT` is asked for.
       */
      void
      set_symmetric_possible(const bool possible)
      {
        symmetric_possible = possible;
      }

      LinearSolver();
      ~LinearSolver();

      /// Forget the symbolic factorization (call after the sparsity changes).
      void
      reset();

      /**
       * Factorize @p A (direct: numeric factorization, reusing the symbolic
       * one while the matrix object is the same; amg: build the
       * preconditioner). Every solve() until the next call reuses it, so a
       * bordered system costs one factorization and a few substitutions.
       */
      void
      factorize(const LA::SparseMatrix &A);

      /**
       * Solve A x = b with the factorization of the last factorize(A);
       * returns the number of Krylov iterations (0 for the direct solver).
       * Throws SolverControl::NoConvergence on failure.
       */
      unsigned int
      solve(const LA::SparseMatrix &A, LA::Vector &x, const LA::Vector &b);

      /**
       * The same for several right-hand sides: with the symmetric direct
       * factorization one MUMPS solve for all of them (one pass over the
       * factors), otherwise one solve each. Returns the Krylov iterations.
       */
      unsigned int
      solve(const LA::SparseMatrix                &A,
            const std::vector<LA::Vector *>       &x,
            const std::vector<const LA::Vector *> &b);

      /**
       * Relative tolerance that the next solves on an earlier
       * factorization must reach (an inexact Newton forcing term); never
       * below "direct/Reuse tolerance" or "amg/Relative tolerance".
       */
      void
      set_forcing(const double eta)
      {
        forcing = eta;
      }

      /// Entry "Type".
      LinearSolverType
      type() const
      {
        return solver_type;
      }

      /// Is the last factorize()'s factorization an LDL^T?
      bool
      factorized_ldlt() const
      {
        return solver_type == LinearSolverType::direct && factorizations > 0
               && use_symmetric && symmetric_ldlt;
      }

      /// The name of the last factorize()'s factorization for logs:
      /// "LDLT", "LU" or "" (none yet, or AMG).
      std::string
      factorization() const
      {
        if (solver_type != LinearSolverType::direct || factorizations == 0)
          return "";
        return factorized_ldlt() ? "LDLT" : "LU";
      }

      /// The inertia of the current factorization if it is an LDL^T of
      /// the last factorized matrix (not stale); false otherwise.
      bool
      inertia(Inertia &result) const
      {
        if (solver_type != LinearSolverType::direct || !use_symmetric
            || !symmetric_ldlt || !symmetric || stale)
          return false;
        result = symmetric->last();
        return true;
      }

      /// Entries of the factors and floating-point operations of the last
      /// MUMPS factorization (INFOG(29), RINFOG(3); 0 for KLU and AMG).
      double
      factor_entries() const;
      double
      factorization_flops() const;

      /// The work of the symmetric (LDL^T) factorizations so far:
      /// analyses and the seconds of MUMPS' phases (zero without them).
      SymmetricInertia::Work
      symmetric_work() const;

      /// Numeric factorizations done so far (direct solver).
      unsigned int
      n_factorizations() const
      {
        return factorizations;
      }

      /// GMRES iterations so far (AMG, or solves on an earlier
      /// factorization).
      unsigned int
      n_krylov_iterations() const
      {
        return krylov_iterations;
      }

      /// Continue the counts of a run restarted from a checkpoint.
      void
      set_counts(const unsigned int n_factorizations,
                 const unsigned int n_krylov_iterations)
      {
        factorizations    = n_factorizations;
        krylov_iterations = n_krylov_iterations;
      }

      /// Its counts and, for the direct solver, the last factorization
      /// (kind, size, work) and where the LDL^T's time went, as summary
      /// entries (linear_solver_statistics.cc).
      void
      add_statistics(Statistics &row) const;

    private:
      /// Entry "Type".
      LinearSolverType solver_type = LinearSolverType::direct;
      /// The entries of "Linear solver/direct".
      struct DirectSettings
      {
        /// "Package": the Amesos solver.
        DirectPackage package = DirectPackage::mumps;
        /// "Factorization".
        FactorizationChoice factorization = FactorizationChoice::automatic;
        /// "Ordering": MUMPS's fill-reducing ordering, its ICNTL(7) value
        /// (2: amf).
        int ordering = 2;
        /// "Reuse factorization", "Reuse iterations", "Reuse tolerance":
        /// factorize() keeps the numeric factors of an earlier tangent and
        /// solve() runs GMRES on the current one, preconditioned by them;
        /// when GMRES needs more than reuse_iterations the tangent has
        /// moved too far and is factorized afresh.
        bool reuse_factorization = false;
        /// "Distributed factorization": MUMPS on all ranks (not
        /// reproducible in the last digits) instead of on rank 0
        /// (symmetric_inertia.h).
        bool         distributed      = false;
        unsigned int reuse_iterations = 8;
        double       reuse_tolerance  = 1e-9;
      } direct_settings;
      /// The entries of "Linear solver/amg": GMRES's relative tolerance
      /// and iteration limit.
      struct AmgSettings
      {
        double       relative_tolerance = 1e-10;
        unsigned int max_iterations     = 2000;
      } amg_settings;

      std::vector<std::vector<bool>>   constant_modes;
      std::vector<std::vector<double>> rigid_body_modes;
      /// Contiguous storage of rigid_body_modes handed to ML (it keeps the
      /// pointer while the preconditioner lives).
      std::vector<double> null_space;
      // Direct solver state: the symbolic factorization (fill-reducing
      // ordering) is computed once per matrix and reused by every Newton
      // iteration; only the numeric factorization is redone.
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    direct;
      const void                           *factored_matrix = nullptr;
      /// MUMPS' LDL^T of a symmetric tangent, or on several ranks its LU
      /// on rank 0 (its analysis is kept while the sparsity does not
      /// change).
      std::unique_ptr<SymmetricInertia> symmetric;
      /// @p symmetric holds an LDL^T (not an LU).
      bool symmetric_ldlt = true;
      /// The work of symmetric factorizations released by reset().
      SymmetricInertia::Work released_work;
      /// The pivot order of the released factorization, for the next
      /// (reset() follows a new sparsity pattern, often of the same size).
      SymmetricInertia::PivotOrder released_order;
      void
      release_symmetric();
      /// The active factorization is the one of @p symmetric (its LDL^T,
      /// or the LU on rank 0).
      bool use_symmetric = false;
      /// set_symmetric_possible().
      bool symmetric_possible = true;
      /// The forcing term of set_forcing().
      double forcing = 0.;
      /// True while the factors are those of an earlier tangent (reuse).
      bool         stale             = false;
      unsigned int factorizations    = 0;
      unsigned int krylov_iterations = 0;

      /// Numeric factorization of the matrix bound to the Amesos problem.
      void
      numeric_factorization();
      /// Numeric LDL^T (@p ldlt) or LU factorization of @p A through
      /// SymmetricInertia.
      void
      symmetric_factorization(const LA::SparseMatrix &A, const bool ldlt);
      /// Whether the next factorization of @p A is the LDL^T.
      bool
      choose_symmetric(const LA::SparseMatrix &A) const;
      /// x = (factored matrix)^-1 b.
      void
      direct_solve(LA::Vector &x, const LA::Vector &b);
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    };
  } // namespace solvers
} // namespace pneuma
