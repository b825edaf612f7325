#pragma once

/**
 * @file
 * The interface that every physics of the coupled system implements: the
 * membrane, the chambers, the cables and the contact today; shells, ties
 * or an arc-length constraint later (doc/architecture.md).
 *
 * A subsystem declares and parses its own parameters, adds its unknowns
 * (field dofs numbered after the subsystems before it, or a few border
 * unknowns), its constraints and sparsity couplings, assembles its residual
 * and tangent contributions for a state, takes part in the life of a step
 * (begin, check, commit, reject), adds named statistics with units, and
 * writes its output fields. The Model (core/model.h) loops over the
 * subsystems a scene activates, in their registration order; a scene
 * without cables builds no cable subsystem. No subsystem knows the
 * solution strategy that drives the model.
 *
 * A subsystem is registered once, in its own .cc file:
 * @code
 * PNEUMA_REGISTER_SUBSYSTEM(CableSubsystem, "cables", 20,
 *                           CableSubsystem::declare_switches,
 *                           CableSubsystem::is_active);
 * @endcode
 */

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/statistics.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class Checkpoint;
  class InputLayout;
  class Model;

  namespace solvers
  {
    struct BorderCoupling;
  }

  /// What one assembly pass fills (every target may be nullptr).
  struct Assembly
  {
    /// Pseudo time of the loads.
    double time = 0.;
    /// The field, ghosted, and the (scaled) border unknowns.
    const LA::Vector             *field  = nullptr;
    const dealii::Vector<double> *border = nullptr;
    /// Constraints to distribute with.
    const dealii::AffineConstraints<double> *constraints = nullptr;
    /// r = f_int - f_ext, the tangent dr/du, the external load vector.
    LA::Vector       *residual = nullptr;
    LA::SparseMatrix *tangent  = nullptr;
    LA::Vector       *external = nullptr;
    /// Residual rows of the border (scaled) and its Jacobian blocks.
    dealii::Vector<double>  *border_residual = nullptr;
    solvers::BorderCoupling *coupling        = nullptr;
    /// An assembly for a report (Model::support_residual): subsystems keep
    /// the state their assembly records (contact points, friction anchors).
    bool probe = false;
  };

  /// A contiguous range [first, first + size) of global unknowns.
  struct UnknownRange
  {
    dealii::types::global_dof_index first = 0, size = 0;
  };

  /// One physics of the coupled system.
  class Subsystem
  {
  public:
    virtual ~Subsystem() = default;

    /// Name in messages and in the convergence table ("membrane").
    virtual std::string
    name() const = 0;

    // ---- parameters
    /// Declare the parameters of the instances @p layout names; entries
    /// are bound to members (ParameterHandler::add_parameter).
    virtual void
    declare_parameters(dealii::ParameterHandler &prm,
                       const InputLayout        &layout) = 0;
    /// Check and derive after the input is read; throws InputError naming
    /// the entry.
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;
    /// Cross-checks with the other subsystems of the model (all parsed).
    virtual void
    check_parameters(const Model &model)
    {
      (void)model;
    }

    // ---- setup, called in this order by Model::setup()
    /// Build meshes; number the field unknowns from @p first on; returns
    /// their number.
    virtual dealii::types::global_dof_index
    setup_unknowns(const dealii::types::global_dof_index first,
                   const MPI_Comm                        comm)
    {
      (void)first;
      (void)comm;
      return 0;
    }
    /// Owned field unknowns (in the global numbering of @p n_total).
    virtual void
    add_locally_owned(dealii::IndexSet &owned) const
    {
      (void)owned;
    }
    /// Field unknowns this rank must see (ghosts, couplings to other
    /// subsystems); may search the mesh.
    virtual void
    add_locally_relevant(dealii::IndexSet &relevant)
    {
      (void)relevant;
    }
    /// Number of border unknowns (few global scalars, see solvers/border.h).
    virtual unsigned int
    n_border_unknowns() const
    {
      return 0;
    }
    /// Kinematic constraints: hanging nodes, rigid plates, ties.
    virtual void
    add_kinematic_constraints(dealii::AffineConstraints<double> &c) const
    {
      (void)c;
    }
    /// Homogeneous constraints of the Newton update at prescribed dofs.
    virtual void
    add_update_constraints(dealii::AffineConstraints<double> &c) const
    {
      (void)c;
    }
    /// Everything that needs the final numbering and constraints.
    virtual void
    finish_setup()
    {
    }
    /// Couplings of the tangent.
    virtual void
    add_sparsity(dealii::DynamicSparsityPattern          &dsp,
                 const dealii::AffineConstraints<double> &constraints) const
    {
      (void)dsp;
      (void)constraints;
    }
    /// The regularisation matrix of the continuation: the geometric
    /// stiffness of a unit prestress on the subsystem's unknowns.
    virtual void
    add_regularisation(const dealii::AffineConstraints<double> &constraints,
                       LA::SparseMatrix                        &L) const
    {
      (void)constraints;
      (void)L;
    }
    /**
     * The mass matrix of the eigen analysis (solvers/eigen_analysis.h):
     * the consistent mass of this subsystem's translations in the
     * reference configuration (density times thickness or section area),
     * distributed with @p constraints into @p M (the tangent's pattern).
     */
    virtual void
    add_mass(const dealii::AffineConstraints<double> &constraints,
             LA::SparseMatrix                        &M) const
    {
      (void)constraints;
      (void)M;
    }
    /**
     * Near-null-space vectors for AMG over the owned dofs (in the order of
     * @p owned), filled where this subsystem owns dofs: modes 0-2 the
     * rigid translations, 3-5 the rotations (left zero if the subsystem
     * has none).
     */
    virtual void
    add_near_null_space(const dealii::IndexSet           &owned,
                        std::vector<std::vector<double>> &modes) const
    {
      (void)owned;
      (void)modes;
    }
    /**
     * The first continuation shift this subsystem proposes for a shift
     * @p factor relative to its stiffness scale (0: no proposal; the first
     * proposal in subsystem order is taken): e.g. factor mean(diag K) /
     * mean(diag L) over the subsystem's unconstrained dofs @p range.
     */
    virtual double
    initial_shift(const double                             factor,
                  const UnknownRange                      &range,
                  const LA::SparseMatrix                  &K,
                  const LA::SparseMatrix                  &L,
                  const LA::Vector                        &external,
                  const dealii::AffineConstraints<double> &constraints) const
    {
      (void)factor;
      (void)range;
      (void)K;
      (void)L;
      (void)external;
      (void)constraints;
      return 0.;
    }

    /**
     * Newton's stiffened start (solvers/newton_solver.h): an isotropic
     * membrane force (N/m) estimated from the applied loads @p external
     * (owned) or from this subsystem's own loads at the state last
     * assembled (a chamber's pressure), whose geometric stiffness makes
     * the first solve from an unstressed state well posed and free of the
     * linear solution's kinks; 0: no proposal (the proposals add up).
     */
    virtual double
    start_prestress(const LA::Vector &external) const
    {
      (void)external;
      return 0.;
    }

    /**
     * False if this subsystem's tangent, as last assembled, is not
     * symmetric by construction (the smoothed master normal's contact
     * force, a slipping friction point; asked after each Newton assembly,
     * the same answer on every rank): the direct solver then
     * takes the LU path, whatever the measured asymmetry of the assembled
     * matrix (a random projection that a small, local asymmetric part
     * passes below its threshold).
     */
    virtual bool
    symmetric_tangent() const
    {
      return true;
    }
    /// Adaptive refinement: cycles after the first run (0: none).
    virtual unsigned int
    refinement_cycles() const
    {
      return 0;
    }
    /// Refine by an error indicator of the converged @p field (ghosted);
    /// the model is set up again afterwards.
    virtual void
    refine(const LA::Vector &field)
    {
      (void)field;
    }

    /// Before a run's first factorization: throw an InputError naming
    /// what the scene leaves free (rigid-body motions, unsupported
    /// bodies). Not called by finite-difference checks of the tangent.
    virtual void
    check_well_posed() const
    {
    }

    // ---- the life of a step
    /**
     * The first step of a run starts from the reference state: write a
     * first guess of this subsystem's free unknowns for the step to @p t
     * into the owned entries of @p field (a cable that is slack in its
     * straight reference hangs along its load, so that Newton does not
     * settle on the straight, compressed equilibrium). Prescribed values
     * are written afterwards.
     */
    virtual void
    first_guess(const double t, LA::Vector &field) const
    {
      (void)t;
      (void)field;
    }
    /**
     * The automatic first step (Load stepping/Initial prestress): loads
     * that act in full from the start of the run whatever the load curves
     * (a cable's prestress or short unstressed length) grow from zero at
     * @p t0 to full at @p t1 with the factor min(1, (t - t0)/(t1 - t0)),
     * so that a cut back reduces them with the other loads; @p t1 <= @p t0
     * removes the ramp (a new run). Returns whether this subsystem has
     * such loads (the same on every rank).
     */
    virtual bool
    ramp_initial_loads(const double t0, const double t1)
    {
      (void)t0;
      (void)t1;
      return false;
    }
    /// Write the prescribed values at pseudo time @p t into the owned
    /// entries of @p field.
    virtual void
    set_prescribed_values(const double t, LA::Vector &field) const
    {
      (void)t;
      (void)field;
    }
    /// The reference state at pseudo time @p t (ghosted @p field; 0 at the
    /// start of a run).
    virtual void
    initialize(const LA::Vector &field, const double t)
    {
      (void)field;
      (void)t;
    }
    /**
     * Prepare the step to @p t from the state @p field (ghosted): renew
     * contact candidates, predict border unknowns. Sets @p grown if the
     * sparsity pattern must be rebuilt. Returns an empty string, or why
     * the step is impossible (it is then reported as a failure).
     */
    virtual std::string
    begin_step(const double t, const LA::Vector &field, bool &grown)
    {
      (void)t;
      (void)field;
      (void)grown;
      return "";
    }
    /// This subsystem's border unknowns (scaled) for the step just begun.
    virtual dealii::Vector<double>
    border() const
    {
      return {};
    }
    /// Assemble this subsystem's contributions into @p assembly.
    virtual void
    assemble(const Assembly &assembly) = 0;
    /// Why a converged state is not admissible (e.g. the surface turned
    /// inside out), or an empty string.
    virtual std::string
    check_state(const LA::Vector &field) const
    {
      (void)field;
      return "";
    }
    /// Accept the converged state at @p t (@p border: this subsystem's
    /// part).
    virtual void
    commit_step(const double                  t,
                const LA::Vector             &field,
                const dealii::Vector<double> &border)
    {
      (void)t;
      (void)field;
      (void)border;
    }
    /// The step begun last was rejected (Newton failed or the state was
    /// not admissible): forget what begin_step() predicted; the strategy
    /// restores the field and border of the last converged state.
    virtual void
    reject_step()
    {
    }
    /// Reports of a converged state that need the final assembly (contact
    /// points at the accepted state).
    virtual void
    refresh(const LA::Vector &field)
    {
      (void)field;
    }
    /// Force scale of this subsystem's loads at the current state, for
    /// Newton's residual reference.
    virtual double
    force_scale(const LA::Vector &field) const
    {
      (void)field;
      return 0.;
    }

    // ---- checkpoint and restart (core/checkpoint.h)
    /**
     * Does this subsystem save and restore its own field values (the
     * membrane, through p4est with its mesh)? Otherwise the model stores
     * the values of its range, gathered on rank 0.
     */
    virtual bool
    saves_own_field() const
    {
      return false;
    }
    /**
     * Store what a restart needs besides the field and the border (all
     * ranks call it; sections put on rank 0 are the ones written).
     * @p fields (ghosted): the converged field first, then the other
     * whole-model vectors the load path keeps (the last step's increment,
     * its predictor); a subsystem that saves its own field saves all.
     */
    virtual void
    save_checkpoint(Checkpoint                            &checkpoint,
                    const std::vector<const LA::Vector *> &fields) const
    {
      (void)checkpoint;
      (void)fields;
    }
    /**
     * Restore that state (the model is set up and initialized at t = 0);
     * a subsystem that saves its own field writes its owned entries of
     * each of @p fields (as many as were saved) here.
     */
    virtual void
    load_checkpoint(const Checkpoint                &checkpoint,
                    const std::vector<LA::Vector *> &fields)
    {
      (void)checkpoint;
      (void)fields;
    }
    // ---- reporting
    /// True if add_statistics() reads Model::support_residual() (it costs
    /// one residual assembly of every subsystem per report).
    virtual bool
    needs_support_residual() const
    {
      return false;
    }
    /// True if add_statistics() reads Model::unconstrained_residual() (one
    /// more residual assembly of every subsystem per report).
    virtual bool
    needs_unconstrained_residual() const
    {
      return false;
    }
    /// Add named values with units at the converged state @p field.
    virtual void
    add_statistics(Statistics &statistics, const LA::Vector &field) const
    {
      (void)statistics;
      (void)field;
    }
    /// Output, phase 1: add fields of the state (ghosted @p field) to the
    /// outputs of this or other subsystems (e.g. contact pressure on the
    /// membrane's VTU).
    virtual void
    add_output_fields(const LA::Vector &field)
    {
      (void)field;
    }
    /**
     * Output, between phases 1 and 2: add the mode shapes @p modes
     * (ghosted global vectors, alive until phase 2) of an eigen analysis
     * as fields named @p names (e.g. "mode_1") to this subsystem's output.
     */
    virtual void
    add_mode_fields(const std::vector<std::string> &names,
                    const std::vector<LA::Vector>  &modes)
    {
      (void)names;
      (void)modes;
    }
    /// Output, phase 2: write this subsystem's files for @p step into
    /// @p directory (VTU, PVTU, PVD records).
    virtual void
    write_output_files(const std::string &directory,
                       const unsigned int step,
                       const double       t,
                       const LA::Vector  &field)
    {
      (void)directory;
      (void)step;
      (void)t;
      (void)field;
    }
  };

  /// How to make one kind of subsystem (see PNEUMA_REGISTER_SUBSYSTEM).
  struct SubsystemEntry
  {
    std::string name;
    /// Position among the subsystems: field unknowns are numbered and
    /// assembled in this order.
    int order = 0;
    /// Entries that decide whether the subsystem is present (e.g. the
    /// number of cables); declared even when it is absent.
    std::function<void(dealii::ParameterHandler &)> declare_switches;
    /// Is it present in a run with this layout?
    std::function<bool(const InputLayout &)> is_active;
    /// Make it (the model gives access to the subsystems before it).
    std::function<std::unique_ptr<Subsystem>(Model &)> create;
  };

  /// The registered subsystems, in order.
  const std::vector<SubsystemEntry> &
  subsystem_entries();

  /// Register a subsystem (used by PNEUMA_REGISTER_SUBSYSTEM).
  bool
  register_subsystem(const SubsystemEntry &entry);
} // namespace pneuma

#define PNEUMA_CONCAT_IMPL(a, b) a##b
#define PNEUMA_CONCAT(a, b) PNEUMA_CONCAT_IMPL(a, b)

/**
 * Register the subsystem class @p Class (constructible from Model &) under
 * @p name at position @p order, with its switch declaration and activity
 * test (static functions). Use once per class, at namespace scope.
 */
#define PNEUMA_REGISTER_SUBSYSTEM(Class, name, order, switches, active) \
  namespace                                                             \
  {                                                                     \
    const bool PNEUMA_CONCAT(pneuma_registered_subsystem_, __LINE__) =  \
      ::pneuma::register_subsystem(                                     \
        {name, order, switches, active, [](::pneuma::Model &model) {    \
           return std::unique_ptr<::pneuma::Subsystem>(                 \
             std::make_unique<Class>(model));                           \
         }});                                                           \
  }
