#pragma once

/**
 * @file
 * Dynamic relaxation with kinetic damping (Barnes 1988, 1999; Topping &
 * Khan 1994; doc/theory.md "Dynamic relaxation"): a static strategy
 * without linear solves that finds the equilibrium r(u) = 0 of each stage
 * as the rest state of a fictitious, undamped motion
 * \f[ M\,\ddot u = -r(u), \f]
 * integrated by central differences with the time step 1,
 * \f[ v_{n+1/2} = v_{n-1/2} - M^{-1} r(u_n), \qquad
 *     u_{n+1} = u_n + v_{n+1/2}, \f]
 * whose kinetic energy \f$T = \tfrac12 v^T M v\f$ is reset to zero at
 * each of its peaks: there the motion passes the minimum of the potential
 * energy along its path. At a peak (T falls) the state is moved back to
 * the peak, \f$u^* = u_{n+1} - \tfrac32 v_{n+1/2} + \tfrac12 M^{-1}
 * (-r(u_n))\f$, and the motion starts again from rest.
 *
 * The fictitious mass is diagonal and chosen for the fastest stable
 * iteration: by Gershgorin's theorem the largest eigenvalue of
 * \f$M^{-1}K\f$ is at most \f$\max_i \sum_j |K_{ij}| / M_i\f$, and central
 * differences with the step 1 are stable for \f$\lambda_{max} < 4\f$, so
 * \f[ M_i = \tfrac{s}{4} \max_{k \in \mathrm{node}(i)} \sum_j |K_{kj}|,
 * \f]
 * with the safety factor s (Mass safety factor, 2 by default, Barnes'
 * choice) and the row sums of the tangent's field block plus the
 * chambers' border coupling eliminated (a gas chamber's volume stiffness).
 * The largest row sum over the components of a node (Inertia::
 * largest_per_node) gives a flat membrane's normal direction, which
 * has no stiffness there, the mass of its in-plane ones (as in mem4py).
 * The mass follows the tangent: it is computed again at every reset.
 *
 * The border unknowns (chamber pressures and levels) follow the field at
 * every step (Model::border_for). Converged when |r| <= Residual
 * tolerance * |r_ref| with Newton's reference |r_ref| = max(|r_0|, |f|),
 * and the kinetic energy has fallen below Kinetic energy tolerance times
 * its largest peak; then, by default, Newton finishes the stage from the
 * relaxed state (Finish with Newton), so that the reported state is the
 * exact equilibrium of Newton's tolerance.
 *
 * Each stage is relaxed once, at its end time: the loads act at once (a
 * run that needs intermediate states has more stages). A flaccid start
 * (a flat, unstressed airbag) that Newton's continuation cannot inflate
 * is the case it is made for: relax the first stage, then go on with the
 * static strategy (`Load stepping/Strategy = relaxation, static`).
 */

#include <pneuma/core/linear_algebra.h>
#include <pneuma/strategies/solution_strategy.h>

namespace pneuma
{
  namespace strategies
  {
    /// "Dynamic relaxation": a stage strategy.
    class DynamicRelaxation : public SolutionStrategy
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) override;
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const Stages             &stages) override;

      /// The border unknowns of every subsystem must follow the field
      /// (BorderFromField).
      void
      check(Model &model) const override;

      /// Relax the segment's stages in turn from @p start (or from the
      /// reference state, reported as step 0). Stages that end at or
      /// before the start's time (a restart) are skipped.
      Outcome
      run(Run &run, const Segment &segment, const Outcome &start) override;

      /// Iterations, resets and Newton iterations of the relaxations.
      void
      add_summary(Statistics &row) const override;

      /// The counts of the relaxations so far (a restart goes on with
      /// them).
      void
      save_summary(Checkpoint &checkpoint) const override;
      void
      load_summary(const Checkpoint &checkpoint) override;

      /// The settings of one relaxation.
      struct Settings
      {
        unsigned int max_iterations           = 200000;
        double       residual_tolerance       = 1e-4;
        double       kinetic_energy_tolerance = 1e-6;
        double       safety                   = 2.;
        bool         finish_with_newton       = true;
        /// Print a progress row every this many iterations.
        unsigned int print_every = 1000;
      };

      /// How one relaxation ended.
      struct Result
      {
        bool         converged  = false;
        unsigned int iterations = 0, resets = 0;
        /// |r|/|r_ref| at the end, and |r_ref|.
        double      ratio = 0., reference = 0.;
        std::string failure;
      };

    private:
      /// One relaxation of the stage ending at @p t from @p state (which
      /// holds the result); @p tolerance the residual's.
      Result
      relax(Run                     &run,
            solvers::BorderedVector &state,
            const double             t,
            const double             tolerance) const;
      /// Why the relaxation stops at iteration @p it without converging
      /// (a non-finite residual, the iteration limit, a signal), or "".
      std::string
      stop_reason(const Model       &model,
                  const Result      &result,
                  const unsigned int it) const;
      /// The stage ending at @p t: relaxation, then Newton (if asked);
      /// false with @p message if it failed.
      bool
      solve_stage(Run                     &run,
                  solvers::BorderedVector &state,
                  const double             t,
                  StepReport              &report,
                  std::string             &message);
      /// Commit and report the converged @p state of the stage ending at
      /// @p t.
      void
      accept(Run                           &run,
             const solvers::BorderedVector &state,
             const double                   t,
             StepReport                    &report) const;

      Settings settings;
      /// Some stage of the run is relaxed.
      bool         used             = false;
      unsigned int total_iterations = 0, total_resets = 0,
                   newton_iterations = 0;
    };

    /**
     * The fictitious mass of dynamic relaxation at the tangent last
     * assembled by @p model (see the file's description): positive on
     * every free dof.
     */
    LA::Vector
    relaxation_mass(const Model &model, const double safety);
  } // namespace strategies
} // namespace pneuma
