#include <pneuma/core/model.h>
#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/solvers/newton_solver.h>
#include <pneuma/solvers/path_following.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/stability_monitor.h>
#include <pneuma/strategies/static_load_path/critical_points.h>
#include <pneuma/strategies/static_load_path/path_control.h>

#include <algorithm>
#include <iostream>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;
    using solvers::PathConstraintProblem;

    std::string
    to_string(const CriticalPointType type)
    {
      return type == CriticalPointType::bifurcation ? "bifurcation"
                                                    : "limit point";
    }

    CriticalPointSearch::CriticalPointSearch(Run &run, const double tolerance)
      : run(run)
      , tolerance(tolerance)
    {
    }

    CriticalPoint
    CriticalPointSearch::locate(const BorderedVector &last,
                                const double          t_old,
                                const double          t_new,
                                const long long       before,
                                const long long       after) const
    {
      // Each probe solves from the last accepted state (its subsystems'
      // committed state is intact: the new step is not yet committed) to
      // the middle of the bracket, judges it and is rejected.
      Model                   &model = run.model;
      const ConditionalOStream quiet(std::cout, false);
      CriticalPoint            c;
      c.before  = before;
      c.after   = after;
      double lo = t_old, hi = t_new;
      while (hi - lo > tolerance * (t_new - t_old) && c.probes < 40)
        {
          const double mid = 0.5 * (lo + hi);
          model.reject_step(t_old);
          BorderedVector    probe(last);
          const std::string impossible = model.begin_step(mid, probe);
          ++c.probes;
          if (!impossible.empty())
            break;
          const auto newton = run.newton.solve(model, probe, quiet, false);
          if (!newton.converged || !model.check_state(probe).empty())
            break;
          const auto r = run.stability->judge(model, probe, model.time(), true);
          if (!r.computed)
            break;
          (r.negative == before ? lo : hi) = mid;
        }
      model.reject_step(t_old);
      c.time    = 0.5 * (lo + hi);
      c.bracket = hi - lo;
      return c;
    }

    bool
    CriticalPointSearch::switch_branch(BorderedVector           &state,
                                       const double              t,
                                       const double              amplitude,
                                       solvers::StabilityReport &stability,
                                       CriticalPoint            &c) const
    {
      // The critical mode: the negative eigenvalue nearest zero (the one
      // that just crossed it).
      Model                    &model = run.model;
      const ConditionalOStream &out   = run.out;
      solvers::EigenParameters  p;
      p.type       = solvers::EigenProblem::tangent;
      p.n_modes    = 1;
      const auto e = solvers::EigenAnalysis::run(model, state, t, p);
      if (!e.computed || e.values.empty() || e.values[0] >= 0.)
        {
          out << "  branch switching: no critical mode ("
              << (e.computed ? "no negative eigenvalue" : e.error)
              << "); the path stays on the primary branch" << std::endl;
          return false;
        }
      LA::Vector phi(e.modes[0]);
      model.constraints().distribute(phi);
      phi /= phi.l2_norm();
      const ConditionalOStream quiet(std::cout, false);
      double                   xi = amplitude > 0. ? amplitude : 1e-3;
      for (unsigned int attempt = 0; attempt < 4; ++attempt, xi *= 3.)
        {
          BorderedVector probe(state);
          probe.field.add(xi, phi);
          const auto newton = run.newton.solve(model, probe, quiet, false);
          if (!newton.converged || !model.check_state(probe).empty())
            continue;
          const auto r = run.stability->judge(model, probe, model.time(), true);
          if (!r.computed || r.negative < 0 || r.negative >= stability.negative)
            continue;
          LA::Vector away(probe.field);
          away -= state.field;
          c.switched           = true;
          c.amplitude          = away.l2_norm();
          c.negative_secondary = r.negative;
          out << "  branch switching: along the critical mode (eigenvalue "
              << e.values[0] << " N/m), perturbation " << xi
              << ": on the secondary branch at |u - u_primary| = "
              << c.amplitude << ", negative eigenvalues " << stability.negative
              << " -> " << r.negative << std::endl;
          state     = probe;
          stability = r;
          return true;
        }
      out << "  branch switching: no perturbation up to " << xi / 3.
          << " along the critical mode left the primary branch; the path "
             "stays on it"
          << std::endl;
      return false;
    }

    CriticalPoint
    CriticalPointSearch::locate_on_path(PathConstraintProblem &problem,
                                        const BorderedVector  &last,
                                        const BorderedVector  &increment,
                                        const double           size,
                                        const LA::Vector      &w,
                                        const long long        before,
                                        const long long        after) const
    {
      // Probes solve the constraint of a smaller size from the last
      // accepted state, predicted along the accepted increment; each is
      // judged and rejected.
      Model                   &model = run.model;
      const ConditionalOStream quiet(std::cout, false);
      const double             t_old = PathConstraintProblem::load_factor(last);
      const auto               monitor = [&](const BorderedVector &x) {
        return monitor_value(w, x.field);
      };
      struct Probe
      {
        double r, tau, m;
      };
      BorderedVector end(last);
      end.add(1., increment);
      std::vector<Probe> probes = {{0., t_old, monitor(last)},
                                   {size,
                                    PathConstraintProblem::load_factor(end),
                                    monitor(end)}};
      CriticalPoint      c;
      c.before  = before;
      c.after   = after;
      double lo = 0., hi = size;
      while (std::abs(hi - lo) > tolerance * std::abs(size) && c.probes < 40)
        {
          const double mid = 0.5 * (lo + hi);
          model.reject_step(t_old);
          BorderedVector x(last);
          x.add(mid / size, increment);
          BorderedVector    state      = PathConstraintProblem::model_part(x);
          const double      tau        = PathConstraintProblem::load_factor(x);
          const std::string impossible = model.begin_step(tau, state);
          ++c.probes;
          if (!impossible.empty())
            break;
          x = PathConstraintProblem::extend(state, tau);
          problem.set_size(mid);
          const auto newton = run.newton.solve(problem, x, quiet, false);
          const BorderedVector probe = PathConstraintProblem::model_part(x);
          if (!newton.converged || !model.check_state(probe).empty())
            break;
          const auto r = run.stability->judge(model, probe, model.time(), true);
          if (!r.computed)
            break;
          probes.push_back(
            {mid, PathConstraintProblem::load_factor(x), monitor(x)});
          (r.negative == before ? lo : hi) = mid;
        }
      problem.set_size(size);
      model.reject_step(t_old);
      std::sort(probes.begin(), probes.end(), [](const auto &a, const auto &b) {
        return a.r < b.r;
      });
      // The bracket [lo, hi] and its neighbours: the load factor rises
      // towards the bracket on one side and falls away on the other at a
      // limit point.
      unsigned int i_lo = 0, i_hi = probes.size() - 1;
      for (unsigned int i = 0; i < probes.size(); ++i)
        {
          if (probes[i].r == lo)
            i_lo = i;
          if (probes[i].r == hi)
            i_hi = i;
        }
      const Probe &a = probes[i_lo], &b = probes[i_hi];
      c.time    = 0.5 * (a.tau + b.tau);
      c.monitor = 0.5 * (a.m + b.m);
      c.bracket = std::abs(b.tau - a.tau);
      if (i_lo > 0 && i_hi + 1 < probes.size())
        {
          const double left  = probes[i_lo].tau - probes[i_lo - 1].tau;
          const double right = probes[i_hi + 1].tau - probes[i_hi].tau;
          c.type = left * right < 0. ? CriticalPointType::limit_point
                                     : CriticalPointType::bifurcation;
        }
      return c;
    }
  } // namespace strategies
} // namespace pneuma
