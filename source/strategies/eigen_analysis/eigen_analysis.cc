#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/strategies/eigen_analysis/eigen_analysis.h>
#include <pneuma/strategies/run.h>

#include <cmath>
#include <iomanip>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::EigenProblem;

    void
    EigenAnalysisStrategy::declare_parameters(ParameterHandler &prm)
    {
      solvers::EigenParameters &p = parameters;
      prm.enter_subsection("Eigen analysis");
      add_selection(
        prm,
        "Type",
        p.type,
        {{"none", EigenProblem::none},
         {"tangent", EigenProblem::tangent},
         {"modal", EigenProblem::modal},
         {"buckling", EigenProblem::buckling}},
        "Eigen analysis of the final converged state: none; tangent (the "
        "lowest eigenvalues of the tangent, chamber terms included: "
        "negative ones are unstable directions); modal (natural "
        "frequencies about the prestressed state, with the membrane's and "
        "cables' mass: Materials/.../Density, Cables/.../Density); buckling "
        "(linear buckling of the state under the rate of the loads that led "
        "to it: critical pseudo time t + lambda).");
      prm.add_parameter("Number of modes",
                        p.n_modes,
                        "Eigenpairs to compute: those below the shift first "
                        "(counted by the factorization), then the nearest "
                        "above it; with Shift = 0, the lowest. Buckling: the "
                        "lowest positive load factors.",
                        Patterns::Integer(1, 200));
      prm.add_parameter(
        "Shift",
        p.shift,
        "Shift-and-invert point: tangent, an eigenvalue [N/m]; modal, a "
        "frequency [Hz] (the modes around it). Must not be an eigenvalue. "
        "Not used by buckling.",
        Patterns::Double());
      prm.add_parameter("Tolerance",
                        p.tolerance,
                        "ARPACK's relative accuracy of the eigenvalues.",
                        Patterns::Double(1e-15, 1e-2));
      prm.add_parameter("Maximum iterations",
                        p.max_iterations,
                        "ARPACK's restarts before the analysis is reported "
                        "not converged.",
                        Patterns::Integer(1, 100000));
      prm.add_parameter(
        "Every step",
        every_step,
        "Also analyse every converged step after the reference state and "
        "write the values to history.csv (mode<k>_eigenvalue, "
        "mode<k>_frequency or mode<k>_critical_time): the lowest "
        "eigenvalues along the path. Costs the analysis per step.");
      add_selection(
        prm,
        "Solver",
        p.solver,
        {{"automatic", solvers::EigenSolver::automatic},
         {"symmetric", solvers::EigenSolver::symmetric},
         {"non-symmetric", solvers::EigenSolver::non_symmetric}},
        "automatic: Lanczos on MUMPS' LDL^T for a symmetric tangent, "
        "Arnoldi on its LU where the tangent is not symmetric (measured, or "
        "declared by friction in slip or a smoothed contact normal); "
        "symmetric or non-symmetric: that one (buckling is symmetric only). "
        "The non-symmetric solve gives the eigenvalues nearest the shift "
        "(real parts; complex pairs reported by their real part) without "
        "Sylvester's count below it.");
      prm.add_parameter("Write modes",
                        write_modes,
                        "Add the mode shapes (largest component 1) as fields "
                        "mode_1, mode_2, ... to the final state's VTU files.");
      prm.leave_subsection();
    }

    void
    EigenAnalysisStrategy::parse_parameters(ParameterHandler &, const Stages &)
    {
      const solvers::EigenParameters &p = parameters;
      check_input(!(p.type == EigenProblem::buckling
                    && p.solver == solvers::EigenSolver::non_symmetric),
                  "Eigen analysis/Solver",
                  "linear buckling needs the symmetric solver (its metric is "
                  "the positive definite tangent)");
      check_input(!(p.type == EigenProblem::modal && p.shift < 0.),
                  "Eigen analysis/Shift",
                  "a modal analysis' shift is a frequency [Hz] and must not "
                  "be negative");
    }

    void
    EigenAnalysisStrategy::check(Model &model) const
    {
      if (enabled())
        solvers::EigenAnalysis::check_size(model, parameters.n_modes);
    }

    Outcome
    EigenAnalysisStrategy::run(Run &run, const Segment &, const Outcome &start)
    {
      Outcome outcome = start;
      result          = solvers::EigenAnalysis::run(run.model,
                                           start.state,
                                           start.time,
                                           parameters);
      print(run.out);
      if (!result.computed)
        {
          outcome.exit_code = 2;
          outcome.message   = "the eigen analysis failed: " + result.error;
        }
      else if (write_modes)
        {
          std::vector<std::string> names;
          for (unsigned int k = 0; k < result.modes.size(); ++k)
            names.push_back("mode_" + std::to_string(k + 1));
          run.model.set_output_modes(names, result.modes);
          outcome.output_changed = true;
        }
      return outcome;
    }

    std::string
    EigenAnalysisStrategy::unit() const
    {
      return parameters.type == EigenProblem::tangent ? " N/m"
             : parameters.type == EigenProblem::modal ? " 1/s^2"
                                                      : " (load factors)";
    }

    void
    EigenAnalysisStrategy::add_history(Statistics                    &row,
                                       const StepReport              &report,
                                       const solvers::BorderedVector &state,
                                       Run                           &run)
    {
      // The lowest eigenvalues along the path (not at the reference state,
      // whose tangent is singular for a stress-free membrane).
      if (!enabled() || !every_step)
        return;
      solvers::EigenResult r;
      if (report.step > 0)
        {
          r = solvers::EigenAnalysis::run(run.model,
                                          state,
                                          report.time,
                                          parameters);
          if (!r.computed)
            run.out << "  eigen analysis: " << r.error << std::endl;
          else
            {
              run.out << "  eigen analysis: lowest";
              for (const double v : r.values)
                run.out << " " << v;
              run.out << unit() << std::endl;
            }
        }
      const EigenProblem type = parameters.type;
      for (unsigned int k = 0; k < parameters.n_modes; ++k)
        {
          const double v = k < r.values.size() ? r.values[k] : std::nan("");
          const StatisticsGroup g{"mode", "", "", k + 1};
          if (type == EigenProblem::tangent)
            row.add(g, "eigenvalue", "N/m", v, Statistics::history);
          else if (type == EigenProblem::modal)
            row.add(g,
                    "frequency",
                    "Hz",
                    solvers::EigenAnalysis::frequency(v),
                    Statistics::history);
          else
            row.add(
              g, "critical_time", "", report.time + v, Statistics::history);
        }
    }

    void
    EigenAnalysisStrategy::print(const ConditionalOStream &out) const
    {
      const solvers::EigenResult &r    = result;
      const EigenProblem          type = parameters.type;
      const std::string name = type == EigenProblem::tangent ? "tangent"
                               : type == EigenProblem::modal ? "modal"
                                                             : "buckling";
      if (!r.computed)
        {
          out << "eigen analysis (" << name << "): " << r.error << std::endl;
          return;
        }
      out << "eigen analysis (" << name << ") at t = " << r.time << ": "
          << r.values.size() << " modes in " << r.iterations
          << " ARPACK restarts, largest relative residual " << std::scientific
          << std::setprecision(2) << r.residual;
      if (r.non_symmetric)
        out << "; non-symmetric tangent: Arnoldi on its LU, the "
               "eigenvalues nearest the shift (largest |Im|/|lambda| "
            << r.imaginary << ")";
      else if (type != EigenProblem::buckling)
        out << ", " << r.below_shift << " eigenvalue(s) below the shift";
      out << std::endl;
      for (unsigned int k = 0; k < r.values.size(); ++k)
        {
          out << "  mode " << std::setw(3) << k + 1 << ": " << std::setw(14)
              << std::setprecision(6) << r.values[k];
          if (type == EigenProblem::tangent)
            out << " N/m";
          else if (type == EigenProblem::modal)
            out << " 1/s^2, f = " << std::setw(13)
                << solvers::EigenAnalysis::frequency(r.values[k]) << " Hz";
          else
            out << ", critical t = " << std::setw(13) << r.time + r.values[k];
          out << std::endl;
        }
      out << std::defaultfloat;
    }

    void
    EigenAnalysisStrategy::add_summary(Statistics &row) const
    {
      if (!result.computed)
        return;
      const auto                  run    = StatisticsGroup::run();
      constexpr unsigned int      counts = Statistics::summary;
      const solvers::EigenResult &r      = result;
      row.add_count(run,
                    "eigen_below_shift",
                    r.below_shift >= 0 ? r.below_shift : std::nan(""),
                    counts);
      row.add_count(run, "eigen_non_symmetric", r.non_symmetric, counts);
      row.add(run, "eigen_asymmetry", "", r.asymmetry, counts);
      row.add_count(run, "eigen_iterations", r.iterations, counts);
      row.add(run, "eigen_residual", "", r.residual, counts);
      row.add_count(run, "eigen_substitutions", r.substitutions, counts);
      row.add(run,
              "eigen_factorization_seconds",
              "s",
              r.factorization_seconds,
              counts);
      row.add(run, "eigen_seconds", "s", r.seconds, counts);
      const EigenProblem type = parameters.type;
      if (type == EigenProblem::modal)
        row.add(run, "modal_mass", "kg", r.total_mass, counts);
      for (unsigned int k = 0; k < r.values.size(); ++k)
        {
          const double          v = r.values[k];
          const StatisticsGroup g{"mode", "eigen_modes", "mode", k + 1};
          if (type == EigenProblem::tangent)
            row.add(g, "eigenvalue", "N/m", v, counts);
          else if (type == EigenProblem::modal)
            {
              row.add(g, "omega_squared", "1/s^2", v, counts);
              row.add(g,
                      "frequency",
                      "Hz",
                      solvers::EigenAnalysis::frequency(v),
                      counts);
              const auto &e = r.effective_mass[k];
              row.add(g, "effective_mass_x", "kg", e[0], counts);
              row.add(g, "effective_mass_y", "kg", e[1], counts);
              row.add(g, "effective_mass_z", "kg", e[2], counts);
            }
          else
            {
              row.add(g, "load_factor", "", v, counts);
              row.add(g, "critical_time", "", r.time + v, counts);
            }
        }
    }

    PNEUMA_REGISTER_STRATEGY(EigenAnalysisStrategy,
                             "eigen analysis",
                             Placement::after_stages,
                             "the lowest eigenvalues, natural frequencies or "
                             "buckling loads of the final state");
  } // namespace strategies
} // namespace pneuma
