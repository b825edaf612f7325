#pragma once

/**
 * @file
 * Path following: the load factor becomes an unknown of Newton's system,
 * bordered by one constraint row (doc/theory.md "Path following").
 *
 * In a stage under arc-length or displacement control the pseudo time
 * \f$\tau\f$ of the load curves is no longer prescribed: it is the load
 * factor, solved for together with the field \f$u\f$ and the chamber
 * unknowns, so that the loads that change over the stage (pressure, gas
 * amount, liquid volume, surface, line and point loads, cable loads) are
 * scaled together, as in Abaqus' Riks step. The residual \f$R(u,\tau)\f$ is
 * bordered by one constraint
 * - arc length (Crisfield's cylindrical constraint, \f$\psi = 0\f$, or
 *   the spherical one, \f$\psi = 1\f$):
 *   \f$ g = \sqrt{(|\Delta u|^2/U^2 + \psi^2\Delta\tau^2)/(1+\psi^2)}
 *   - \Delta s = 0\f$,
 * - displacement control of a monitored component \f$d = w\cdot u\f$:
 *   \f$ g = (w\cdot\Delta u - \Delta d)/\dot d_0 = 0\f$,
 *
 * where \f$\Delta\f$ is the change since the last converged state,
 * \f$U = |du/d\tau|\f$ and \f$\dot d_0 = |w\cdot du/d\tau|\f$ at the start of
 * the stage, so that \f$\Delta s\f$ is measured in pseudo time (the first
 * arc-length step of a stage is a load step of \f$\Delta\tau = \Delta s\f$).
 * Newton is applied to the whole bordered system, constraint included, so
 * it stays quadratic. Its linear system is solved by the bordering
 * algorithm on the same factorization: \f$J a = r\f$ and \f$J b =
 * \partial R/\partial\tau\f$ (two substitutions), then
 * \f$\delta\tau = (r_g - g_u\cdot a)/(g_\tau - g_u\cdot b)\f$ and
 * \f$\delta u = a - \delta\tau\, b\f$, where J is the model's own bordered
 * Jacobian (chambers included). \f$\partial R/\partial\tau\f$ is the
 * difference quotient of the residual in \f$\tau\f$ at the current state
 * (exact up to round-off for loads linear in \f$\tau\f$).
 */

#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/newton_solver.h>

#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace solvers
  {
    /// How a load stage is driven.
    enum class Control
    {
      load,        ///< the pseudo time is prescribed (load control)
      arc_length,  ///< arc-length control
      displacement ///< displacement control of the monitored component
    };

    /**
     * The model bordered by the path constraint: the unknowns are the
     * model's (field and border) and, last on the border, the load
     * factor \f$\tau\f$ (pseudo time, unscaled). The constraint's residual
     * row is \f$F g\f$ with the force scale \f$F = |\partial R/\partial
     * \tau|\f$ at the start of the stage (so that Newton's norm mixes forces
     * with forces).
     */
    class PathConstraintProblem : public NonlinearProblem
    {
    public:
      /// The problem on @p model; @p h is the step of the difference
      /// quotient in the pseudo time.
      PathConstraintProblem(Model &model, const double h);

      /// The extended vector of the model's @p state at pseudo time @p t.
      static BorderedVector
      extend(const BorderedVector &state, const double t);
      /// The model's part of an extended vector.
      static BorderedVector
      model_part(const BorderedVector &x);
      /// The load factor (pseudo time) of an extended vector.
      static double
      load_factor(const BorderedVector &x)
      {
        return x.border[x.border.size() - 1];
      }

      /**
       * The path's tangent at the converged extended state @p x:
       * \f$du/d\tau = -J^{-1}\partial R/\partial\tau\f$ (model sized), and
       * the force scale \f$|\partial R/\partial\tau|\f$ in @p force_rate.
       * Assembles and factorizes at @p x.
       */
      BorderedVector
      tangent(const BorderedVector &x, double &force_rate);

      /// The monitor functional w (w . u is the monitored component).
      void
      set_monitor(const LA::Vector &monitor)
      {
        w = monitor;
      }
      /// The scales of the stage: U = |du/dtau| (@p u_scale), \f$\psi^2\f$
      /// (@p psi2), F = |dR/dtau| (@p force_scale) and the monitor's
      /// |rate| per pseudo time (@p rate).
      void
      set_scales(const double u_scale,
                 const double psi2,
                 const double force_scale,
                 const double rate);
      /// The constraint of the step from the converged (extended)
      /// @p center: the arc length @p size (arc_length) or the monitor's
      /// change @p size (displacement).
      void
      set_constraint(const Control         type,
                     const BorderedVector &center,
                     const double          size);

      /// Change the constraint's size: the arc radius, or the monitor's
      /// prescribed change.
      void
      set_size(const double size)
      {
        (control == Control::displacement ? increment : radius) = size;
      }

      /// The constraint's value g (pseudo-time units) at @p x.
      double
      constraint(const BorderedVector &x) const;

      /// The arc length of the extended increment @p dx (the norm of the
      /// arc-length constraint with the current scales).
      double
      arc_length(const BorderedVector &dx) const;
      /// Inner product of two extended increments in that norm.
      double
      dot(const BorderedVector &a, const BorderedVector &b) const;

      // ---- NonlinearProblem
      void
      assemble(const BorderedVector &x, BorderedVector &residual) override;
      void
      solve_linear(const double          shift,
                   const BorderedVector &rhs,
                   BorderedVector       &dx) override;
      double
      initial_shift(const double factor) override;
      void
      laplacian_vmult(const BorderedVector &x, BorderedVector &y) override;
      double
      load_norm() override;
      double
      start_prestress() override;
      void
      set_linear_tolerance(const double eta) override;
      bool
      interrupted() override;
      std::vector<std::string>
      block_names() const override;
      std::vector<double>
      block_norms(const BorderedVector &r) const override;

      /// y = J_ext d with the bordered Jacobian at the last assembled
      /// state (for the finite-difference check of the tangent).
      void
      vmult(const BorderedVector &d, BorderedVector &y);

      /// The residual difference quotient dR/dtau at the last assembled
      /// state (model sized).
      const BorderedVector &
      load_rate() const
      {
        return rate;
      }

    private:
      /// dR/dtau at the last assembled state, if not yet computed.
      void
      update_rate();
      /// The arc-length radius of the state (@p field, @p tau) about the
      /// centre, and its field increment @p du.
      double
      radius_at(const LA::Vector &field,
                const double      tau,
                LA::Vector       &du) const;
      /// Assemble the model at the extended @p x (its time too).
      void
      assemble_model(const BorderedVector &x);
      /// The constraint's gradient at the last assembled state:
      /// g_u = scale * direction, and g_tau.
      struct Gradient
      {
        LA::Vector direction;
        double     scale = 0., tau = 0.;
      };
      Gradient
      gradient() const;

      Model         &model;
      double         h;
      Control        control = Control::arc_length;
      BorderedVector center;
      LA::Vector     w;
      double         radius = 0., u_scale = 1., psi2 = 0.;
      double         increment = 0., monitor_rate = 1.;
      double         force = 1.;
      /// The last assembled state and residual (model sized), and dR/dtau
      /// there.
      BorderedVector last_x, last_r, rate;
      bool           rate_current = false;
    };
  } // namespace solvers
} // namespace pneuma
