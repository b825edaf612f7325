#pragma once

/**
 * @file
 * Optional capabilities of a subsystem (doc/architecture.md "The subsystem
 * interface"): a Subsystem (core/subsystem.h) implements the physics hooks
 * every subsystem has; what only some have, or only some strategies use,
 * is one of these interfaces, which a subsystem derives from when it needs
 * it. The Model finds them by type (Model::with<Capability>()).
 *
 * | capability       | for                                               |
 * |------------------|---------------------------------------------------|
 * | NewtonAids       | Newton's continuation, stiffened start, first guess,
 * ramped prestress, force scale | | Inertia          | mass: consistent (modal
 * analysis) and lumped (explicit strategies) | | LinearSolverHints| near-null
 * space for AMG, a tangent that is not symmetric | | Refinable        |
 * adaptive refinement                                | | Checkpointed     |
 * history state and own field in checkpoints        | | OutputFiles      |
 * fields and files of the VTU output                | | Holds            |
 * holds another subsystem's dofs (contact, ties)    | | MonitorPoints    |
 * monitored points (path following, reports)        | | BorderFromField  |
 * border unknowns evaluated for a given field       |
 */

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/subsystem.h>

#include <string>
#include <vector>

namespace pneuma
{
  class Checkpoint;

  /// What Newton's method (solvers/newton_solver.h) asks of a subsystem
  /// beyond its residual and tangent; every hook has a neutral default.
  class NewtonAids
  {
  public:
    virtual ~NewtonAids() = default;
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
     * Newton's stiffened start: an isotropic membrane force (N/m)
     * estimated from the applied loads @p external (owned) or from this
     * subsystem's own loads at the state last assembled (a chamber's
     * pressure), whose geometric stiffness makes the first solve from an
     * unstressed state well posed and free of the linear solution's kinks;
     * 0: no proposal (the proposals add up).
     */
    virtual double
    start_prestress(const LA::Vector &external) const
    {
      (void)external;
      return 0.;
    }
    /**
     * The first step of a run starts from the reference state: write a
     * first guess of this subsystem's free unknowns for the step to @p t
     * into the owned entries of @p field (a cable that is slack in its
     * straight reference hangs along its load). Prescribed values are
     * written afterwards.
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
     * @p t0 to full at @p t1, so that a cut back reduces them with the
     * other loads; @p t1 <= @p t0 removes the ramp (a new run). Returns
     * whether this subsystem has such loads (the same on every rank).
     */
    virtual bool
    ramp_initial_loads(const double t0, const double t1)
    {
      (void)t0;
      (void)t1;
      return false;
    }
    /// Force scale of this subsystem's loads at the current state, for
    /// Newton's residual reference.
    virtual double
    force_scale(const LA::Vector &field) const
    {
      (void)field;
      return 0.;
    }
  };

  /// Mass, for modal analyses and explicit strategies.
  class Inertia
  {
  public:
    virtual ~Inertia() = default;
    /**
     * The consistent mass of this subsystem's translations in the
     * reference configuration (density times thickness or section area),
     * distributed with @p constraints into @p M (the tangent's pattern).
     */
    virtual void
    add_mass(const dealii::AffineConstraints<double> &constraints,
             LA::SparseMatrix                        &M) const = 0;
    /**
     * The lumped (diagonal) mass of the same translations into the owned
     * entries of @p m: the row sums of the consistent mass, positive for
     * the Lagrange elements used (doc/theory.md "Mass"). Unknowns without
     * an inertia of their own here (a solid beam's section directors) are
     * left 0.
     */
    virtual void
    add_lumped_mass(LA::Vector &m) const = 0;
    /**
     * Replace the owned entries of @p v on this subsystem's translation
     * dofs by their largest value over the components of each node (a
     * fictitious mass the same in every direction of a node: dynamic
     * relaxation). The default leaves @p v as it is.
     */
    virtual void
    largest_per_node(LA::Vector &v) const
    {
      (void)v;
    }
    /**
     * While @p on, assemble the tangent of the stiffest state each point
     * can reach (a membrane's laws without tension field: slack points as
     * stiff as taut ones), which bounds the stiffness along a relaxation
     * (Model::assemble_stiffest_tangent). The default changes nothing.
     */
    virtual void
    stiffest_tangent(const bool on)
    {
      (void)on;
    }
  };

  /// What the linear solver may use of a subsystem.
  class LinearSolverHints
  {
  public:
    virtual ~LinearSolverHints() = default;
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
     * False if this subsystem's tangent, as last assembled, is not
     * symmetric by construction (the smoothed master normal's contact
     * force, a slipping friction point; the same answer on every rank):
     * the direct solver then takes the LU path.
     */
    virtual bool
    symmetric_tangent() const
    {
      return true;
    }
  };

  /// Adaptive refinement of the subsystem's mesh.
  class Refinable
  {
  public:
    virtual ~Refinable() = default;
    /// Cycles after the first run (0: none).
    virtual unsigned int
    refinement_cycles() const = 0;
    /// Refine by an error indicator of the converged @p field (ghosted);
    /// the model is set up again afterwards.
    virtual void
    refine(const LA::Vector &field) = 0;
  };

  /// Checkpoint and restart (core/checkpoint.h).
  class Checkpointed
  {
  public:
    virtual ~Checkpointed() = default;
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
     * whole-model vectors the strategy keeps; a subsystem that saves its
     * own field saves all.
     */
    virtual void
    save_checkpoint(Checkpoint                            &checkpoint,
                    const std::vector<const LA::Vector *> &fields) const = 0;
    /**
     * Restore that state (the model is set up and initialized at t = 0);
     * a subsystem that saves its own field writes its owned entries of
     * each of @p fields (as many as were saved) here.
     */
    virtual void
    load_checkpoint(const Checkpoint                &checkpoint,
                    const std::vector<LA::Vector *> &fields) = 0;
  };

  /// Fields and files of the output.
  class OutputFiles
  {
  public:
    virtual ~OutputFiles() = default;
    /// Phase 1: add fields of the state (ghosted @p field) at pseudo time
    /// @p t to the outputs of this or other subsystems (contact pressure
    /// on the membrane's).
    virtual void
    add_output_fields(const LA::Vector &field, const double t)
    {
      (void)field;
      (void)t;
    }
    /// Between phases 1 and 2: add the mode shapes @p modes (ghosted,
    /// alive until phase 2) of an eigen analysis as fields @p names.
    virtual void
    add_mode_fields(const std::vector<std::string> &names,
                    const std::vector<LA::Vector>  &modes)
    {
      (void)names;
      (void)modes;
    }
    /// Phase 2: write this subsystem's files for @p step into
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

  /// A subsystem that may hold another one's dofs in place (contact with
  /// supported cables, ties): the other's free rigid motions are then not
  /// an error of the input.
  class Holds
  {
  public:
    virtual ~Holds() = default;
    virtual bool
    holds(const Subsystem &other) const = 0;
  };

  /**
   * Points of the structure whose displacement is monitored (Output/
   * Monitor points): a strategy controls or reports them through
   * Model::monitor_dof().
   */
  class MonitorPoints
  {
  public:
    virtual ~MonitorPoints() = default;
    /// Number of monitor points.
    virtual unsigned int
    n_monitor_points() const = 0;
    /// Global index of displacement component @p c of monitor point @p m
    /// on the one rank that reports it; invalid on the others.
    virtual dealii::types::global_dof_index
    monitor_dof(const unsigned int m, const unsigned int c) const = 0;
  };

  /**
   * A border row that is a constraint on the field, g(u, t) = 0, held by
   * its unknown as a Lagrange multiplier (a chamber's prescribed volume,
   * held by its pressure): no value of the unknown satisfies it for a
   * given field, so a strategy without a matrix moves the field instead
   * (strategies/border_projection.h). @p row: the row among the
   * subsystem's (the model's, from Model::border_for()); @p value: g in
   * its physical unit; @p scale: the size that makes it relative (the
   * prescribed volume); @p unit: the unknown's scale in the border vector
   * (the physical multiplier is the border entry times @p unit).
   */
  struct BorderConstraint
  {
    unsigned int row   = 0;
    double       value = 0., scale = 1., unit = 1.;
  };

  /**
   * Border unknowns evaluated for a given field, without Newton (what an
   * explicit strategy needs): the values that satisfy this subsystem's
   * border equations at @p field (ghosted) and pseudo time @p t (a gas
   * pressure from its law at the current volume, a liquid level that holds
   * the liquid's volume). The unknowns of constraint rows keep their value
   * in @p border (scaled, this subsystem's part); those rows and their
   * values at @p field go to @p constraints.
   */
  class BorderFromField
  {
  public:
    virtual ~BorderFromField() = default;
    virtual dealii::Vector<double>
    border_for(const LA::Vector              &field,
               const double                   t,
               const dealii::Vector<double>  &border,
               std::vector<BorderConstraint> &constraints) const = 0;
  };
} // namespace pneuma
