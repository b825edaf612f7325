#pragma once

/**
 * @file
 * Explicit dynamics by central differences (doc/theory.md "Explicit
 * dynamics"; Belytschko, Liu & Moran, Nonlinear Finite Elements, 2014,
 * section 6.2): a stage strategy that follows the motion of the model in
 * real time t,
 * \f[ M \ddot u + \alpha M \dot u + r(u, t) = 0, \qquad
 *     r = f_{int}(u) - f_{ext}(u, t), \f]
 * with the lumped (row-sum, diagonal) mass of every subsystem with
 * Inertia and mass-proportional damping \f$\alpha = 2 \zeta \omega\f$ (the
 * damping ratio \f$\zeta\f$ at the angular frequency \f$\omega = 2\pi
 * f\f$ the user names, or else the lowest natural frequency of the
 * state each stage starts from: damping.cc). With \f$\Delta t_n = (\Delta
 * t_{n-1/2} + \Delta t_{n+1/2})/2\f$: \f[ v_{n+1/2} = \frac{(1 - \alpha\Delta
 * t_n/2)\, v_{n-1/2} - \Delta t_n M^{-1} r(u_n, t_n)}{1 + \alpha \Delta t_n /
 * 2}, \qquad u_{n+1} = u_n + \Delta t_{n+1/2}\, v_{n+1/2}. \f] Prescribed
 * values (supports, rigid plates, cable ends) follow t (Model::begin_step() at
 * every step), dependent dofs their masters; the chamber pressures and levels
 * follow the field at every step (Model::border_for(): a gas by its exact law
 * from the current volume).
 *
 * The stable step of central differences is \f$\Delta t \le 2 /
 * \omega_{max}\f$; \f$\omega_{max}^2 = \lambda_{max}(M^{-1}K)\f$ is bounded
 * by Gershgorin's theorem, \f$\lambda_{max} \le \max_i \sum_j |K_{ij}| /
 * M_i\f$ (strategies/gershgorin.h: the border's volume stiffness
 * included), an upper bound, so the estimate is on the safe side. It is
 * estimated at the start and every Estimate interval steps from the
 * tangent there, times the Time step safety factor.
 *
 * Energies (per history row): kinetic \f$T = \tfrac12 v_n^T M v_n\f$ at
 * the step, \f$v_n = v_{n-1/2} - \tfrac12 \Delta t M^{-1} r_n\f$, the work of
 * the residual forces \f$W = \sum (u_{n+1} - u_n)^T (r_n + r_{n+1})/2\f$
 * (internal energy, gas and penalty energy minus external work, by the
 * trapezoidal rule), the energy the damping took, \f$D = \sum \alpha \Delta t_n
 * v^T M v\f$, and the balance error \f$|T + W + D - T_0|\f$ relative to the
 * largest of T, |W| and D so far.
 */

#include <deal.II/base/types.h>

#include <array>
#include <cmath>
#include <utility>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/strategies/border_projection.h>
#include <pneuma/strategies/solution_strategy.h>

namespace pneuma
{
  namespace strategies
  {
    /// "Explicit dynamics": a stage strategy.
    class ExplicitDynamics : public SolutionStrategy
    {
    public:
      void
      declare_parameters(dealii::ParameterHandler &prm) override;
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const Stages             &stages) override;
      /// Every free unknown has a mass; the border unknowns follow the
      /// field (BorderFromField).
      void
      check(Model &model) const override;
      /// Integrate the segment's stages in turn from @p start (or from the
      /// reference state at rest, reported as step 0).
      Outcome
      run(Run &run, const Segment &segment, const Outcome &start) override;
      /// Energies and time step of the reported state.
      void
      add_history(Statistics                    &row,
                  const StepReport              &report,
                  const solvers::BorderedVector &state,
                  Run                           &run) override;
      void
      add_summary(Statistics &row) const override;
      /// The motion (velocity, step, energies) for a restart.
      void
      save_checkpoint(
        Checkpoint                                   &checkpoint,
        std::vector<const solvers::BorderedVector *> &vectors) const override;
      void
      load_checkpoint(const Checkpoint                     &checkpoint,
                      std::vector<solvers::BorderedVector> &vectors) override;
      void
      save_summary(Checkpoint &checkpoint) const override;
      void
      load_summary(const Checkpoint &checkpoint) override;

      struct Settings
      {
        /// 0: the stable step estimate times the safety factor.
        double time_step = 0., safety = 0.9;
        /// Mass scaling's target step (0: off).
        double       mass_scaling_step = 0.;
        unsigned int estimate_every    = 100;
        double       damping_ratio = 0., damping_frequency = 0.;
        /// 0: a row at each stage's end only.
        double       output_interval = 0.;
        unsigned int max_steps = 10000000, print_every = 1000;
      };

      /// The motion between reports: velocity v_{n-1/2} (field and an
      /// empty border), the last step, the energies.
      struct Motion
      {
        solvers::BorderedVector velocity;
        /// The last step's increment u_{n+1} - u_n (field only).
        solvers::BorderedVector increment;
        double previous_step = 0., stable_step = 0., kinetic = 0., work = 0.,
               damping = 0., start_energy = 0.;
        /// The largest of T, |W| and D so far (the balance error's scale).
        double scale = 0.;
        /// The largest relative error of the border constraints since the
        /// last report.
        double constraint_error = 0.;
        /// The mass scaling's added mass over the physical mass (at the
        /// last estimate).
        double       added_mass = 0.;
        unsigned int steps = 0, estimates = 0;
        /// The step of the last stable-step estimate (none: invalid).
        unsigned int estimated_at = dealii::numbers::invalid_unsigned_int;

        /// |T + W + D - T_0| relative to the largest energy so far.
        double
        balance_error() const
        {
          return scale > 0.
                   ? std::abs(kinetic + work + damping - start_energy) / scale
                   : 0.;
        }

        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &previous_step &stable_step &kinetic &work &damping &start_energy &
            scale &constraint_error &added_mass &steps &estimates &estimated_at;
        }
      };

    private:
      /// Integrate from @p t to @p t_end (at most): the state @p x and the
      /// motion move on; returns "" or why it failed.
      std::string
      integrate(Run                     &run,
                solvers::BorderedVector &x,
                double                  &t,
                const double             t_end);
      /// The stable step at @p x, t from the tangent there (the residual
      /// there into residual).
      double
      estimate_step(Model                         &model,
                    const solvers::BorderedVector &x,
                    const double                   t);
      /// The projection's changes into the step of length @p dt: the
      /// velocity, the increment, the residual @p r of u_n and the work.
      void
      hold_constraints(const Model &model, LA::Vector &r, const double dt);
      /// The damping (alpha) at the lowest natural frequency of @p x at
      /// @p t (a modal analysis, printed); InputError naming the Damping
      /// frequency where there is none.
      void
      damp_lowest_mode(Run                           &run,
                       const solvers::BorderedVector &x,
                       const double                   t);
      /// inverse_mass from the diagonal mass @p m (zero where m is).
      void
      set_inverse_mass(const LA::Vector &m);
      /// Mass scaling: every node whose Gershgorin row bounds @p g give a
      /// stable step below the target gets the mass (the same in its three
      /// directions) that reaches it.
      void
      scale_mass(const Model &model, const LA::Vector &g);
      /// The resultants of the inertial forces -M a and of the damping
      /// forces -alpha M v at the reported state along x, y, z: with the
      /// supports' reactions and the applied loads they sum to zero (the
      /// internal forces do).
      std::pair<std::array<double, 3>, std::array<double, 3>>
      resultant_forces(const Model &model) const;
      /// The progress row at @p t with the step @p dt.
      void
      print_progress(Run &run, const double t, const double dt) const;
      /// Begin the stage ending at @p t_end from @p x at @p t: estimate the
      /// stable step (not when @p resuming a checkpoint's stage: its
      /// estimate goes on), refuse it (InputError) if it needs more than
      /// Maximum steps; "" or why it cannot begin.
      std::string
      begin_stage(Run                     &run,
                  solvers::BorderedVector &x,
                  const double             t,
                  const double             t_end,
                  const unsigned int       stage,
                  const bool               resuming);
      /// Commit and report the state @p x at @p t.
      void
      accept(Run &run, const solvers::BorderedVector &x, const double t);

      Settings settings;
      double   alpha = 0.; ///< mass damping [1/s]
      /// The frequency alpha holds the Damping ratio at [Hz].
      double damping_frequency = 0.;
      bool   used = false, resumed = false;
      Motion motion;
      /// The physical lumped mass (zero on constrained dofs) and the
      /// inverse of the one in use (scaled, if mass scaling is on).
      LA::Vector mass, inverse_mass;
      /// The inverse mass for a checkpoint (scratch).
      mutable solvers::BorderedVector checkpoint_mass;
      /// r(u_n, t_n) of the state the motion is at.
      solvers::BorderedVector residual;
      /// The increment of the step before the last (scratch).
      LA::Vector previous_increment;
      /// What the last projection of the border constraints changed.
      BorderProjection projection;
      unsigned int steps_at_report = 0, total_steps = 0, total_estimates = 0;
      double       smallest_step = 0., largest_added = 0.;
      /// The running stage: its end, and the wall time and steps at its
      /// start (the progress rows' rate).
      double       stage_end = 0., stage_start_wall = 0.;
      unsigned int stage_start_steps = 0;
    };

    /// A number in a message, to 6 significant digits.
    std::string
    as_text(const double x);

    /**
     * Gershgorin's bound 2 / sqrt(max_i g_i / M_i) on the stable
     * central-difference step, from the row sums g_i = sum_j |K_ij| of the
     * last assembled tangent (stiffness_row_sums()) and the diagonal mass
     * @p inverse_mass (inverted; zero on constrained dofs). Infinite where
     * nothing is stiff.
     */
    double
    stable_time_step(const LA::Vector &g, const LA::Vector &inverse_mass);
  } // namespace strategies
} // namespace pneuma
