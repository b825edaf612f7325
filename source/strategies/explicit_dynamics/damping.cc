/**
 * @file
 * The damping of explicit dynamics at the lowest natural frequency
 * (strategies/explicit_dynamics/explicit_dynamics.h, doc/theory.md
 * "Explicit dynamics"): where the input gives a Damping ratio but no
 * Damping frequency, the frequency is that of the lowest mode of the state
 * each explicit stage starts from, by the modal analysis of
 * solvers/eigen_analysis.h (the tangent with the chamber terms, the
 * consistent mass).
 */

#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/strategies/explicit_dynamics/explicit_dynamics.h>
#include <pneuma/strategies/run.h>

#include <cmath>
#include <string>

namespace pneuma
{
  namespace strategies
  {
    void
    ExplicitDynamics::damp_lowest_mode(Run                           &run,
                                       const solvers::BorderedVector &x,
                                       const double                   t)
    {
      solvers::EigenParameters p;
      p.type    = solvers::EigenProblem::modal;
      p.n_modes = 1;
      const solvers::EigenResult modes =
        solvers::EigenAnalysis::run(run.model, x, t, p);
      const std::string entry = "Explicit dynamics/Damping frequency";
      const std::string where = "0 takes the Damping ratio's frequency "
                                "from the lowest mode of the state at t = "
                                + as_text(t) + ", but ";
      // The shift is 0 here: a singular tangent has no stiffness against
      // some motion.
      const bool singular = modes.singular;
      check_input(modes.error.empty(),
                  entry,
                  where
                    + (singular
                         ? "the tangent there is singular (no "
                           "stiffness against some motion, as in a "
                           "flaccid or free-floating start)"
                         : "its modal analysis failed (" + modes.error + ")")
                    + "; give the frequency");
      const double omega_squared = modes.values.at(0);
      check_input(omega_squared > 0.,
                  entry,
                  where
                    + "the lowest mode has omega^2 = " + as_text(omega_squared)
                    + " rad^2/s^2 (no stiffness there, as in a flaccid or "
                      "free-floating start, or an unstable state); give "
                      "the frequency");
      damping_frequency = solvers::EigenAnalysis::frequency(omega_squared);
      alpha = 4. * M_PI * settings.damping_ratio * damping_frequency;
      run.out << "  damping: ratio " << settings.damping_ratio
              << " at the lowest natural frequency " << damping_frequency
              << " Hz (modal analysis at t = " << t << "), alpha = " << alpha
              << " 1/s" << std::endl;
    }
  } // namespace strategies
} // namespace pneuma
