#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/stability_monitor.h>

#include <cmath>
#include <sstream>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    void
    StabilityMonitor::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Stability");
      prm.add_parameter(
        "Check inertia",
        check,
        "Count the negative eigenvalues of the tangent at every converged "
        "step, chamber terms included (MUMPS LDL^T of the field block and "
        "the chamber Schur complement). With Newton's LDL^T factorization "
        "the count is that of its last iterate (no extra cost; a changed "
        "count is confirmed on the state's own factorization); with an LU, "
        "one extra symmetric factorization per step. An unstable state gets "
        "a warning.");
      prm.add_parameter(
        "Locate critical points",
        tolerance,
        "Where the count changes between two converged steps (a bifurcation "
        "under load control), bisect in pseudo time until the bracket is this "
        "fraction of the step (each probe is a Newton solve from the earlier "
        "state); 0: do not locate.",
        Patterns::Double(0., 1.));
      prm.add_parameter(
        "Branch switching",
        switching,
        "At the first located bifurcation point, leave the primary path for "
        "the secondary branch: the state just past the point is perturbed "
        "along the critical mode (the eigenvector of the negative eigenvalue "
        "nearest zero) by the last step's displacement norm, then 3, 9 and 27 "
        "times it, each solved at the same load, until a state with fewer "
        "negative eigenvalues is found; the path goes on from there.");
      prm.leave_subsection();
    }

    void
    StabilityMonitor::parse_parameters(ParameterHandler &)
    {
      check_input(!switching || (check && tolerance > 0.),
                  "Stability/Branch switching",
                  "needs the located bifurcation: Stability/Check inertia = "
                  "true and Stability/Locate critical points > 0");
    }

    solvers::StabilityReport
    StabilityMonitor::judge(Model                         &model,
                            const solvers::BorderedVector &state,
                            const double                   t,
                            const bool                     exact)
    {
      if (!stability)
        stability =
          std::make_unique<solvers::StabilityCheck>(model.mpi_communicator());
      try
        {
          return stability->check(model, state, t, exact);
        }
      catch (const std::exception &e)
        {
          solvers::StabilityReport r;
          r.note = std::string("not computed: ") + e.what();
          return r;
        }
    }

    void
    StabilityMonitor::add_history(Statistics               &row,
                                  const StepReport         &step,
                                  const ConditionalOStream &out)
    {
      // The converged states after the reference state (whose tangent
      // is singular for a stress-free membrane).
      const double                    nan = std::nan("");
      const solvers::StabilityReport &r   = step.stability;
      if (step.step > 0)
        {
          if (r.energy_form)
            last = r;
          if (!r.computed)
            {
              // Explicit dynamics' rows are not equilibria: no note.
              if (!r.note.empty())
                out << "  stability: " << r.note << std::endl;
            }
          else if (!r.energy_form)
            out << "  stability: under prescribed pressures "
                << r.negative_field << " negative eigenvalue(s); " << r.note
                << std::endl;
          else
            out << "  stability: " << r.negative
                << " negative eigenvalue(s); under prescribed pressures "
                << r.negative_field
                << (r.note.empty() ? "" : " (" + r.note + ")") << std::endl;
          if (r.computed && r.energy_form && r.negative > 0)
            {
              if (unstable_steps == 0)
                first_unstable = step.time;
              ++unstable_steps;
              out << "pneuma: warning: the converged state at t = " << step.time
                  << " is unstable (" << r.negative
                  << " negative eigenvalue(s) of the tangent)" << std::endl;
            }
        }
      const auto run = StatisticsGroup::run();
      row.add_count(run,
                    "negative_eigenvalues",
                    r.computed && r.energy_form ? r.negative : nan,
                    Statistics::history);
      row.add_count(run,
                    "negative_eigenvalues_prescribed_pressure",
                    r.computed ? r.negative_field : nan,
                    Statistics::history);
      row.add_count(run,
                    "zero_pivots",
                    r.computed ? r.zero : nan,
                    Statistics::history);
    }

    void
    StabilityMonitor::add_summary(Statistics &row) const
    {
      const auto             run    = StatisticsGroup::run();
      constexpr unsigned int counts = Statistics::summary;
      row.add_count(run, "unstable_steps", unstable_steps, counts);
      row.add(run, "first_unstable_time", "", first_unstable, counts);
      row.add_count(run,
                    "negative_eigenvalues",
                    last.computed ? last.negative : std::nan(""),
                    counts);
    }

    std::string
    StabilityMonitor::warning() const
    {
      if (unstable_steps == 0)
        return "";
      std::ostringstream m;
      m << "warning: " << unstable_steps
        << " converged state(s) are unstable, the first at t = "
        << first_unstable
        << " (negative eigenvalues of the tangent; history.csv "
           "column negative_eigenvalues)";
      return m.str();
    }

    void
    StabilityMonitor::save_checkpoint(Checkpoint &cp) const
    {
      cp.put("run/stability",
             std::vector<double>{static_cast<double>(unstable_steps),
                                 first_unstable,
                                 last.computed ? 1. : 0.,
                                 static_cast<double>(last.negative)});
    }

    void
    StabilityMonitor::load_checkpoint(const Checkpoint &cp)
    {
      const auto s   = cp.get<std::vector<double>>("run/stability");
      unstable_steps = static_cast<unsigned int>(s[0]);
      first_unstable = s[1];
      last.computed  = s[2] != 0.;
      last.negative  = static_cast<long long>(s[3]);
    }
  } // namespace strategies
} // namespace pneuma
