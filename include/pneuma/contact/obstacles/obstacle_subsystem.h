#pragma once

/**
 * @file
 * Rigid obstacles as a subsystem of the coupled model (core/subsystem.h):
 * the penalty contact of the membrane with planes, spheres and cylinders
 * that stand still or move by a prescribed translation
 * (contact/obstacles/obstacle_contact.h, doc/theory.md "Rigid
 * obstacles"). Present only when "Obstacles/Number of obstacles" is
 * positive. Its terms join the membrane's cell loop (membrane::CellTerms),
 * and its forces count as applied loads in the membrane's reactions; each
 * obstacle reports the force on it, its contact area, its largest
 * penetration and its penalty energy.
 *
 * An obstacle with "Control = force" has one border unknown, its position
 * s along its Force direction e (doc/theory.md §19, "Obstacles loaded by
 * a force"): the row -(F(t) + e . f) = 0 (f the membrane's contact force
 * on it; the derivative of the potential by s) with the blocks
 * B = -K_k E, C = -K_k^T E, D = E . K_k E from the obstacle's own contact
 * tangent K_k on each cell and E the rigid motion along e (symmetric
 * without friction); while it touches nothing, it keeps its position
 * (s = s_0).
 */

#include <pneuma/contact/obstacles/obstacle_contact.h>
#include <pneuma/contact/obstacles/obstacle_parameters.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/membrane/cell_terms.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include <memory>

namespace pneuma
{
  namespace contact
  {
    /// The rigid obstacles.
    class ObstacleSubsystem : public Subsystem,
                              public membrane::CellTerms,
                              public OutputFiles,
                              public Checkpointed,
                              public Holds
    {
    public:
      explicit ObstacleSubsystem(Model &model);

      /// "Obstacles/Number of obstacles".
      static void
      declare_switches(ParameterHandler &prm);
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "obstacles";
      }
      /// One per force-controlled obstacle: its position s [m].
      unsigned int
      n_border_unknowns() const override;
      /// The positions of the last accepted state.
      Vector<double>
      border() const override;
      /// The positions of the last accepted state again.
      void
      reject_step() override;
      /// A step starts from the strategy's positions (extrapolated with
      /// the field).
      bool
      predicts_border() const override
      {
        return false;
      }
      /// The membrane may rest on the obstacles.
      bool
      holds(const Subsystem &other) const override;
      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;
      /// The regions exist; print each obstacle and its penalty.
      void
      finish_setup() override;
      /// No point of the membrane starts inside an obstacle.
      void
      initialize(const LA::Vector &field, const double t) override;
      void
      assemble(const Assembly &) override
      {
        // The terms are assembled in the membrane's cell loop.
      }
      /// With friction: the anchors of the accepted state at @p t.
      void
      commit_step(const double          t,
                  const LA::Vector     &field,
                  const Vector<double> &border) override;
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field,
                     const double      t) const override;
      /// With friction: the anchors (section "obstacles/anchors", by cell
      /// id); without, nothing.
      void
      save_checkpoint(Checkpoint &checkpoint,
                      const std::vector<const LA::Vector *> &) const override;
      void
      load_checkpoint(const Checkpoint &checkpoint,
                      const std::vector<LA::Vector *> &) override;
      void
      add_output_fields(const LA::Vector &field, const double t) override;

      // ---- membrane::CellTerms: the contact terms on the membrane's cells
      void
      begin(const Assembly &a) override;
      std::unique_ptr<membrane::CellTerms::Scratch>
      new_scratch() const override;
      std::unique_ptr<membrane::CellTerms::Record>
      new_record() const override;
      void
      cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
           const membrane::ReferenceGeometry            &reference,
           const unsigned int                            cell_index,
           const std::vector<double>                    &local_u,
           FullMatrix<double>                           *cell_matrix,
           Vector<double>                               *cell_residual,
           membrane::CellTerms::Scratch                 &scratch,
           membrane::CellTerms::Record                  &record) const override;
      void
      commit(const membrane::CellTerms::Record          &record,
             const std::vector<types::global_dof_index> &dof_indices) override;
      /// The force-controlled obstacles' rows and blocks.
      void
      end() override;
      void
      add_loads(const LA::Vector                &u,
                const AffineConstraints<double> &constraints,
                const double                     t,
                LA::Vector                      &residual,
                LA::Vector                      &external) const override;

    private:
      /// The sums over this rank's cells at the ghosted state @p u and
      /// time @p t, and (if given) the cells' output values by active cell
      /// index.
      std::vector<ObstacleSums>
      sums(const LA::Vector                &u,
           const double                     t,
           std::vector<ObstacleCellOutput> *cells = nullptr) const;
      /// The smallest and largest penalty of each obstacle over the cells
      /// it may touch (over the ranks).
      std::vector<std::pair<double, double>>
      penalty_range() const;
      /// The membrane's values of the owned cell @p cell_index in @p u.
      void
      cell_values(const LA::Vector    &u,
                  const unsigned int   cell_index,
                  std::vector<double> &local_u) const;

      /// The friction state that the state @p field at @p t leaves.
      void
      accept_friction(const LA::Vector &field, const double t);
      /// The friction state of the owned cell @p c (nullptr: none kept).
      const PointFriction *
      friction_of(const unsigned int c) const;
      /// Entries of the friction state per cell (points x obstacles).
      unsigned int
      friction_stride() const;
      /// The row of the force-controlled obstacle @p k (its @p j th) on
      /// one cell from its own terms @p M, @p f there: adds them to the
      /// cell's (either may be nullptr) and fills @p record.
      void
      add_force_row(const membrane::ReferenceGeometry &reference,
                    const unsigned int                 k,
                    const FullMatrix<double>          &M,
                    const Vector<double>              &f,
                    FullMatrix<double>                *cell_matrix,
                    Vector<double>                    *cell_residual,
                    membrane::CellTerms::Record       &record,
                    const unsigned int                 j) const;
      /// Move the force-controlled obstacles to @p border's positions
      /// (nullptr: the accepted ones).
      void
      set_positions(const Vector<double> *border);

      Model                           &model;
      membrane::MembraneSubsystem     &membrane;
      ObstacleParameters               parameters;
      std::unique_ptr<ObstacleContact> contact;
      /// The obstacles' translations at the time of the assembly.
      std::vector<Tensor<1, 3>> assembly_translations;
      Vector<float>             pressure_output, gap_output;
      /// With friction: per owned cell, point and obstacle, the state of
      /// the last accepted step (sized at the first assembly on a mesh; a
      /// new mesh starts without anchors).
      std::vector<PointFriction> anchors;

      /// The force-controlled obstacles (their border rows in this order).
      std::vector<unsigned int> force_controlled;
      /// Their positions in the last accepted state [m].
      Vector<double> accepted_positions;
      /// During an assembly: the assembly, and per force-controlled
      /// obstacle e . f, D and its points in contact on this rank.
      const Assembly           *assembly = nullptr;
      std::vector<double>       force_sum, stiffness_sum;
      std::vector<unsigned int> contact_points;
    };
  } // namespace contact
} // namespace pneuma
