/**
 * @file
 * The central-difference steps of explicit dynamics (strategies/
 * explicit_dynamics/explicit_dynamics.h): the update, the energies, the
 * stable step.
 */

#include <pneuma/core/capabilities.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/border.h>
#include <pneuma/strategies/border_projection.h>
#include <pneuma/strategies/explicit_dynamics/explicit_dynamics.h>
#include <pneuma/strategies/gershgorin.h>
#include <pneuma/strategies/run.h>
#include <pneuma/strategies/stages.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;


    double
    stable_time_step(const LA::Vector &g, const LA::Vector &inverse_mass)
    {
      double largest = 0.;
      for (const auto row : g.locally_owned_elements())
        largest = std::max(largest, g[row] * inverse_mass[row]);
      largest = Utilities::MPI::max(largest, g.get_mpi_communicator());
      return largest > 0. ? 2. / std::sqrt(largest)
                          : std::numeric_limits<double>::infinity();
    }

    void
    ExplicitDynamics::set_inverse_mass(const LA::Vector &m)
    {
      inverse_mass = m;
      for (auto &mi : inverse_mass)
        mi = mi > 0. ? 1. / mi : 0.;
    }

    void
    ExplicitDynamics::scale_mass(const Model &model, const LA::Vector &g)
    {
      // Row i is stable for dt <= 2 sqrt(m_i/g_i): the step s dt_i reaches
      // the target with m_i = g_i (target/(2 s))^2.
      // A node's mass is the same in its three directions (the largest
      // need of its components), so the scaled mass stays isotropic.
      const double c =
        std::pow(settings.mass_scaling_step / (2. * settings.safety), 2);
      LA::Vector needed = g;
      needed *= c;
      for (const auto *i : model.with<Inertia>())
        i->largest_per_node(needed);
      LA::Vector m     = mass;
      double     added = 0., total = 0.;
      for (const auto row : m.locally_owned_elements())
        if (mass[row] > 0.)
          {
            total += mass[row];
            if (needed[row] > mass[row])
              {
                added += needed[row] - mass[row];
                m[row] = needed[row];
              }
          }
      m.compress(VectorOperation::insert);
      const MPI_Comm comm = m.get_mpi_communicator();
      motion.added_mass   = Utilities::MPI::sum(added, comm)
                          / std::max(Utilities::MPI::sum(total, comm), 1e-300);
      largest_added = std::max(largest_added, motion.added_mass);
      set_inverse_mass(m);
    }

    double
    ExplicitDynamics::estimate_step(Model                &model,
                                    const BorderedVector &x,
                                    const double          t)
    {
      residual = x;
      model.assemble(x, t, residual);
      ++motion.estimates;
      motion.estimated_at = motion.steps;
      ++total_estimates;
      const LA::Vector g = stiffness_row_sums(model);
      if (settings.mass_scaling_step > 0.)
        scale_mass(model, g);
      return stable_time_step(g, inverse_mass);
    }

    namespace
    {
      /**
       * The step's global sums in one reduction: v^T M v (the damping's
       * power), v_{n+1}^T M v_{n+1} with v_{n+1} = v_{n+1/2} - dt/2 M^-1
       * r_{n+1} (twice the kinetic energy at the step, where W is; the
       * damping's half step left out), |r_{n+1}|^2 (to see that the
       * motion is finite) and the trapezoidal work of the step,
       * (u_{n+1} - u_n)^T (r_n + r_{n+1})/2, from the increment @p dx and
       * @p r_old = r_n. Unknowns without a mass (zero inverse mass) count
       * in |r|^2 and the work only. One reduction per step instead of
       * five (they are a step's collectives besides the assembly's).
       */
      std::array<double, 4>
      step_sums(const LA::Vector &v,
                const LA::Vector &dx,
                const LA::Vector &r_old,
                const LA::Vector &r,
                const LA::Vector &inverse_mass,
                const double      dt)
      {
        std::array<double, 4> local{{0., 0., 0., 0.}}, sums;
        const auto            n  = v.locally_owned_size();
        const double         *mi = inverse_mass.begin(), *ri = r.begin(),
                     *ro = r_old.begin(), *vi = v.begin(), *di = dx.begin();
        for (std::size_t i = 0; i < n; ++i)
          {
            if (mi[i] > 0.)
              {
                const double v_full = vi[i] - 0.5 * dt * mi[i] * ri[i];
                local[0] += vi[i] * vi[i] / mi[i];
                local[1] += v_full * v_full / mi[i];
              }
            local[2] += ri[i] * ri[i];
            local[3] += di[i] * (ro[i] + ri[i]);
          }
        Utilities::MPI::sum(ArrayView<const double>(local.data(), 4),
                            v.get_mpi_communicator(),
                            ArrayView<double>(sums.data(), 4));
        sums[3] *= 0.5;
        return sums;
      }
    } // namespace

    std::pair<std::array<double, 3>, std::array<double, 3>>
    ExplicitDynamics::resultant_forces(const Model &model) const
    {
      // M a_n = -r_n - alpha M v_n on every unknown with a mass (the mass
      // in use), v_n = v_{n-1/2} - dt/2 M^-1 r_n as for the kinetic
      // energy: the inertial force -M a_n and the damping force
      // -alpha M v_n, summed along each axis.
      std::array<double, 3> inertial{}, damping{};
      const LA::Vector     &v  = motion.velocity.field;
      const LA::Vector     &r  = residual.field;
      const double          dt = motion.previous_step;
      for (unsigned int c = 0; c < 3; ++c)
        {
          const LA::Vector axis = model.rigid_translation(c);
          for (const auto i : axis.locally_owned_elements())
            if (axis[i] != 0. && inverse_mass[i] > 0.)
              {
                const double v_full = v[i] - 0.5 * dt * inverse_mass[i] * r[i];
                const double f_damp = -alpha * v_full / inverse_mass[i];
                inertial[c] += axis[i] * (r[i] - f_damp);
                damping[c] += axis[i] * f_damp;
              }
        }
      const MPI_Comm        comm = model.mpi_communicator();
      std::array<double, 6> local, sums;
      std::copy(inertial.begin(), inertial.end(), local.begin());
      std::copy(damping.begin(), damping.end(), local.begin() + 3);
      Utilities::MPI::sum(ArrayView<const double>(local.data(), 6),
                          comm,
                          ArrayView<double>(sums.data(), 6));
      return {{{sums[0], sums[1], sums[2]}}, {{sums[3], sums[4], sums[5]}}};
    }

    void
    ExplicitDynamics::print_progress(Run         &run,
                                     const double t,
                                     const double dt) const
    {
      // Steps per second of wall time since the stage started, and the
      // wall time the rest of the stage needs at that rate.
      const double wall = run.wall_clock.wall_time() - stage_start_wall;
      const double rate = (motion.steps - stage_start_steps) / wall;
      run.out << "  step " << std::setw(8) << total_steps
              << ": t = " << std::scientific << std::setprecision(4) << t
              << " s, dt = " << dt << " s, kinetic energy " << motion.kinetic
              << " J, " << std::defaultfloat << std::setprecision(3) << rate
              << " steps/s, " << (stage_end - t) / dt / rate
              << " s to the stage's end" << std::setprecision(6) << std::endl;
    }

    void
    ExplicitDynamics::hold_constraints(const Model &model,
                                       LA::Vector  &r,
                                       const double dt)
    {
      // The projection's field change is part of the step: the velocity,
      // the increment; the residual r_n had the multipliers' new values;
      // the last step's work had r_n with their old ones (the trapezoid
      // rule's second half).
      const solvers::BorderCoupling &coupling = model.last_border_coupling();
      double                         work     = 0.;
      for (unsigned int k = 0; k < projection.rows.size(); ++k)
        {
          const LA::Vector &B = coupling.B[projection.rows[k]];
          r.add(projection.increments[k], B);
          work += projection.increments[k] * (previous_increment * B);
        }
      motion.work += 0.5 * work;
      motion.velocity.field.add(1. / dt, projection.free_change);
      motion.increment.field += projection.field_change;
      motion.constraint_error =
        std::max(motion.constraint_error, projection.error);
    }

    std::string
    ExplicitDynamics::integrate(Run            &run,
                                BorderedVector &x,
                                double         &t,
                                const double    t_end)
    {
      Model &model = run.model;
      // The residual at x, t is the last step's (or begin_stage()'s).
      BorderedVector &r = residual, r_next = residual;
      LA::Vector     &dx = motion.increment.field, &v = motion.velocity.field;
      while (!run.stages.finished(t, t_end))
        {
          if (motion.steps % settings.estimate_every == 0
              && motion.estimated_at != motion.steps)
            motion.stable_step = estimate_step(model, x, t);
          if (settings.time_step > motion.stable_step)
            {
              const std::string what =
                "the time step " + as_text(settings.time_step)
                + " s is above the stable step " + as_text(motion.stable_step)
                + " s at t = " + as_text(t);
              return what + " (Explicit dynamics/Time step)";
            }
          // Equal steps to t_end (an output time or the stage's end): a
          // short step to meet it, then long ones, would let the
          // variable-step scheme pump energy.
          const double allowed = settings.time_step > 0.
                                   ? settings.time_step
                                   : settings.safety * motion.stable_step;
          const double dt =
            (t_end - t) / std::max(1., std::ceil((t_end - t) / allowed - 1e-9));
          // The velocity at the half step (mass damping centred).
          const double dt_mid = 0.5 * (motion.previous_step + dt);
          const double c      = 0.5 * alpha * dt_mid;
          auto         mi     = inverse_mass.begin();
          auto         ri     = r.field.begin();
          for (auto &vi : v)
            vi = ((1. - c) * vi - dt_mid * *mi++ * *ri++) / (1. + c);
          dx.swap(previous_increment);
          dx.equ(dt, v);
          model.distribute_increment(dx);
          x.field += dx;
          t += dt;
          std::string message = model.begin_step(t, x);
          if (!message.empty())
            return message;
          if (model.n_border() > 0)
            {
              // The border follows the field; multipliers of constraints
              // (a prescribed chamber volume) move it to hold them.
              message = project_border(
                model, x, t, inverse_mass, dt * dt_mid / (1. + c), projection);
              if (!message.empty())
                return message;
              if (!projection.rows.empty())
                hold_constraints(model, r.field, dt);
            }
          model.assemble_residual(x, t, r_next);
          const auto sums =
            step_sums(v, dx, r.field, r_next.field, inverse_mass, dt);
          std::swap(r, r_next);
          motion.work += sums[3];
          motion.damping += alpha * dt_mid * sums[0];
          motion.kinetic = 0.5 * sums[1];
          if (!std::isfinite(sums[2]) || !std::isfinite(r.border.l2_norm())
              || !std::isfinite(motion.kinetic))
            return "the motion is not finite at t = " + as_text(t)
                   + " (an unstable step, or a load that is not finite)";
          model.commit_step(t, x);
          motion.scale         = std::max({motion.scale,
                                           motion.kinetic,
                                           std::abs(motion.work),
                                           motion.damping});
          motion.previous_step = dt;
          smallest_step = smallest_step > 0. ? std::min(smallest_step, dt) : dt;
          ++motion.steps;
          ++total_steps;
          if (total_steps % settings.print_every == 0)
            print_progress(run, t, dt);
          if (total_steps % 256 == 0
              && interrupt_signal(model.mpi_communicator()))
            return "";
        }
      return "";
    }
  } // namespace strategies
} // namespace pneuma
