#include <pneuma/solvers/newton_solver.h>

#include <cmath>
#include <iomanip>

namespace pneuma
{
  namespace solvers
  {
    void
    NewtonSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      prm.declare_entry("Maximum iterations",
                        "25",
                        Patterns::Integer(1, 1000),
                        "Newton iterations per load step before the step "
                        "is cut back.");
      prm.declare_entry("Residual tolerance",
                        "1e-9",
                        Patterns::Double(1e-16, 1.),
                        "Converged when |r| <= tol * max(|r_0|, |f_ext|).");
      prm.declare_entry("Update tolerance",
                        "1e-8",
                        Patterns::Double(1e-16, 1.),
                        "... and |du| <= tol * |u| (or |du| < tol*|du_0|).");
      prm.declare_entry("Line search",
                        "true",
                        Patterns::Bool(),
                        "Backtrack when a full step increases |r|.");
      prm.declare_entry("Maximum line search steps",
                        "6",
                        Patterns::Integer(0, 30),
                        "Halvings of the step length at most.");
      prm.declare_entry("Regularisation factor",
                        "1e-2",
                        Patterns::Double(0.),
                        "First Levenberg-Marquardt shift, relative to "
                        "mean(diag K)/mean(diag L), used when a Newton step "
                        "fails to reduce |r| (0 = never regularise). Changes "
                        "the iteration matrix only, not the equilibrium.");
      prm.declare_entry("Print convergence table",
                        "true",
                        Patterns::Bool(),
                        "Print one line per Newton iteration.");
      prm.leave_subsection();
    }

    void
    NewtonSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      max_iter           = prm.get_integer("Maximum iterations");
      residual_tolerance = prm.get_double("Residual tolerance");
      update_tolerance   = prm.get_double("Update tolerance");
      line_search        = prm.get_bool("Line search");
      max_line_search    = prm.get_integer("Maximum line search steps");
      shift_factor       = prm.get_double("Regularisation factor");
      print_table        = prm.get_bool("Print convergence table");
      prm.leave_subsection();
    }

    NewtonResult
    NewtonSolver::solve(NonlinearProblem &        problem,
                        LA::Vector &              u,
                        const ConditionalOStream &out) const
    {
      NewtonResult result;
      LA::Vector   residual(u), trial_residual(u), du(u), u_trial(u);
      problem.assemble(u, residual);
      double       r_norm = residual.l2_norm();
      const double r_ref  = std::max(r_norm, problem.load_norm());
      // Levenberg-Marquardt shift: zero (pure Newton) until a step fails.
      double       shift       = 0.;
      double       shift_unit  = 0.;
      bool         tangent_at_u = true;

      if (print_table)
        out << "      it  |r|/|r_ref|   |du|/|u|    shift     step\n";

      unsigned int solves = 0;
      result.residual_history.push_back(r_norm);
      while (true)
        {
          if (!std::isfinite(r_norm))
            {
              result.failure_reason = "residual is not finite";
              break;
            }
          if (r_ref == 0. || (solves > 0 && r_norm <= residual_tolerance * r_ref))
            {
              result.converged = true;
              break;
            }
          if (solves >= max_iter)
            {
              result.failure_reason =
                "no convergence in " + std::to_string(max_iter) + " iterations";
              break;
            }
          if (!tangent_at_u)
            {
              problem.assemble(u, residual);
              tangent_at_u = true;
            }
          if (shift_unit == 0.)
            shift_unit = problem.shift_scale();

          du = 0.;
          residual *= -1.;
          bool solved = true;
          try
            {
              problem.solve_linear(shift * shift_unit, residual, du);
            }
          catch (...)
            {
              solved = false;
            }
          residual *= -1.;
          ++solves;
          const double du_norm = du.l2_norm();
          solved               = solved && std::isfinite(du_norm);

          // Pure Newton: the full step, then shorter ones (Armijo).
          // Regularised (pseudo-transient) steps are always taken.
          double alpha      = 1.;
          double trial_norm = std::numeric_limits<double>::infinity();
          bool   accepted   = false;
          const unsigned int n_trials =
            (line_search && shift == 0.) ? max_line_search + 1 : 1;
          for (unsigned int ls = 0; solved && ls < n_trials; ++ls)
            {
              u_trial = u;
              u_trial.add(alpha, du);
              problem.assemble(u_trial, trial_residual);
              trial_norm = trial_residual.l2_norm();
              if (!std::isfinite(trial_norm))
                break;
              if (shift > 0. || !line_search ||
                  trial_norm <= (1. - 1e-4 * alpha) * r_norm ||
                  trial_norm <= residual_tolerance * r_ref)
                {
                  accepted = true;
                  break;
                }
              alpha *= 0.5;
            }

          if (print_table)
            out << "    " << std::setw(4) << solves - 1 << std::scientific
                << std::setprecision(3) << "  " << trial_norm / r_ref << "  "
                << alpha * du_norm / std::max(u_trial.l2_norm(), 1e-300)
                << "  " << shift << "  " << std::defaultfloat
                << std::setprecision(3) << (accepted ? alpha : 0.)
                << std::endl;

          if (accepted)
            {
              // Switched evolution relaxation: the shift follows the
              // residual, and is dropped once it is small.
              if (shift > 0.)
                {
                  shift *= std::min(std::max(trial_norm / r_norm, 0.1), 4.);
                  if (shift < 1e-8 * shift_factor)
                    shift = 0.;
                }
              u        = u_trial;
              residual = trial_residual;
              r_norm   = trial_norm;
              result.residual_history.push_back(r_norm);
              tangent_at_u = true;
            }
          else
            {
              // Regularise: the tangent now sits at the trial point.
              tangent_at_u = false;
              if (shift_factor == 0.)
                {
                  result.failure_reason = solved ? "line search failed" :
                                                   "linear solver failed";
                  break;
                }
              shift = (shift == 0.) ? shift_factor : 4. * shift;
            }
        }
      result.iterations = solves;
      return result;
    }
  } // namespace solvers
} // namespace pneuma
