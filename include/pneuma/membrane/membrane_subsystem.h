#pragma once

/**
 * @file
 * The membrane as a subsystem of the coupled model (core/subsystem.h): the
 * codimension-one mesh (`parallel::distributed::Triangulation<2,3>`) with
 * its FE_Q displacement, material regions, boundary conditions, rigid
 * plates and junction ties, the follower-pressure, gravity and dead loads,
 * the enclosed volume, the monitor points and the support reactions
 * (doc/theory.md "Weak form", doc/user-guide.md "Membranes").
 *
 * Other subsystems that act on the membrane's cells (chambers) add their
 * terms to its cell loop through CellTerms, so each cell matrix is
 * distributed once.
 */

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/numerics/data_out.h>

#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/core/vtu_series.h>
#include <pneuma/geometry/adaptive_refinement.h>
#include <pneuma/geometry/junctions.h>
#include <pneuma/geometry/scene_generator.h>
#include <pneuma/loads/boundary_conditions.h>
#include <pneuma/loads/rigid_regions.h>
#include <pneuma/membrane/bending/shell_bending.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/face_terms.h>
#include <pneuma/membrane/membrane_assembler.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    /// The membrane subsystem.
    class MembraneSubsystem : public Subsystem,
                              public MonitorPoints,
                              public NewtonAids,
                              public Inertia,
                              public LinearSolverHints,
                              public Refinable,
                              public Checkpointed,
                              public OutputFiles
    {
    public:
      explicit MembraneSubsystem(Model &model);
      ~MembraneSubsystem() override;

      /// "Geometry/Type"; declared whether or not a membrane is present.
      static void
      declare_switches(ParameterHandler &prm);
      /// A membrane unless Geometry/Type is none.
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "membrane";
      }

      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;

      types::global_dof_index
      setup_unknowns(const types::global_dof_index first,
                     const MPI_Comm                comm) override;
      void
      add_locally_owned(IndexSet &owned) const override;
      void
      add_locally_relevant(IndexSet &relevant) override;
      void
      add_kinematic_constraints(AffineConstraints<double> &c) const override;
      void
      add_update_constraints(AffineConstraints<double> &c) const override;
      void
      finish_setup() override;
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const override;
      /// The virial estimate sum (x_i - c).f_i / (2 A) of the mean
      /// membrane force (doc/theory.md "Stiffened start").
      double
      start_prestress(const LA::Vector &external) const override;
      void
      add_regularisation(const AffineConstraints<double> &constraints,
                         LA::SparseMatrix                &L) const override;
      void
      add_mass(const AffineConstraints<double> &constraints,
               LA::SparseMatrix                &M) const override;
      void
      add_lumped_mass(LA::Vector &m) const override;
      void
      largest_per_node(LA::Vector &v) const override;
      void
      stiffest_tangent(const bool on) override;
      void
      add_near_null_space(
        const IndexSet                   &owned,
        std::vector<std::vector<double>> &modes) const override;
      double
      initial_shift(
        const double                     factor,
        const UnknownRange              &range,
        const LA::SparseMatrix          &K,
        const LA::SparseMatrix          &L,
        const LA::Vector                &external,
        const AffineConstraints<double> &constraints) const override;

      void
      set_prescribed_values(const double t, LA::Vector &field) const override;
      void
      initialize(const LA::Vector &field, const double t) override;
      void
      assemble(const Assembly &a) override;
      std::string
      check_state(const LA::Vector &field) const override;
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field,
                     const double      t) const override;
      void
      add_output_fields(const LA::Vector &field, const double t) override;
      void
      add_mode_fields(const std::vector<std::string> &names,
                      const std::vector<LA::Vector>  &modes) override;
      void
      write_output_files(const std::string &directory,
                         const unsigned int step,
                         const double       t,
                         const LA::Vector  &field) override;

      // ---- for the subsystems that couple to the membrane
      /// Add terms to the membrane's cell loop (kept until destruction).
      void
      add_cell_terms(CellTerms &terms);
      /// Add terms on the cells' edges (membrane/face_terms.h; kept until
      /// destruction), before the model's setup: their couplings enter the
      /// sparsity pattern.
      void
      add_face_terms(FaceTerms &terms);
      const Mapping<2, 3> &
      mapping() const
      {
        return *mapping_cache;
      }
      const DoFHandler<2, 3> &
      dof_handler() const
      {
        return dofs;
      }
      const parallel::distributed::Triangulation<2, 3> &
      triangulation() const
      {
        return mesh;
      }
      const geometry::SceneGenerator &
      geometry() const
      {
        return scene;
      }
      unsigned int
      degree() const
      {
        return fe_degree;
      }
      /// The reference data of the membrane kernel (per owned cell, in
      /// cell order).
      const ReferenceGeometry &
      reference_geometry() const
      {
        return assembler->reference_geometry();
      }
      /// Number of monitor points (Output/Monitor points; known once the
      /// input is parsed).
      unsigned int
      n_monitor_points() const override
      {
        return monitor_points.size();
      }
      /// Global index of displacement component @p c of monitor point
      /// @p m on the one rank that reports it; invalid on the others
      /// (located at initialize()).
      types::global_dof_index
      monitor_dof(const unsigned int m, const unsigned int c) const override
      {
        return monitor_dofs[m][c];
      }
      /// The regions' materials (laws, thicknesses).
      const MaterialRegions &
      material_regions() const
      {
        return materials;
      }
      /// The material ids of the mesh (every rank).
      const std::set<types::material_id> &
      material_ids() const
      {
        return mesh_ids;
      }
      /// The shells' bending energy of this rank at the last assembly (0
      /// without shell regions).
      double
      bending_energy() const
      {
        return shell ? shell->energy() : 0.;
      }
      /// The membrane's VTU of the current output (between
      /// add_output_fields and write_output_files).
      DataOut<2, 3> &
      data_out()
      {
        return *output;
      }
      // ---- form finding (strategies/form_finding/form_finding.h)
      /**
       * Replace every region's law by the updated-reference law of its
       * prestress (membrane/form_finding_law.h) with homotopy factor
       * @p lambda; loads and prescribed values are off until
       * end_form_finding(). InputError naming the entry if a region has no
       * positive prestress, an anisotropic one with lambda > 0, or the
       * scene rigid regions or adaptive refinement.
       */
      void
      begin_form_finding(const double lambda);
      /// Move the reference surface by the membrane part of the ghosted
      /// @p field (X <- X + u) and return max |u| over the ranks.
      double
      move_reference(const LA::Vector &field);
      /// The regions' own laws again; analysis starts from the found shape.
      void
      end_form_finding();
      /// Diameter of the bounding box of the reference surface.
      double
      reference_diameter() const;
      /// The scale of the prestress forces (a prestress-driven step has
      /// no load): the largest prestress times the square root of the
      /// area.
      double
      force_scale(const LA::Vector &field) const override;

      unsigned int
      refinement_cycles() const override
      {
        return adaptive.cycles();
      }
      void
      refine(const LA::Vector &field) override;

    private:
      /// The mapping of the current mesh, its support points cached.
      void
      cache_mapping();
      /// The support points of this rank's dofs and the centroid of all
      /// owned ones over the ranks (the centre of the rigid rotations).
      Point<3>
      support_centroid(
        std::map<types::global_dof_index, Point<3>> &support) const;
      double
      prestress_force_scale() const;
      /// Area of the reference surface over the ranks, without the cells
      /// of the regions @p excluded.
      double
      reference_area(const std::set<types::material_id> &excluded = {}) const;
      /// Form finding: the consistent normal int N_i n dA of every node of
      /// the owned cells on the input surface (motion_direction).
      void
      compute_motion_directions();
      /// Form finding: every free node moves along its motion direction
      /// only (the tangential position of the nodes is the mesh's, not a
      /// physical unknown of an isotropic prestress; left free, a Q1 mesh
      /// twists into configurations of smaller discrete area).
      void
      add_normal_motion_constraints(AffineConstraints<double> &c) const;
      /// Masters that dependent dofs refer to (share_constraints.h).
      IndexSet
      shared_masters() const;
      void
      locate_monitor_points();
      /// The dofs of the vertex nearest to @p p (invalid except on the
      /// lowest rank that owns such a vertex) and its reference position
      /// (on every rank).
      std::pair<std::array<types::global_dof_index, 3>, std::array<double, 3>>
      nearest_vertex(const Point<3> &p) const;
      /// Find the point loads' vertices and say where they act.
      void
      locate_point_loads();
      /// Add the dead point loads at time @p t to @p residual (minus) and
      /// @p external (either may be nullptr); true if there are any and
      /// form finding is not on (the vectors then need compress(add)).
      bool
      add_point_loads(const double                     t,
                      const AffineConstraints<double> &constraints,
                      LA::Vector                      *residual,
                      LA::Vector                      *external) const;
      /// InputError naming the rigid-body motions the supports leave free
      /// (a warning when other subsystems may hold the membrane).
      void
      check_well_posed() const override;
      bool
      saves_own_field() const override
      {
        return true;
      }
      void
      save_checkpoint(
        Checkpoint                            &checkpoint,
        const std::vector<const LA::Vector *> &fields) const override;
      void
      load_checkpoint(const Checkpoint                &checkpoint,
                      const std::vector<LA::Vector *> &fields) override;
      void
      compute_reactions(const LA::Vector      &u,
                        const double           t,
                        std::array<double, 3> &reaction,
                        std::array<double, 3> &applied) const;

      Model                       &model;
      MPI_Comm                     comm;
      geometry::SceneGenerator     scene;
      geometry::AdaptiveRefinement adaptive;
      MaterialRegions              materials;
      loads::BoundaryConditions    boundary_conditions;
      loads::RigidRegions          rigid_regions;
      unsigned int                 fe_degree = 1;
      std::vector<Point<3>>        monitor_points;
      /// Output/Probe points (postprocess/membrane_probes.h).
      std::vector<Point<3>> probe_points;

      parallel::distributed::Triangulation<2, 3> mesh;
      bool                                       mesh_created = false;
      std::set<types::material_id>               mesh_ids;
      std::unique_ptr<FESystem<2, 3>>            fe;
      std::unique_ptr<Mapping<2, 3>>             mapping_cache;
      DoFHandler<2, 3>                           dofs;
      IndexSet                                   owned_dofs, relevant_dofs;
      geometry::JunctionTies                     junction_ties;
      std::unique_ptr<MembraneAssembler>         assembler;
      std::vector<CellTerms *>                   cell_terms;
      std::vector<FaceTerms *>                   face_terms;
      /// The shells' bending (regions with Bending = shell), its section.
      bending::Parameters                    bending_parameters;
      std::unique_ptr<bending::ShellBending> shell;
      double                                 reference_volume = 0.;
      /// Form finding: on, its force scale, the displacement of the
      /// reference from the input's surface (ghosted) and its updates.
      bool                                            form_finding    = false;
      double                                          prestress_force = 0.;
      LA::Vector                                      reference_shift;
      std::map<types::global_dof_index, Tensor<1, 3>> motion_direction;
      /// Force and moment about the origin of each supported boundary at
      /// the last compute_reactions().
      mutable std::map<types::boundary_id, std::array<double, 6>>
                   boundary_reactions;
      unsigned int form_finding_updates = 0;

      // Monitor points: (owning rank's) dof indices of the nearest vertex.
      std::vector<std::array<types::global_dof_index, 3>> monitor_dofs;
      std::vector<std::array<double, 3>>                  monitor_positions;
      // Point loads: (owning rank's) dof indices of the nearest vertex.
      std::vector<std::array<types::global_dof_index, 3>> point_load_dofs;

      std::unique_ptr<DataOut<2, 3>> output;
      /// solution.pvd over the solution_NNNN.pvtu files.
      VtuSeries                  series{"solution"};
      std::vector<Vector<float>> output_cell_data;
    };
  } // namespace membrane
} // namespace pneuma
