#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <pneuma/solvers/linear_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>

#include <iostream>
#include <sstream>

namespace pneuma
{
  namespace solvers
  {
    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "direct",
                        Patterns::Selection("direct|amg"),
                        "direct: sparse LU (MUMPS or KLU through Trilinos "
                        "Amesos); amg: GMRES preconditioned by Trilinos ML "
                        "algebraic multigrid.");
      prm.declare_entry("Direct solver package",
                        "Amesos_Mumps",
                        Patterns::Selection("Amesos_Mumps|Amesos_Klu"),
                        "Package of the direct solver.");
      prm.declare_entry("MUMPS ordering",
                        "metis",
                        Patterns::Selection("metis|amd|auto"),
                        "Fill-reducing ordering of MUMPS (ICNTL(7)): nested "
                        "dissection (metis) suits surface meshes best.");
      prm.declare_entry("Relative tolerance",
                        "1e-10",
                        Patterns::Double(1e-16, 1.),
                        "GMRES stopping tolerance relative to |b|.");
      prm.declare_entry("Maximum iterations",
                        "2000",
                        Patterns::Integer(1),
                        "GMRES iteration limit.");
      prm.leave_subsection();
    }

    void
    LinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      solver_type        = prm.get("Type");
      direct_package     = prm.get("Direct solver package");
      ordering           = prm.get("MUMPS ordering");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
      prm.leave_subsection();
    }

    LinearSolver::LinearSolver()  = default;
    LinearSolver::~LinearSolver() = default;

    void
    LinearSolver::reset()
    {
      direct.reset();
      problem.reset();
      amg.reset();
      factored_matrix = nullptr;
    }

    void
    LinearSolver::set_constant_modes(
      const std::vector<std::vector<bool>> &modes)
    {
      constant_modes = modes;
    }

    void
    LinearSolver::factorize(const LA::SparseMatrix &A)
    {
      if (solver_type == "direct")
        {
          if (factored_matrix != &A.trilinos_matrix() || !direct)
            {
              problem = std::make_unique<Epetra_LinearProblem>();
              problem->SetOperator(
                const_cast<Epetra_CrsMatrix *>(&A.trilinos_matrix()));
              Amesos factory;
              direct.reset(factory.Create(direct_package.c_str(), *problem));
              AssertThrow(direct != nullptr,
                          ExcMessage("Amesos solver " + direct_package
                                     + " is not available"));
              // Failures are reported by the caller, not printed by Amesos.
              Teuchos::ParameterList amesos_parameters;
              amesos_parameters.set("OutputLevel", 0);
              amesos_parameters.set("PrintStatus", false);
              direct->SetParameters(amesos_parameters);
              if (auto *mumps = dynamic_cast<Amesos_Mumps *>(direct.get()))
                mumps->SetICNTL(7,
                                ordering == "metis" ? 5
                                : ordering == "amd" ? 0
                                                    : 7);
              AssertThrow(direct->SymbolicFactorization() == 0,
                          ExcMessage("symbolic factorization failed"));
              factored_matrix = &A.trilinos_matrix();
            }
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
          return;
        }

      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      data.constant_modes        = constant_modes;
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(A, data);
    }

    unsigned int
    LinearSolver::solve(const LA::SparseMatrix &A,
                        LA::Vector             &x,
                        const LA::Vector       &b)
    {
      if (solver_type == "direct")
        {
          Assert(direct, ExcMessage("factorize() first"));
          problem->SetLHS(&x.trilinos_vector());
          problem->SetRHS(const_cast<Epetra_MultiVector *>(
            static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
          AssertThrow(direct->Solve() == 0, ExcMessage("direct solve failed"));
          return 0;
        }

      Assert(amg, ExcMessage("factorize() first"));
      SolverControl                                 control(max_iterations,
                            relative_tolerance * b.l2_norm(),
                            false,
                            false);
      TrilinosWrappers::SolverGMRES::AdditionalData gmres_data(false, 200);
      TrilinosWrappers::SolverGMRES                 solver(control, gmres_data);
      solver.solve(A, x, b, *amg);
      return control.last_step();
    }
  } // namespace solvers
} // namespace pneuma
