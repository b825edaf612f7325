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
 * (begin, check, commit, reject) and adds named statistics with units.
 * What only some subsystems have (Newton's aids, mass, refinement,
 * checkpoint state, output files, ...) are the optional capability
 * interfaces of core/capabilities.h. The Model (core/model.h) loops over
 * the subsystems a scene activates, in their registration order; a scene
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
    /// Where a subsystem reports that its tangent in this assembly is not
    /// symmetric (a slipping friction point): it sets the flag to false
    /// (nullptr: nobody asks). An assembly changes no subsystem's state;
    /// what a subsystem records of a state it records in refresh().
    bool *symmetric = nullptr;
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
    /// Before a run's first factorization: throw an InputError naming
    /// what the scene leaves free (rigid-body motions, unsupported
    /// bodies). Not called by finite-difference checks of the tangent.
    virtual void
    check_well_posed() const
    {
    }

    // ---- the life of a step
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
    /// Whether border() predicts the unknowns at the start of a step (a
    /// chamber's pressure from the field); if not, a step starts from the
    /// strategy's own values (the last state, or its extrapolation), and
    /// border() is only the accepted state's.
    virtual bool
    predicts_border() const
    {
      return true;
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
    // ---- reporting
    /// Add named values with units at the converged state @p field
    /// (ghosted) at pseudo time @p t; the reactions come from
    /// Model::support_residual().
    virtual void
    add_statistics(Statistics       &statistics,
                   const LA::Vector &field,
                   const double      t) const
    {
      (void)statistics;
      (void)field;
      (void)t;
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
