#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <pneuma/solvers/linear_solver.h>

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
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
      prm.leave_subsection();
    }

    void
    LinearSolver::set_constant_modes(
      const std::vector<std::vector<bool>> &modes)
    {
      constant_modes = modes;
    }

    unsigned int
    LinearSolver::solve(const LA::SparseMatrix &A,
                        LA::Vector &            x,
                        const LA::Vector &      b)
    {
      if (solver_type == "direct")
        {
          SolverControl                    control(1, 0);
          TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                              direct_package);
          TrilinosWrappers::SolverDirect   solver(control, data);
          solver.solve(A, x, b);
          return 0;
        }

      TrilinosWrappers::PreconditionAMG                 amg;
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      data.constant_modes        = constant_modes;
      amg.initialize(A, data);

      SolverControl control(max_iterations,
                            relative_tolerance * b.l2_norm(),
                            false,
                            false);
      TrilinosWrappers::SolverGMRES::AdditionalData gmres_data(false, 200);
      TrilinosWrappers::SolverGMRES solver(control, gmres_data);
      solver.solve(A, x, b, amg);
      return control.last_step();
    }
  } // namespace solvers
} // namespace pneuma
