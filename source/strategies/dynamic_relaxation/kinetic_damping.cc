/**
 * @file
 * One relaxation with kinetic damping (strategies/dynamic_relaxation/
 * dynamic_relaxation.h): the fictitious motion, its resets at the peaks of
 * the kinetic energy, and the guard against an unstable mass.
 */

#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/strategies/border_projection.h>
#include <pneuma/strategies/dynamic_relaxation/dynamic_relaxation.h>
#include <pneuma/strategies/run.h>

#include <cmath>
#include <iomanip>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;
    using solvers::BorderedVector;

    namespace
    {
      /// The fictitious motion: diagonal mass, velocity v_{n-1/2},
      /// acceleration -M^-1 r(u_n), kinetic energy of v_{n-1/2}. The
      /// vectors share the owned layout; the loops run over its local
      /// entries.
      struct Motion
      {
        LA::Vector inverse_mass, velocity, acceleration, next;
        double     kinetic = 0., peak = 0.;

        void
        set_mass(const LA::Vector &mass)
        {
          inverse_mass = mass;
          velocity.reinit(mass);
          acceleration.reinit(mass);
          next.reinit(mass);
          for (auto &m : inverse_mass)
            m = 1. / m;
        }
        /// a = -M^-1 r.
        void
        accelerate(const LA::Vector &r)
        {
          acceleration = inverse_mass;
          auto ri      = r.begin();
          for (auto &a : acceleration)
            a *= -*ri++;
        }
        /// From rest: v_{-1/2} = -a/2, so that v_{1/2} = a/2.
        void
        start()
        {
          velocity.equ(-0.5, acceleration);
          kinetic = 0.;
        }
        /// 1/2 v^T M v of @p v.
        double
        energy(const LA::Vector &v) const
        {
          double sum = 0.;
          auto   mi  = inverse_mass.begin();
          for (const double vi : v)
            sum += vi * vi / *mi++;
          return 0.5 * Utilities::MPI::sum(sum, v.get_mpi_communicator());
        }
      };
    } // namespace

    namespace
    {
      /// One relaxation at pseudo time t: the state x, its residual r and
      /// the motion, with the named steps of the iteration.
      struct Relaxation
      {
        Model           &model;
        BorderedVector  &x;
        const double     t;
        double           safety;
        BorderedVector   r;
        Motion           motion;
        LA::Vector       dx;
        BorderProjection projection;
        /// Why the border constraints could not be held ("" if they were).
        std::string failure;

        /// x moves by dx; the border unknowns follow the field, and the
        /// multipliers of constraints (a prescribed volume) move it along
        /// M^-1 B to hold them (strategies/border_projection.h; the step
        /// has a unit time: the velocity takes the change).
        void
        move()
        {
          model.distribute_increment(dx);
          x.field += dx;
          if (model.n_border() == 0)
            return;
          if (motion.inverse_mass.size() == 0)
            {
              x.border = model.border_for(x.field, t);
              return;
            }
          failure =
            project_border(model, x, t, motion.inverse_mass, 1., projection);
          if (failure.empty() && !projection.rows.empty())
            motion.velocity += projection.free_change;
        }
        /**
         * Move x onto the border constraints (a prescribed volume that
         * the stage's time has changed) keeping their multipliers: the
         * projection's multiplier is the impulse of one fictitious step,
         * not a pressure; the motion then finds the pressure. Returns
         * whether x moved (then restart()).
         */
        bool
        hold_constraints()
        {
          if (model.n_border() == 0)
            return false;
          const Vector<double> kept = x.border;
          failure =
            project_border(model, x, t, motion.inverse_mass, 1., projection);
          if (!failure.empty())
            return false;
          for (const auto row : projection.rows)
            x.border[row] = kept[row];
          return !projection.rows.empty();
        }
        /// From rest at x, with the mass of the stiffest tangent there;
        /// returns |r|.
        double
        restart()
        {
          model.assemble_stiffest_tangent(x, t);
          motion.set_mass(relaxation_mass(model, safety));
          model.assemble_residual(x, t, r);
          motion.accelerate(r.field);
          motion.start();
          return r.l2_norm();
        }
        /**
         * One step of the motion, or, where the kinetic energy falls, back
         * to its peak half a step behind and from rest there. Returns
         * whether it was a reset; |r| at the new x in @p r_norm.
         */
        bool
        step(double &r_norm)
        {
          LA::Vector &v_next = motion.next;
          v_next             = motion.velocity;
          v_next += motion.acceleration;
          const double kinetic = motion.energy(v_next);
          if (kinetic < motion.kinetic)
            {
              motion.peak = std::max(motion.peak, motion.kinetic);
              dx.equ(-0.5, motion.velocity);
              move();
              r_norm = restart();
              return true;
            }
          motion.velocity.swap(v_next);
          motion.kinetic = kinetic;
          dx             = motion.velocity;
          move();
          model.assemble_residual(x, t, r);
          motion.accelerate(r.field);
          r_norm = r.l2_norm();
          return false;
        }
      };
    } // namespace

    std::string
    DynamicRelaxation::stop_reason(const Model       &model,
                                   const Result      &result,
                                   const unsigned int it) const
    {
      const std::string ratio =
        ", |r|/|r_ref| = " + std::to_string(result.ratio);
      if (!std::isfinite(result.ratio))
        return "the residual is not finite after " + std::to_string(it)
               + " iterations";
      if (it == settings.max_iterations)
        return "no convergence in " + std::to_string(it)
               + " iterations (Dynamic relaxation/Maximum iterations)" + ratio;
      if (it % 256 == 255 && interrupt_signal(model.mpi_communicator()))
        return "interrupted" + ratio;
      return "";
    }

    DynamicRelaxation::Result
    DynamicRelaxation::relax(Run            &run,
                             BorderedVector &x,
                             const double    t,
                             const double    tolerance) const
    {
      Relaxation relaxation{
        run.model, x, t, settings.safety, {}, {}, {}, {}, {}};
      Result result;
      relaxation.dx = run.model.make_field();
      relaxation.move();
      relaxation.r  = x;
      double r_norm = relaxation.restart();
      if (relaxation.hold_constraints())
        r_norm = relaxation.restart();
      if (!relaxation.failure.empty())
        {
          result.failure = relaxation.failure;
          return result;
        }
      result.reference = std::max(r_norm, run.model.load_norm());
      if (result.reference == 0.)
        {
          result.converged = true;
          return result;
        }
      BorderedVector at_reset    = x;
      double         reset_ratio = r_norm / result.reference;
      const Motion  &motion      = relaxation.motion;
      for (unsigned int it = 0;; ++it)
        {
          result.iterations = it;
          result.ratio      = r_norm / result.reference;
          if (result.ratio <= tolerance
              && motion.kinetic
                   <= settings.kinetic_energy_tolerance * motion.peak)
            break;
          result.failure = relaxation.failure.empty()
                             ? stop_reason(run.model, result, it)
                             : relaxation.failure;
          if (!result.failure.empty())
            return result;
          if (result.ratio > 1e3 * std::max(1., reset_ratio))
            {
              // Unstable: the stiffness outgrew the mass since the last
              // reset. Back there, with twice the mass.
              x = at_reset;
              relaxation.safety *= 2.;
              run.out << "  relaxation unstable at iteration " << it
                      << ": back to the last reset, mass safety factor "
                      << relaxation.safety << std::endl;
              r_norm = relaxation.restart();
              continue;
            }
          if (relaxation.step(r_norm))
            {
              ++result.resets;
              at_reset    = x;
              reset_ratio = r_norm / result.reference;
            }
          if ((it + 1) % settings.print_every == 0)
            run.out << "  relaxation " << std::setw(7) << it + 1
                    << ": |r|/|r_ref| = " << std::scientific
                    << std::setprecision(3) << r_norm / result.reference
                    << ", kinetic energy " << motion.kinetic << ", "
                    << result.resets << " resets" << std::defaultfloat
                    << std::setprecision(6) << std::endl;
        }
      result.converged = true;
      run.out << "  relaxed in " << result.iterations << " iterations ("
              << result.resets
              << " resets) to |r|/|r_ref| = " << std::scientific
              << std::setprecision(3) << result.ratio << std::defaultfloat
              << std::setprecision(6) << std::endl;
      return result;
    }
  } // namespace strategies
} // namespace pneuma
