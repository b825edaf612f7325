#pragma once

/**
 * @file
 * The cables of a scene as one block of the global system
 * (doc/theory.md §8, doc/user-guide.md "Cables").
 *
 * Each cable has its own `Triangulation<1,3>` and `DoFHandler<1,3>`; every
 * rank holds the whole cable mesh (p4est does not distribute 1D meshes).
 * The cable unknowns follow the membrane unknowns in the global numbering:
 * cable k's dof i is global index first + offset_k + i. Rank 0 owns all
 * cable dofs; every rank sees them (ghosts) and assembles a contiguous
 * share of the elements into rank 0's rows; later couplings (contact) add
 * off-diagonal blocks to the same matrix.
 *
 * Unknowns per node: those of the cable's element (cable_element.h), the
 * displacement of the mid-line first (the cable element: 3; the solid
 * beam: 9, with the changes of the two section semi-axis vectors). The
 * cable system builds each mesh from the cable's shape (cable_shape.h),
 * holds the supports and applies the dead loads on the mid-line, and asks
 * the element for the cell terms; it does not know which element a cable
 * uses. A scene without cables has no cable unknowns and does no cable
 * work.
 */

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <pneuma/cables/cable_parameters.h>
#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/vtu_series.h>
#include <pneuma/loads/loads.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pneuma
{
  class Checkpoint;

  namespace cables
  {
    /// What a cable reports after a converged step.
    struct CableReport
    {
      /// Largest and smallest axial force along the cable [N].
      double max_force = 0., min_force = 0.;
      /// Current length of the mid-line [m].
      double length = 0.;
      /// Support reactions at the start and end (force on the cable) [N].
      std::array<double, 3> start_reaction{{0., 0., 0.}},
        end_reaction{{0., 0., 0.}};
      /// Displacement of the start, end, and middle node [m].
      std::array<double, 3> start_displacement{{0., 0., 0.}},
        end_displacement{{0., 0., 0.}}, mid_displacement{{0., 0., 0.}};
      /// Largest bending and torsion moments [N m] (zero for an element
      /// without moments).
      double max_bending = 0., max_torsion = 0.;
      /// With an end moment: rotation of the end section about the moment
      /// axis since the start [rad].
      double end_rotation = 0.;
    };

    /// What the contact needs to know of one cable.
    struct CableView
    {
      const DoFHandler<1, 3> *dof_handler = nullptr;
      /// Global index of the cable's local dof 0.
      types::global_dof_index offset = 0;
      /// Reference value of every local dof (positions in components 0-2).
      const Vector<double> *reference = nullptr;
      /// Larger semi-axis of the section [m].
      double radius = 0.;
      /// The components of the section semi-axis vectors a1, a2
      /// (CableElement::section_vector_components(); empty: none).
      std::vector<unsigned int> section_components;
    };

    /// The cable block of the global system.
    class CableSystem
    {
    public:
      CableSystem(const CableParameters &parameters, const loads::Loads &loads);
      ~CableSystem();

      /// Build the meshes and number the cable dofs from @p first on.
      void
      setup(const types::global_dof_index first, const MPI_Comm comm);

      bool
      empty() const
      {
        return bodies.empty();
      }
      /// Number of cable unknowns.
      types::global_dof_index
      n_dofs() const
      {
        return n_cable_dofs;
      }
      /// Mesh, dofs and reference of cable @p k.
      CableView
      view(const unsigned int k) const;

      /**
       * The global dofs of every node of cable @p k (each node's components
       * in the element's order: position first), in mesh order; with
       * @p ends_only, the start node and the end node of an open cable.
       */
      std::vector<std::vector<types::global_dof_index>>
      node_dofs(const unsigned int k, const bool ends_only) const;

      /// Extra cell fields of cable @p k for the next write_output() (e.g.
      /// the contact line load), by name.
      void
      set_output_field(const unsigned int    k,
                       const std::string    &name,
                       const Vector<double> &values);

      /// Largest axial stiffness EA of the cables [N].
      double
      axial_stiffness() const;
      /// Number of cable elements.
      unsigned int
      n_cells() const;
      /// The cable dofs owned here (all on rank 0), in a set of @p size.
      IndexSet
      locally_owned_dofs(const types::global_dof_index size) const;
      /// All cable dofs, in a set of @p size.
      IndexSet
      all_dofs(const types::global_dof_index size) const;

      /// Homogeneous constraints of the supported end dofs (for the Newton
      /// update).
      void
      add_support_constraints(AffineConstraints<double> &constraints) const;
      /**
       * The first guess of a run's first step (owned entries of
       * @p solution): a cable or beam whose straight reference is shorter
       * than its unstressed length L0 is sagged into the parabola of
       * length L0 along the part of its dead load (gravity, distributed
       * load at @p t and the middle) normal to the chord, its sections
       * turned with the mid-line. Others are left as they are.
       */
      void
      first_guess(const double t, LA::Vector &solution) const;
      /// Set the supported end dofs of @p solution to their prescribed
      /// values at pseudo time @p t (owned entries).
      void
      set_prescribed_values(const double t, LA::Vector &solution) const;
      /// The couplings of the cable elements.
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const;

      /**
       * Add the cable terms at @p u (ghosted: every cable unknown) to the
       * residual r = f_int - f_ext, the tangent and the external load
       * vector (each may be nullptr); compresses what it touched.
       */
      void
      assemble(const double                     t,
               const LA::Vector                &u,
               const AffineConstraints<double> &constraints,
               LA::SparseMatrix                *tangent,
               LA::Vector                      *residual,
               LA::Vector                      *external) const;

      /// The regularisation matrix of the pseudo-time continuation: the
      /// geometric stiffness of a unit axial force, int N_i' N_j' dS.
      void
      assemble_regularisation(const AffineConstraints<double> &constraints,
                              LA::SparseMatrix                &matrix) const;

      /// The consistent mass of the mid-lines' translations, int rho A
      /// N_i N_j dS over the reference curve (section unknowns of a solid
      /// beam carry none).
      void
      assemble_mass(const AffineConstraints<double> &constraints,
                    LA::SparseMatrix                &matrix) const;
      /// The lumped mass of the mid-line translations (the row sums of
      /// assemble_mass()) into @p m (added; all ranks call).
      void
      lumped_mass(LA::Vector &m) const;
      /// The owned entries of @p v on each node's three translations set
      /// to their largest (the section unknowns keep theirs).
      void
      largest_per_node(LA::Vector &v) const;

      /// Mode shapes (global vectors) to add as nodal fields to the next
      /// write_output(), by name.
      void
      set_mode_fields(const std::vector<std::string> &names,
                      const std::vector<LA::Vector>  &modes);

      /// For the AMG near-null space: the displacement component (0..2) of
      /// owned cable dof @p i, or -1 (an element's further unknowns).
      int
      translation_component(const types::global_dof_index i) const;

      /// Accept the converged state @p u (tracks the end-section rotation
      /// of a cable loaded by an end moment).
      void
      commit_step(const LA::Vector &u);
      /// Checkpoint: the committed state of every cable (rank 0's) and
      /// the .pvd records.
      void
      save_checkpoint(Checkpoint &checkpoint) const;
      void
      load_checkpoint(const Checkpoint &checkpoint);

      /**
       * Reports of every cable at @p u (valid on rank 0). The end reactions
       * are the support residual @p support (Model::support_residual: the
       * whole residual at the held end dofs, contact forces on the end
       * elements included); without it they are left 0.
       */
      std::vector<CableReport>
      reports(const double      t,
              const LA::Vector &u,
              const LA::Vector *support = nullptr) const;

      /// The prestress force of @p d at pseudo time @p t (its Prestress
      /// factor f(t) times the Prestress force, times the ramp of
      /// ramp_initial_loads()).
      double
      staged_prestress(const CableDefinition &d, const double t) const;

      /**
       * The automatic first step (Subsystem::ramp_initial_loads): every
       * cable in tension at @p t0 (a Prestress force acting there, or an
       * Unstressed length shorter than the cable) takes it with the factor
       * min(1, (t - t0)/(t1 - t0)) from now on: rho = 1 + h (rho_full - 1).
       * Returns whether some cable is in tension at @p t0. A slack cable
       * (rho < 1) is left as it is. @p t1 <= @p t0 removes the ramp.
       */
      bool
      ramp_initial_loads(const double t0, const double t1);

      /// Throws an InputError naming the Prestress factor of a cable whose
      /// staged prestress is not finite at @p t (on every rank alike).
      void
      check_prestress(const double t) const;

      /// Write cables_<k>_<step>.vtu and the cables.pvd record (rank 0).
      void
      write_output(const std::string &directory,
                   const unsigned int step,
                   const double       t,
                   const LA::Vector  &u);

    private:
      /// rho = 1 + f(t) F/EA of every cable with a staged prestress, and
      /// the ramped rho of every cable while ramp_initial_loads() acts.
      void
      stage_prestress(const double t) const;
      /// The ramp factor min(1, (t - t0)/(t1 - t0)) (1 without a ramp).
      double
      ramp_factor(const double t) const;
      /// The ramp of ramp_initial_loads() (none while ramp_end <= start).
      double ramp_start = 0., ramp_end = 0.;
      struct Body;

      /// Per-cell element terms in the local numbering of body @p b.
      void
      cell_terms(const Body                                   &b,
                 const DoFHandler<1, 3>::active_cell_iterator &cell,
                 const double                                  t,
                 const Vector<double>                         &local_u,
                 FullMatrix<double>                           *cell_matrix,
                 Vector<double>                               *cell_residual,
                 Vector<double>                               *cell_external,
                 CableCellOutput *cell_output) const;

      /// Does this rank assemble element @p element (numbered over all
      /// bodies in mesh order)? Contiguous ranges, one per rank.
      bool
      assembles(const std::size_t element) const;

      /// The body's dofs of @p u (replicated local copy).
      Vector<double>
      extract(const Body &b, const LA::Vector &u) const;

      const CableParameters             &parameters;
      const loads::Loads                &loads;
      MPI_Comm                           comm     = MPI_COMM_SELF;
      bool                               is_owner = true;
      unsigned int                       rank = 0, n_ranks = 1;
      std::vector<std::unique_ptr<Body>> bodies;
      types::global_dof_index            first = 0, n_cable_dofs = 0;
      /// cables.pvd over one cables_<k>_NNNN.vtu per cable (part) and step.
      VtuSeries series{"cables"};
      std::vector<std::vector<std::pair<std::string, Vector<double>>>>
        extra_fields;
      /// Per cable: the mode shapes of the next write_output().
      std::vector<std::vector<std::pair<std::string, Vector<double>>>>
        mode_fields;
    };
  } // namespace cables
} // namespace pneuma
