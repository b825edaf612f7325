#pragma once

/**
 * @file
 * The chamber unknowns and their constraints, bordering the membrane
 * equations (doc/theory.md "Chambers: the bordered system").
 *
 * Each chamber group (a chamber with the chambers connected to it) has one
 * or two unknowns: its gauge gas pressure p and/or its free-surface level
 * h. With the membrane residual R(u, p, h) and the constraints
 * - gas, prescribed pressure:  p - p_hat(t) = 0
 * - gas, closed amount:        p - (p_law(V - V_l, V_n) - p_a) = 0
 * - gas, prescribed volume:    V - V_hat(t) = 0
 * - liquid:                    V_l(u, h) - V_l,hat(t) = 0
 * Newton solves the bordered system
 * \f[ \begin{pmatrix} K & B\\ C^T & D\end{pmatrix}
 *     \begin{pmatrix}\delta u\\ \delta\lambda\end{pmatrix} = -
 *     \begin{pmatrix} R\\ g\end{pmatrix}, \f]
 * B = dR/d(p,h) = -(q, rho|g| q_l), C = dg/du, D = dg/d(p,h), with the
 * Schur complement \f$S = D - C^T K^{-1} B\f$ on the few chamber
 * unknowns: one factorization of the sparse K (which holds the follower and
 * hydrostatic stiffness) and one substitution per coupled unknown. The
 * dense rank-one terms q q^T never enter the sparse matrix. Unknowns whose
 * constraint does not involve u (prescribed pressure) are eliminated
 * first and cost nothing.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/full_matrix.h>

#include <pneuma/chambers/chamber_assembler.h>
#include <pneuma/chambers/chamber_parameters.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/solvers/border.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pneuma
{
  class Checkpoint;

  namespace chambers
  {
    /// What is reported for one chamber (history.csv, summary.json).
    struct ChamberReport
    {
      double pressure          = 0.; ///< gauge gas pressure [Pa]
      double absolute_pressure = 0.; ///< [Pa]
      double volume = 0., gas_volume = 0., liquid_volume = 0.;
      double level = 0., wetted_area = 0.;
      double gas_amount = 0.; ///< V_n: gas volume at ambient pressure
      double pv_kappa   = 0.; ///< the law's invariant, p_abs V_gas^kappa
    };

    class ChamberSystem
    {
    public:
      ChamberSystem(const ChamberParameters &parameters,
                    const ChamberAssembler  &assembler);

      /// Number of unknowns on the border.
      unsigned int
      n_unknowns() const
      {
        return n_total;
      }

      /// The unknowns of the chambers (one group per chamber and the
      /// chambers connected to it); initialize() calls it again.
      void
      setup_groups();

      /// The reference state at pseudo time @p t (ghosted @p u).
      void
      initialize(const LA::Vector &u, const double t);

      /**
       * Prepare the step to pseudo time @p t from the converged @p u:
       * predict the unknowns (levels from the liquid volume on the
       * current geometry, pressures of closed gas from the law) and fix the
       * scales of the border. Returns an empty string, or why the step is
       * impossible (e.g. more liquid than the chamber holds).
       */
      std::string
      begin_step(const LA::Vector &u, const double t);

      /// The pseudo time of the targets (prescribed pressure, volume,
      /// gas amount, liquid volume) in evaluate(): begin_step() sets it,
      /// an assembly at another time (path following) moves it.
      void
      set_time(const double t)
      {
        time = t;
      }

      /// The scaled border for Newton.
      Vector<double>
      pack() const;
      /// Take the physical unknowns from a converged scaled border.
      void
      unpack(const Vector<double> &border);

      /// The loads on each chamber for the scaled unknowns @p border.
      std::vector<ChamberLoad>
      loads(const Vector<double> &border) const;

      /**
       * The scaled constraint residuals for @p border and the measures
       * @p m (assembled with vectors) at pseudo time t of begin_step; writes
       * the Jacobian blocks B, C, D and the scales of these unknowns into
       * rows and columns @p offset.. of @p coupling.
       */
      void
      evaluate(const Vector<double>               &border,
               const std::vector<ChamberMeasures> &m,
               Vector<double>                     &residual,
               solvers::BorderCoupling            &coupling,
               const unsigned int                  offset) const;

      /**
       * The scaled border that the chambers' equations give for the field
       * @p u (ghosted) at pseudo time @p t, without Newton: the levels that
       * hold the liquid volumes, the pressures of the gas laws at the gas
       * volumes they leave, the prescribed pressures. A gas under volume
       * control (not sealed) keeps its pressure from @p border: it is the
       * multiplier of its volume constraint V(u) = V(t), not a function of
       * the field; the constraint's row and V(u) - V(t) [m^3] go to
       * @p constraints.
       */
      Vector<double>
      border_for(const LA::Vector              &u,
                 const double                   t,
                 const Vector<double>          &border,
                 std::vector<BorderConstraint> &constraints) const;

      /// Force scale of the chamber loads (for the residual reference).
      double
      force_scale() const
      {
        return force_reference;
      }

      /// After a converged step at @p t: seal chambers, move the
      /// incremental law's reference, and record the reports.
      void
      commit_step(const LA::Vector         &u,
                  const double              t,
                  const ConditionalOStream &out);

      /// Checkpoint: the state of every group (pressure, level, sealed
      /// amount, the last converged gas state).
      void
      save_checkpoint(Checkpoint &checkpoint) const;
      /// Restore it (after initialize()); the reports follow at record().
      void
      load_checkpoint(const Checkpoint &checkpoint);
      /// Reports of the state @p u with the current group state.
      void
      record(const LA::Vector &u);

      /// The reports of the last commit (or initialize), one per chamber.
      const std::vector<ChamberReport> &
      reports() const
      {
        return chamber_reports;
      }

      /// The loads of the converged state (for output).
      std::vector<ChamberLoad>
      converged_loads() const;

    private:
      struct Group
      {
        unsigned int              leader;  ///< chamber whose filling rules
        std::vector<unsigned int> members; ///< chambers, leader first
        bool                      gas = false, liquid = false;
        unsigned int              p_index = 0, h_index = 0;
        double                    p = 0., h = 0.; ///< physical unknowns
        double                    V0     = 0.;    ///< initial volume
        double                    amount = 0.;    ///< V_n when sealed
        bool                      sealed = false;
        bool                      empty  = false; ///< no liquid: h fixed
        GasState                  old;            ///< last converged state
        /// The last level search that converged at its final level h: the
        /// state (ChamberAssembler::state()), time and volume it was for.
        /// Searching again from h for these finds h at once, so the search
        /// is skipped (an explicit step searches twice at one state).
        struct
        {
          std::uint64_t state = 0;
          double        time = 0., target = 0., h = 0.;
          bool          valid = false;
        } found;
      };

      /// Sum member measures into group totals.
      void
      group_measures(const Group                        &g,
                     const std::vector<ChamberMeasures> &m,
                     double                             &V,
                     double                             &V_l,
                     double                             &A_fs,
                     double                             &wetted) const;
      /// Absolute gas pressure from the law, and its derivative.
      std::pair<double, double>
      gas_law(const Group &g, const double V_gas) const;
      double
      prescribed_amount(const Group &g) const;
      bool
      pressure_controlled(const Group &g) const;
      std::string
      predict_level(Group &g, const LA::Vector &u);

      const ChamberParameters  &parameters;
      const ChamberAssembler   &assembler;
      std::vector<Group>        groups;
      std::vector<unsigned int> group_of;
      unsigned int              n_total = 0;
      double                    time    = 0.;
      std::vector<double>       unknown_scale, residual_scale;
      double                    force_reference = 0.;

      std::vector<ChamberReport> chamber_reports;
    };
  } // namespace chambers
} // namespace pneuma
