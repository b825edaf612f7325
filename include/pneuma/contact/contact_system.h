#pragma once

/**
 * @file
 * Curve-to-surface penalty contact between cable mid-lines and the
 * membrane (source paper section 3.2; doc/theory.md §10).
 *
 * Search: every rank holds the cables and its own membrane cells. Cells of
 * the pair's regions whose current bounding box comes within R + the
 * search distance of a cable element's box are its candidates; the
 * candidates are renewed at the start of every load step (the sparsity
 * pattern grows when new couplings appear), so Newton never meets a
 * coupling outside the matrix. Each integration point of a cable element
 * is projected onto its candidates (closest point, ContactPoint); the
 * nearest projection inside a cell wins, over all ranks (one MPI min
 * reduction per assembly), which makes the answer unique at cell edges and
 * partition boundaries. The rank owning the winning cell assembles the
 * point's penalty force and exact tangent.
 *
 * With a smoothed master normal (Master normal = smoothed) the patches carry
 * the nodal-averaged normals of their nodes (NodalNormals, from the owned and
 * ghost cells of the pair's regions), and the terms of a point reach the
 * nodes those normals depend on: its local matrix is chained from the
 * variables (slave, cell nodes, nodal normals) to the dofs (slave, the
 * cell's nodes and the nodes on the lattice lines through them in the
 * neighbouring cells). The force of a smoothed point acts along the
 * continuous normal, so its tangent is not symmetric (the LU is chosen).
 */

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <pneuma/cables/cable_system.h>
#include <pneuma/contact/contact_parameters.h>
#include <pneuma/contact/contact_point.h>
#include <pneuma/contact/nodal_normals.h>
#include <pneuma/core/linear_algebra.h>
#include <pneuma/geometry/scene_generator.h>

#include <array>
#include <set>
#include <vector>

namespace pneuma
{
  class Checkpoint;

  namespace contact
  {
    /// What a contact pair reports after an assembly.
    struct ContactReport
    {
      unsigned int active_points = 0, points = 0;
      /// Integral of the contact line load N along the cable [N], and the
      /// resultant force on the cable [N] (normal and friction forces).
      double                total_force = 0.;
      std::array<double, 3> force{{0., 0., 0.}};
      /// Largest penetration -xi3 [m] (0 if none).
      double max_penetration = 0.;
      /// Friction: points that slip, and the integral of |t| [N].
      unsigned int slip_points    = 0;
      double       friction_force = 0.;
    };

    /**
     * What an assembly of the contact records at a state (written into the
     * record it is given, never into the system): per pair and point the
     * line load, the friction anchor that a commit would keep, and the
     * master a near point is near; the pairs' reports; the force per
     * master cell.
     */
    struct ContactRecord
    {
      struct Pair
      {
        /// Line load N (>= 0) per point, or 0.
        std::vector<double> line_load;
        /// Friction: the anchor (local master, -1: none) and its
        /// convective coordinates that a commit keeps.
        std::vector<int>      pending_anchor;
        std::vector<Point<2>> pending_xi;
        /// The step check's reference: the master a near point is near
        /// (-1: none here), the projection and the offset x - y(xi).
        std::vector<int>          seen_master;
        std::vector<Point<2>>     seen_xi;
        std::vector<Tensor<1, 3>> seen_offset;
      };
      std::vector<Pair>          pairs;
      std::vector<ContactReport> reports;
      /// Contact force per master cell.
      std::vector<double> master_force;
    };

    /// The contact pairs of a scene.
    class ContactSystem
    {
    public:
      ContactSystem(const ContactParameters        &parameters,
                    const geometry::SceneGenerator &geometry,
                    const cables::CableSystem      &cables);

      bool
      empty() const
      {
        return parameters.empty();
      }

      /// Master cells (owned, in the pairs' regions) and cable points.
      void
      setup(const Mapping<2, 3>    &mapping,
            const DoFHandler<2, 3> &dof_handler,
            const MPI_Comm          comm);

      /// The cable dofs every rank must see (mid-lines of paired cables).
      IndexSet
      cable_dofs(const types::global_dof_index size) const;

      /**
       * Renew the candidates at @p u (ghosted; nullptr: the reference
       * configuration). Returns true on every rank if couplings outside
       * the current sparsity pattern appeared (the caller rebuilds it).
       */
      bool
      update_candidates(const LA::Vector *u);

      /// Couplings of all candidates seen so far.
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const;

      /**
       * Add the penalty forces (to r = f_int - f_ext) and their tangent at
       * @p u (ghosted); compresses what it touched. Changes nothing of the
       * system: what the assembly finds at @p u goes to @p record
       * (new_record() sizes it).
       */
      void
      assemble(const LA::Vector                &u,
               const AffineConstraints<double> &constraints,
               LA::SparseMatrix                *tangent,
               LA::Vector                      *residual,
               ContactRecord                   &record) const;

      /// A record sized for this system's pairs, points and masters.
      ContactRecord
      new_record() const;

      /// Record the state @p u (ghosted): the reports, line loads, contact
      /// pressures and friction anchors that commit_step() and the outputs
      /// use.
      void
      record_state(const LA::Vector                &u,
                   const AffineConstraints<double> &constraints);

      /// Accept the friction state recorded (record_state() at the
      /// converged state): stick anchors stay, slipping ones move. The
      /// points near the master in it become the reference of
      /// check_step().
      void
      commit_step();

      /**
       * Why the converged state @p u (ghosted) of a step is not to be
       * accepted, or an empty string (the same on every rank): a point
       * that was near its master at the last committed state moved
       * relative to that material point of the master by more than the
       * pair's Maximum motion per step (a fraction of the search
       * distance; the candidates of the step may no longer hold it), or a
       * point penetrates a master cell that was not among its element's
       * candidates in the step (the search missed it).
       */
      std::string
      check_step(const LA::Vector &u) const;

      /// Checkpoint: the stick anchors of every pair (gathered; by cell
      /// id, so a restart may use another number of ranks).
      void
      save_checkpoint(Checkpoint &checkpoint) const;
      void
      load_checkpoint(const Checkpoint &checkpoint);

      /**
       * Reports of the accepted state, one per pair (same on every rank):
       * those of the assembly that commit_step() accepted, made with the
       * anchors of the step before, so that a point that slipped in the
       * step counts as slipping (assembled again with the moved anchors it
       * would sit on its cone and count as sticking); before the first
       * commit, those of the last assembly.
       */
      const std::vector<ContactReport> &
      reports() const
      {
        return committed_reports.empty() ? recorded.reports : committed_reports;
      }

      /**
       * The master normal of the load step to pseudo time @p t: smoothed
       * for the pairs with Master normal = smoothed whose Smoothed normal
       * from is 0 or below @p t, facet otherwise. Returns true (on every
       * rank) if a pair turned smoothed, whose couplings with the nodal
       * normals' neighbours the sparsity pattern then needs.
       */
      bool
      set_time(const double t);

      /// True if a pair uses the smoothed master normal now.
      bool
      smoothed() const;

      /// Contact line load (N, positive in compression) averaged over each
      /// element of cable @p k at the recorded state (every rank).
      Vector<double>
      cable_line_load(const unsigned int k) const;

      /// Contact pressure on the owned membrane cells (force over area) at
      /// the recorded state, indexed by active cell index.
      Vector<float>
      membrane_pressure(const unsigned int n_active_cells) const;

    private:
      struct MasterCell
      {
        DoFHandler<2, 3>::active_cell_iterator cell;
        /// Global dofs in lattice order, 3 per node.
        std::vector<types::global_dof_index> dofs;
        /// Reference node positions (lattice order).
        std::vector<Tensor<1, 3>> reference;
        /// +1 if rho_1 x rho_2 points outward (Geometry/Orientation).
        double             outward  = 1.;
        double             area     = 0.;
        types::material_id material = 0;
      };
      struct CablePoint
      {
        unsigned int cable_cell;
        double       eta, weight;
      };
      struct PairData
      {
        double radius = 0., search = 0.;
        /// Solid beam: the gap uses the current elliptic section.
        bool beam = false;
        /// Per cable cell: its mid-line dofs (vertex 0 xyz, vertex 1 xyz),
        /// then for a solid beam a1, a2 of vertex 0 and of vertex 1.
        std::vector<std::vector<types::global_dof_index>> cell_dofs;
        /// Per cable cell: reference vertex positions, and the reference
        /// values of its dofs.
        std::vector<std::array<Tensor<1, 3>, 2>> cell_reference;
        std::vector<std::vector<double>>         cell_reference_values;
        std::vector<CablePoint>                  points;
        /// Per cable cell: candidate master cells (indices).
        std::vector<std::vector<unsigned int>> candidates;
        /// Smoothed master normal: the nodal normals of the pair's cells
        /// (mutable: a cache of the current configuration's values).
        bool                 smoothed = false;
        mutable NodalNormals normals;
        /// Friction: per point the stick anchor (local master, -1: none)
        /// and its convective coordinates.
        std::vector<int>      anchor;
        std::vector<Point<2>> anchor_xi;
        /// Step check: per point the master (local index, -1: none on
        /// this rank or not near), the convective coordinates of the
        /// projection and the offset x - y(xi) from it at the last
        /// committed state.
        std::vector<int>          start_master;
        std::vector<Point<2>>     start_xi;
        std::vector<Tensor<1, 3>> start_offset;
      };
      /// The current end points of every cable element of a pair.
      using Slave = std::vector<std::array<Tensor<1, 3>, 2>>;
      /// The nearest master of each point of a pair: here (distance,
      /// rank) and over all ranks, its master, projection, and whether
      /// this rank assembles it.
      struct Best
      {
        double distance;
        int    rank;
      };
      struct Nearest
      {
        std::vector<Best>         local, global;
        std::vector<unsigned int> master;
        std::vector<Projection>   projection;
        std::vector<bool>         held;
      };
      class Patches;
      class Distributor;

      /// The current sections of a solid beam's elements (none for a
      /// cable).
      std::vector<SlaveSection>
      current_sections(const PairData &d, const LA::Vector &u) const;
      /// The nearest master of each point of pair @p d.
      Nearest
      nearest(const PairData &d, const Slave &slave, Patches &patches) const;
      /// assemble() of pair @p k.
      void
      assemble_pair(const unsigned int               k,
                    const LA::Vector                &u,
                    const AffineConstraints<double> &constraints,
                    LA::SparseMatrix                *tangent,
                    LA::Vector                      *residual,
                    ContactRecord                   &record) const;
      /// The terms of point @p q of pair @p k (assembled here) with its
      /// record: the penalty force, then friction.
      void
      add_point(const unsigned int               k,
                const unsigned int               q,
                const double                     gap,
                const Nearest                   &near,
                const Slave                     &slave,
                const std::vector<SlaveSection> &sections,
                Patches                         &patches,
                const Vector<double>            &gradient,
                const FullMatrix<double>        &hessian,
                const LA::Vector                &u,
                Distributor                     &distributor,
                ContactReport                   &report,
                ContactRecord                   &record) const;
      /// The friction terms of point @p q of pair @p k in contact, and the
      /// anchor a commit keeps.
      void
      add_friction(const unsigned int               k,
                   const unsigned int               q,
                   const Nearest                   &near,
                   const Slave                     &slave,
                   const std::vector<SlaveSection> &sections,
                   Patches                         &patches,
                   Distributor                     &distributor,
                   ContactReport                   &report,
                   ContactRecord                   &record) const;

      /// The current end points of every cable element of pair @p d at
      /// @p u (ghosted).
      std::vector<std::array<Tensor<1, 3>, 2>>
      current_slave(const PairData &d, const LA::Vector &u) const;

      /// The current patch of master @p m, its normal turned to the side
      /// @p outside (u = nullptr: the reference); with @p normals (and u)
      /// it carries the nodal normals.
      MasterPatch
      patch(const MasterCell &m,
            const bool        outside,
            const LA::Vector *u,
            NodalNormals     *normals = nullptr) const;

      /**
       * The current bounding boxes of the master cells of pair @p p (of its
       * regions) with their indices in `masters`, the leaves of the
       * R-tree that the search and the step check query (u = nullptr: the
       * reference).
       */
      std::vector<std::pair<BoundingBox<3>, unsigned int>>
      master_boxes(const ContactPair &p, const LA::Vector *u) const;

      /**
       * The map from the variables of a point's contact terms on master
       * @p m of pair @p d (slave, cell nodes and, smoothed, nodal normals)
       * to dofs: @p dofs gets the slave's, the cell's and, smoothed, the
       * further dofs the nodal normals depend on; @p rows (if given) per
       * variable the dofs (positions in @p dofs) and weights it moves,
       * the nodal normals' rows from their jacobian at @p u.
       */
      void
      variable_map(
        const PairData                                        &d,
        const unsigned int                                     cable_cell,
        const MasterCell                                      &m,
        const LA::Vector                                      *u,
        std::vector<types::global_dof_index>                  &dofs,
        std::vector<std::vector<std::pair<unsigned, double>>> *rows) const;

      const ContactParameters        &parameters;
      const geometry::SceneGenerator &geometry;
      const cables::CableSystem      &cables;
      MPI_Comm                        comm   = MPI_COMM_SELF;
      unsigned int                    degree = 1;
      std::vector<MasterCell>         masters;
      std::vector<PairData>           pairs;
      /// Couplings (pair, cable cell, master) in the sparsity pattern.
      std::set<std::array<unsigned int, 3>> coupled;
      /// The state recorded last (record_state()), and the reports of the
      /// last commit.
      ContactRecord              recorded;
      std::vector<ContactReport> committed_reports;
    };
  } // namespace contact
} // namespace pneuma
