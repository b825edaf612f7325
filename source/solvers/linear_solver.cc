#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_solver.h>

#include <pneuma/core/selection_parameter.h>
#include <pneuma/solvers/linear_solver.h>
#include <pneuma/solvers/stability.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <iostream>
#include <map>
#include <sstream>
#include <utility>

namespace pneuma
{
  namespace solvers
  {
    namespace
    {
      /// The Amesos name of a package.
      const char *
      amesos_name(const DirectPackage package)
      {
        return package == DirectPackage::mumps ? "Amesos_Mumps" : "Amesos_Klu";
      }
    } // namespace

    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      add_selection(prm,
                    "Type",
                    solver_type,
                    {{"direct", LinearSolverType::direct},
                     {"amg", LinearSolverType::amg}},
                    "direct: sparse LDL^T or LU (MUMPS; or KLU through "
                    "Trilinos Amesos); amg: GMRES preconditioned by "
                    "Trilinos ML "
                    "algebraic multigrid. Each type's settings are in "
                    "the subsection of its name.");
      prm.enter_subsection("direct");
      add_selection(prm,
                    "Package",
                    direct_settings.package,
                    {{"Amesos_Mumps", DirectPackage::mumps},
                     {"Amesos_Klu", DirectPackage::klu}},
                    "Package of the direct solver.");
      // MUMPS' ICNTL(7) values.
      add_selection<int>(
        prm,
        "Ordering",
        direct_settings.ordering,
        {{"metis", 5},
         {"amd", 0},
         {"amf", 2},
         {"qamd", 6},
         {"scotch", 3},
         {"pord", 4},
         {"auto", 7}},
        "Fill-reducing ordering of MUMPS (ICNTL(7)). amf (approximate "
        "minimum fill) has the cheapest analysis (benchmarks/"
        "inflated_cylinder/results.md); metis is METIS' nested dissection "
        "of the graph of the nodes, computed by pneuma and given to MUMPS "
        "as its pivot order (Debian's MUMPS has no METIS): at the "
        "waterbeam's 158k unknowns 5.3 instead of 8.4 GFlop per LDL^T "
        "(amf) for about 0.25 s of analysis, worth it where one sparsity "
        "pattern "
        "serves several Newton iterations (parameter_files/"
        "waterbeam_cables.prm). pord, scotch and auto are MUMPS' own "
        "(scotch and auto fall back to MUMPS' automatic choice where it "
        "lacks them).");
      add_selection(
        prm,
        "Factorization",
        direct_settings.factorization,
        {{"automatic", FactorizationChoice::automatic},
         {"LDLT", FactorizationChoice::ldlt},
         {"LU", FactorizationChoice::lu}},
        "MUMPS' factorization. LDLT: the symmetric indefinite LDL^T (half "
        "the factor entries and about 55 % of the work of LU; only the upper "
        "triangle is read, so the tangent must be symmetric); LU: the "
        "general one (friction in "
        "slip, follower pressure on free edges, smoothed contact normals); "
        "automatic: LU where a subsystem's tangent is not symmetric by "
        "construction (a smoothed contact master normal, a slipping "
        "friction point in the assembly), else LDLT for "
        "every tangent whose measured asymmetry is below 1e-10, else LU. "
        "With Package = Amesos_Klu always LU.");
      prm.add_parameter(
        "Distributed factorization",
        direct_settings.distributed,
        "false (default): on several MPI ranks the matrix is gathered to "
        "rank 0, which factorizes and solves it alone with MUMPS, so that "
        "the same input on the same ranks and threads gives the same bits "
        "in every run. true: MUMPS factorizes across all ranks, faster on "
        "many ranks, but its asynchronous scheduling sums contributions "
        "in the order they arrive, and the last digits of the results "
        "vary from run to run. No effect on 1 rank.");
      prm.add_parameter("Reuse factorization",
                        direct_settings.reuse_factorization,
                        "Solve later Newton systems by GMRES preconditioned "
                        "by an earlier factorization, and factorize afresh "
                        "only when that needs more than 'Reuse iterations' "
                        "iterations.");
      prm.add_parameter("Reuse iterations",
                        direct_settings.reuse_iterations,
                        "GMRES iterations allowed on an earlier "
                        "factorization before the tangent is factorized "
                        "again.",
                        Patterns::Integer(1, 100));
      prm.add_parameter("Reuse tolerance",
                        direct_settings.reuse_tolerance,
                        "GMRES stopping tolerance relative to |b| for "
                        "solves on an earlier factorization.",
                        Patterns::Double(1e-16, 1e-2));
      prm.leave_subsection();
      prm.enter_subsection("amg");
      prm.add_parameter("Relative tolerance",
                        amg_settings.relative_tolerance,
                        "GMRES stopping tolerance relative to |b|.",
                        Patterns::Double(1e-16, 1.));
      prm.add_parameter("Maximum iterations",
                        amg_settings.max_iterations,
                        "GMRES iteration limit.",
                        Patterns::Integer(1));
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    LinearSolver::parse_parameters(ParameterHandler &)
    {
      // Every entry is bound by declare_parameters(); the factorization
      // mode also serves the stability count and the eigen analyses.
      SymmetricInertia::set_distributed_factorization(
        direct_settings.distributed);
    }

    LinearSolver::LinearSolver()  = default;
    LinearSolver::~LinearSolver() = default;

    void
    LinearSolver::reset()
    {
      direct.reset();
      problem.reset();
      amg.reset();
      release_symmetric();
      use_symmetric   = false;
      symmetric_ldlt  = true;
      factored_matrix = nullptr;
      stale           = false;
    }

    void
    LinearSolver::release_symmetric()
    {
      if (symmetric)
        {
          released_work += symmetric->work();
          released_order = symmetric->pivot_order();
        }
      symmetric.reset();
    }

    SymmetricInertia::Work
    LinearSolver::symmetric_work() const
    {
      SymmetricInertia::Work w = released_work;
      if (symmetric)
        w += symmetric->work();
      return w;
    }

    bool
    LinearSolver::choose_symmetric(const LA::SparseMatrix &A) const
    {
      if (direct_settings.package != DirectPackage::mumps
          || direct_settings.factorization == FactorizationChoice::lu)
        return false;
      if (direct_settings.factorization == FactorizationChoice::ldlt)
        return true;
      if (!symmetric_possible)
        return false;
      // Two products with A: negligible against a factorization.
      return asymmetry(A, A.locally_owned_range_indices()) < 1e-10;
    }

    void
    LinearSolver::symmetric_factorization(const LA::SparseMatrix &A,
                                          const bool              ldlt)
    {
      if (symmetric && ldlt != symmetric_ldlt)
        release_symmetric();
      symmetric_ldlt = ldlt;
      if (!symmetric)
        {
          symmetric =
            std::make_unique<SymmetricInertia>(A.get_mpi_communicator(),
                                               0.,
                                               ldlt);
          symmetric->set_ordering(direct_settings.ordering);
          symmetric->set_pivot_order(std::move(released_order));
          released_order = SymmetricInertia::PivotOrder();
        }
      try
        {
          symmetric->compute(A);
        }
      catch (const std::runtime_error &)
        {
          release_symmetric();
          use_symmetric = false;
          AssertThrow(false,
                      ExcMessage("numeric factorization failed (singular "
                                 "tangent)"));
        }
      ++factorizations;
      stale         = false;
      use_symmetric = true;
    }

    double
    LinearSolver::factor_entries() const
    {
      if (solver_type != LinearSolverType::direct)
        return 0.;
      if (use_symmetric && symmetric)
        return symmetric->factor_entries();
      if (auto *mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
        return mumps_count(mumps->GetINFOG()[28]);
      return 0.;
    }

    double
    LinearSolver::factorization_flops() const
    {
      if (solver_type != LinearSolverType::direct)
        return 0.;
      if (use_symmetric && symmetric)
        return symmetric->factorization_flops();
      if (auto *mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
        return mumps->GetRINFOG()[2];
      return 0.;
    }

    void
    LinearSolver::set_constant_modes(
      const std::vector<std::vector<bool>> &modes)
    {
      constant_modes = modes;
    }

    void
    LinearSolver::set_rigid_body_modes(
      const std::vector<std::vector<double>> &modes)
    {
      rigid_body_modes = modes;
    }

    void
    LinearSolver::factorize(const LA::SparseMatrix &A)
    {
      if (solver_type == LinearSolverType::direct)
        {
          if (direct_settings.reuse_factorization && factorizations > 0
              && factored_matrix == &A.trilinos_matrix()
              && (use_symmetric ? symmetric != nullptr : direct != nullptr))
            {
              stale = true;
              return;
            }
          if (choose_symmetric(A))
            {
              factored_matrix = &A.trilinos_matrix();
              symmetric_factorization(A, true);
              return;
            }
          // The LU on several ranks: Amesos_Mumps would factorize across
          // them (not reproducible, symmetric_inertia.h); MUMPS' LU on
          // rank 0 through the same interface instead.
          if (direct_settings.package == DirectPackage::mumps
              && !direct_settings.distributed
              && dealii::Utilities::MPI::n_mpi_processes(
                   A.get_mpi_communicator())
                   > 1)
            {
              factored_matrix = &A.trilinos_matrix();
              symmetric_factorization(A, false);
              return;
            }
          use_symmetric = false;
          if (factored_matrix != &A.trilinos_matrix() || !direct)
            {
              problem = std::make_unique<Epetra_LinearProblem>();
              problem->SetOperator(
                const_cast<Epetra_CrsMatrix *>(&A.trilinos_matrix()));
              Amesos factory;
              direct.reset(
                factory.Create(amesos_name(direct_settings.package), *problem));
              AssertThrow(direct != nullptr,
                          ExcMessage(std::string("Amesos solver ")
                                     + amesos_name(direct_settings.package)
                                     + " is not available"));
              // Failures are reported by the caller, not printed by Amesos.
              Teuchos::ParameterList amesos_parameters;
              amesos_parameters.set("OutputLevel", 0);
              amesos_parameters.set("PrintStatus", false);
              direct->SetParameters(amesos_parameters);
              if (auto *mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
                mumps->SetICNTL(7, direct_settings.ordering);
              AssertThrow(direct->SymbolicFactorization() == 0,
                          ExcMessage("symbolic factorization failed"));
              factored_matrix = &A.trilinos_matrix();
              numeric_factorization();
              return;
            }
          // The factors of an earlier tangent serve solve() until GMRES on
          // them needs too many iterations.
          if (direct_settings.reuse_factorization && factorizations > 0)
            {
              stale = true;
              return;
            }
          numeric_factorization();
          return;
        }

      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      data.constant_modes        = constant_modes;
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      if (rigid_body_modes.empty())
        {
          amg->initialize(A, data);
          return;
        }
      // Rigid-body near-null space: ML aggregates with all six modes of a
      // free membrane (translations alone leave the rotations, which a
      // membrane resists no better, to the smoother).
      Teuchos::ParameterList              list;
      std::unique_ptr<Epetra_MultiVector> unused;
      data.set_parameters(list, unused, A);
      const std::size_t n = rigid_body_modes.front().size();
      null_space.resize(n * rigid_body_modes.size());
      for (std::size_t m = 0; m < rigid_body_modes.size(); ++m)
        std::copy(rigid_body_modes[m].begin(),
                  rigid_body_modes[m].end(),
                  null_space.begin() + m * n);
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", int(rigid_body_modes.size()));
      list.set("null space: vectors", null_space.data());
      amg->initialize(A, list);
    }

    void
    LinearSolver::numeric_factorization()
    {
      // Amesos prints MUMPS failures on std::cerr itself; the caller
      // reports them (and recovers), so they are kept off the streams.
      std::ostringstream sink;
      auto *const        err_buf = std::cerr.rdbuf(sink.rdbuf());
      const int          status  = direct->NumericFactorization();
      std::cerr.rdbuf(err_buf);
      if (status != 0)
        {
          // MUMPS is left in an error state: start afresh next time.
          reset();
          AssertThrow(false,
                      ExcMessage("numeric factorization failed (singular "
                                 "tangent)"));
        }
      ++factorizations;
      stale = false;
    }

    void
    LinearSolver::direct_solve(LA::Vector &x, const LA::Vector &b)
    {
      if (use_symmetric)
        {
          symmetric->solve(b, x);
          return;
        }
      problem->SetLHS(&x.trilinos_vector());
      problem->SetRHS(const_cast<Epetra_MultiVector *>(
        static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
      AssertThrow(direct->Solve() == 0, ExcMessage("direct solve failed"));
    }

    unsigned int
    LinearSolver::solve(const LA::SparseMatrix                &A,
                        const std::vector<LA::Vector *>       &x,
                        const std::vector<const LA::Vector *> &b)
    {
      AssertDimension(x.size(), b.size());
      if (solver_type == LinearSolverType::direct && !stale && use_symmetric
          && symmetric)
        {
          symmetric->solve(b, x);
          return 0;
        }
      unsigned int iterations = 0;
      for (unsigned int j = 0; j < x.size(); ++j)
        iterations += solve(A, *x[j], *b[j]);
      return iterations;
    }

    unsigned int
    LinearSolver::solve(const LA::SparseMatrix &A,
                        LA::Vector             &x,
                        const LA::Vector       &b)
    {
      if (solver_type == LinearSolverType::direct)
        {
          Assert(direct, ExcMessage("factorize() first"));
          if (stale)
            {
              // GMRES on the current tangent, preconditioned by the
              // factors of an earlier one.
              struct EarlierFactors
              {
                LinearSolver *solver;
                void
                vmult(LA::Vector &dst, const LA::Vector &src) const
                {
                  solver->direct_solve(dst, src);
                }
              } preconditioner{this};
              SolverControl           control(direct_settings.reuse_iterations,
                                    std::max(direct_settings.reuse_tolerance,
                                             forcing)
                                      * b.l2_norm(),
                                    false,
                                    false);
              SolverGMRES<LA::Vector> gmres(
                control,
                SolverGMRES<LA::Vector>::AdditionalData(
                  direct_settings.reuse_iterations + 2, true));
              x = 0.;
              try
                {
                  gmres.solve(A, x, b, preconditioner);
                  krylov_iterations += control.last_step();
                  return control.last_step();
                }
              catch (const SolverControl::NoConvergence &)
                {
                  // The tangent has moved too far: factorize it (LDL^T
                  // or LU, as the earlier factors were).
                  if (use_symmetric)
                    symmetric_factorization(A, symmetric_ldlt);
                  else
                    numeric_factorization();
                }
            }
          direct_solve(x, b);
          return 0;
        }

      Assert(amg, ExcMessage("factorize() first"));
      SolverControl control(amg_settings.max_iterations,
                            std::max(amg_settings.relative_tolerance, forcing)
                              * b.l2_norm(),
                            false,
                            false);
      TrilinosWrappers::SolverGMRES::AdditionalData gmres_data(false, 200);
      TrilinosWrappers::SolverGMRES                 solver(control, gmres_data);
      solver.solve(A, x, b, *amg);
      krylov_iterations += control.last_step();
      return control.last_step();
    }
  } // namespace solvers
} // namespace pneuma
