#include <deal.II/base/utilities.h>

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
                        "1e-8",
                        Patterns::Double(1e-16, 1.),
                        "Converged when |r| <= tol * max(|r_0|, |f_ext|).");
      prm.declare_entry("Update tolerance",
                        "1e-8",
                        Patterns::Double(1e-16, 1.),
                        "Also converged when a Newton update has |du| <= "
                        "tol |u| while |r| is within 1e4 of the residual "
                        "tolerance (the round-off floor of stiff parts).");
      prm.declare_entry("Line search",
                        "true",
                        Patterns::Bool(),
                        "Backtrack when a full step increases |r|.");
      prm.declare_entry("Maximum line search steps",
                        "6",
                        Patterns::Integer(0, 30),
                        "Halvings of the step length at most.");
      prm.declare_entry("Watchdog steps",
                        "3",
                        Patterns::Integer(0, 20),
                        "A full Newton step that raises |r| is still taken, "
                        "and the iteration goes on for up to this many "
                        "steps; if |r| has not dropped below its value "
                        "before, that state is restored and the line "
                        "search backtracks from it (0: backtrack at once).");
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
      watchdog_steps     = prm.get_integer("Watchdog steps");
      shift_factor       = prm.get_double("Regularisation factor");
      print_table        = prm.get_bool("Print convergence table");
      prm.leave_subsection();
    }

    bool
    NewtonSolver::iterate(NonlinearProblem         &problem,
                          BorderedVector           &u,
                          const double              shift,
                          const BorderedVector     &u_anchor,
                          const unsigned int        max_iterations,
                          const double              tolerance,
                          const double              r_ref,
                          const ConditionalOStream &out,
                          NewtonResult             &result) const
    {
      BorderedVector residual(u), trial(u), du(u), u_trial(u), Lx(u);
      // r_s(u) = r(u) + s L (u - u_anchor): the regularised residual.
      const auto evaluate = [&](const BorderedVector &x, BorderedVector &r) {
        problem.assemble(x, r);
        if (shift > 0.)
          {
            du = x;
            du -= u_anchor;
            problem.laplacian_vmult(du, Lx);
            r.add(shift, Lx);
          }
        return r.l2_norm();
      };
      // Watchdog (non-monotone acceptance, after Chamberlain et al.): a
      // full step that raises |r| is taken anyway from a saved state; if
      // |r| has not dropped below the saved value within `watchdog_steps`
      // further iterations, the saved state is restored and the line
      // search backtracks from it. A linearised rotation stretches the
      // section of a solid beam by the square of the angle, and its stiff
      // section modes then raise |r| by orders of magnitude although the
      // step is good: the next iteration restores the section.
      BorderedVector saved_u(u);
      double         saved_norm   = 0.;
      unsigned int   watch_left   = 0; // > 0: a watch is on
      bool           watch_barred = false;

      double r_norm = evaluate(u, residual);
      for (unsigned int it = 0;; ++it)
        {
          if (!std::isfinite(r_norm))
            {
              result.failure_reason = "residual is not finite";
              return false;
            }
          if (r_norm <= tolerance * r_ref && (it > 0 || shift > 0.))
            return true;
          if (it >= max_iterations)
            {
              result.failure_reason = "no convergence in "
                                      + std::to_string(max_iterations)
                                      + " iterations";
              return false;
            }
          du = 0.;
          residual *= -1.;
          try
            {
              // Forcing term 1e-2 |r|/|r_ref|: the linear error stays
              // below the quadratic term of the Newton step.
              problem.set_linear_tolerance(
                std::min(1e-3, 1e-2 * r_norm / r_ref));
              problem.solve_linear(shift, residual, du);
            }
          catch (const std::exception &e)
            {
              result.failure_reason = "linear solver failed";
              if (print_table)
                out << "    (linear solver: "
                    << Utilities::trim(std::string(e.what()).substr(
                         0, std::string(e.what()).find('\n', 1) + 200))
                    << ")\n";
              return false;
            }
          ++result.iterations;
          const double du_norm = du.l2_norm();
          if (!std::isfinite(du_norm))
            {
              result.failure_reason = "linear solver failed";
              return false;
            }
          // Round-off floor: the residual cannot drop further (e.g. stiff
          // plates beside a soft membrane) but the update has vanished.
          if (shift == 0. && du_norm <= update_tolerance * u.l2_norm()
              && r_norm <= 1e4 * tolerance * r_ref)
            return true;
          const BorderedVector step(du);
          double     alpha      = 1.;
          double     trial_norm = 0.;
          bool       accepted   = false;
          bool       watched    = false;
          for (unsigned int ls = 0; ls <= (line_search ? max_line_search : 0);
               ++ls, alpha *= 0.5)
            {
              u_trial = u;
              u_trial.add(alpha, step);
              trial_norm = evaluate(u_trial, trial);
              if (!line_search
                  || (std::isfinite(trial_norm)
                      && (trial_norm <= (1. - 1e-4 * alpha) * r_norm
                          || trial_norm <= tolerance * r_ref)))
                {
                  accepted = true;
                  break;
                }
              // A full step that raises |r|: start a watch, or go on with
              // the one that is on.
              if (ls == 0 && line_search && watchdog_steps > 0 && !watch_barred
                  && std::isfinite(trial_norm))
                {
                  if (watch_left == 0)
                    {
                      saved_u    = u;
                      saved_norm = r_norm;
                      watch_left = watchdog_steps + 1;
                    }
                  accepted = true;
                  watched  = true;
                  break;
                }
            }
          if (print_table)
            out << "    " << std::setw(4) << result.iterations
                << std::scientific << std::setprecision(3) << "  "
                << trial_norm / r_ref << "  "
                << alpha * du_norm / std::max(u_trial.l2_norm(), 1e-300) << "  "
                << shift << "  " << std::defaultfloat << std::setprecision(3)
                << (accepted ? alpha : 0.) << (watched ? " (watchdog)" : "")
                << std::endl;
          if (!accepted)
            {
              // No descent at the round-off floor of stiff parts (e.g. a
              // penalty next to a prestressed cable): converged if |r| is
              // already within a factor 100 of the tolerance.
              if (shift == 0. && r_norm <= 1e2 * tolerance * r_ref)
                return true;
              result.failure_reason = "line search failed";
              return false;
            }
          u        = u_trial;
          residual = trial;
          r_norm   = trial_norm;
          if (watch_left > 0)
            {
              if (r_norm <= (1. - 1e-4) * saved_norm)
                watch_left = 0; // progress: the watch ends
              else if (--watch_left == 0)
                {
                  // No progress: back to the saved state; backtrack there.
                  u            = saved_u;
                  r_norm       = evaluate(u, residual);
                  watch_barred = true;
                  if (print_table)
                    out << "    (watchdog: back to |r|/|r_ref| = "
                        << std::scientific << std::setprecision(3)
                        << r_norm / r_ref << std::defaultfloat << ")\n";
                  continue;
                }
            }
          else
            watch_barred = false;
          if (shift == 0.)
            result.residual_history.push_back(r_norm);
        }
    }

    NewtonResult
    NewtonSolver::solve(NonlinearProblem         &problem,
                        BorderedVector           &u,
                        const ConditionalOStream &out,
                        const bool                allow_continuation) const
    {
      NewtonResult result;
      BorderedVector r(u);
      problem.assemble(u, r);
      const double r0    = r.l2_norm();
      const double r_ref = std::max(r0, problem.load_norm());
      result.residual_history.push_back(r0);
      if (r_ref == 0.)
        {
          result.converged = true;
          return result;
        }
      if (print_table)
        out << "      it  |r|/|r_ref|   |du|/|u|    shift     step\n";

      // 1. Pure Newton with backtracking.
      const BorderedVector u_start(u);
      if (iterate(problem,
                  u,
                  0.,
                  u,
                  max_iter,
                  residual_tolerance,
                  r_ref,
                  out,
                  result))
        {
          result.converged = true;
          return result;
        }
      if (shift_factor == 0. || !allow_continuation
          || result.iterations >= max_iter)
        return result;

      // 2. Continuation in pseudo time: implicit steps of the Laplacian
      //    flow r(u) + s L (u - u_prev) = 0, with s shrinking to zero.
      if (print_table)
        out << "    (" << result.failure_reason
            << ": continuing with the regularised iteration)\n";
      u = u_start;
      result.residual_history.assign(1, r0);
      problem.assemble(u, r); // the scale is taken from K at the start
      const double unit  = problem.shift_scale();
      double       shift = shift_factor * unit;
      unsigned int   failures = 0;
      BorderedVector u_prev(u);
      while (result.iterations < 4 * max_iter)
        {
          u_prev = u;
          if (!iterate(problem, u, shift, u_prev, 6, 1e-3, r_ref, out, result))
            {
              u = u_prev;
              shift *= 3.;
              // A failure that costs no iteration (the linear solver)
              // must not loop for ever.
              if (++failures > 20)
                break;
              continue;
            }
          problem.assemble(u, r);
          if (r.l2_norm() <= 1e-2 * r_ref || shift < 1e-6 * shift_factor * unit)
            break;
          shift *= 0.5;
        }

      // 3. Pure Newton to full accuracy from there.
      result.residual_history.assign(1, r.l2_norm());
      result.failure_reason.clear();
      result.converged = iterate(
        problem, u, 0., u, max_iter, residual_tolerance, r_ref, out, result);
      return result;
    }
  } // namespace solvers
} // namespace pneuma
