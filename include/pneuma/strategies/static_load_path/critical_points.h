#pragma once

/**
 * @file
 * Critical points of a static load path (doc/theory.md "Stability",
 * "Branch switching"): where the count of negative eigenvalues changes
 * between two converged states, the point is located by bisection (in
 * pseudo time under load control, in the constraint's size on a followed
 * path) and classified; at a bifurcation the path may leave the primary
 * branch along the critical mode.
 */

#include <pneuma/core/linear_algebra.h>
#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/stability.h>

#include <string>

namespace pneuma
{
  namespace solvers
  {
    class PathConstraintProblem;
  }

  namespace strategies
  {
    class Run;

    /// The kind of a critical point.
    enum class CriticalPointType
    {
      bifurcation,
      limit_point
    };

    /// "bifurcation" or "limit point", for messages.
    std::string
    to_string(const CriticalPointType type);

    /**
     * A critical point: a change of the negative-eigenvalue count between
     * two converged states, located by bisection in pseudo time (load
     * control) or in the arc length (path following). Under load control
     * the load grows through it, so it is a bifurcation point (a limit
     * point cannot be passed by load control); on a followed path it is a
     * limit point where the load factor has an extremum there, a
     * bifurcation point where it has not. A limit point found only by the
     * load factor turning back (no stability check) is not located: its
     * bracket is the step.
     */
    struct CriticalPoint
    {
      unsigned int      step    = 0;           ///< the step past it
      double            time    = 0.;          ///< the final bracket's middle
      double            bracket = 0.;          ///< its width
      long long         before = 0, after = 0; ///< the counts on both sides
      unsigned int      probes = 0;            ///< Newton solves to locate it
      CriticalPointType type   = CriticalPointType::bifurcation;
      /// The monitored component (Load stepping/Path following) there; NaN
      /// without a monitor.
      double monitor = 0.;
      /// Branch switching (Stability/Branch switching): the path left the
      /// bifurcation on the secondary branch, at the mode amplitude
      /// @p amplitude (|u - u_primary|) with this count of negative
      /// eigenvalues.
      bool      switched           = false;
      double    amplitude          = 0.;
      long long negative_secondary = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &step &time &bracket &before &after &probes &type &monitor &switched
          &amplitude &negative_secondary;
      }
    };

    /**
     * Locates critical points between two converged states of a run and
     * leaves bifurcations. Each probe is a quiet Newton solve from the
     * last accepted state, judged on its own factorization and rejected
     * (the subsystems' committed state stays that of the accepted state).
     */
    class CriticalPointSearch
    {
    public:
      /// Bisect until the bracket is @p tolerance times the step.
      CriticalPointSearch(Run &run, const double tolerance);

      /// Bisect [t_old, t_new] (load control) for the change of the count
      /// from @p before to @p after; Newton solves from @p last.
      CriticalPoint
      locate(const solvers::BorderedVector &last,
             const double                   t_old,
             const double                   t_new,
             const long long                before,
             const long long                after) const;

      /**
       * Bisect the path-controlled step from the converged @p last
       * (extended) along @p increment (the accepted step, of constraint
       * size @p size: arc length, or the monitor's change) for the change
       * of the count from @p before to @p after; a limit point where the
       * load factor has its extremum in the final bracket. @p w: the
       * monitor functional (empty: none).
       */
      CriticalPoint
      locate_on_path(solvers::PathConstraintProblem &problem,
                     const solvers::BorderedVector  &last,
                     const solvers::BorderedVector  &increment,
                     const double                    size,
                     const LA::Vector               &w,
                     const long long                 before,
                     const long long                 after) const;

      /**
       * Branch switching at a located bifurcation: the converged @p state
       * at pseudo time @p t, just past it on the primary path, is
       * perturbed along the critical mode phi (the eigenvector of the
       * negative eigenvalue nearest zero of the tangent with its chamber
       * terms, solvers/eigen_analysis.h; unit l2 norm) by amplitudes
       * xi = @p amplitude, 3 xi, 9 xi, 27 xi, each solved by Newton at the
       * same load; the first solution with fewer negative eigenvalues is
       * on the secondary branch and replaces @p state (with its report
       * @p stability). Returns whether it did; @p c records it.
       */
      bool
      switch_branch(solvers::BorderedVector  &state,
                    const double              t,
                    const double              amplitude,
                    solvers::StabilityReport &stability,
                    CriticalPoint            &c) const;

    private:
      Run   &run;
      double tolerance;
    };
  } // namespace strategies
} // namespace pneuma
