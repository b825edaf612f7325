#pragma once

/**
 * @file
 * The Model: the coupled system of the subsystems a scene activates, its
 * global unknowns (field dofs in subsystem order, then the border), its
 * constraints, tangent and regularisation matrices, and the linear solver
 * of its bordered systems (doc/architecture.md).
 *
 * The model knows nothing of how it is driven: a solution strategy (the
 * static load path today; arc-length or explicit dynamics later) calls
 * begin_step / Newton's NonlinearProblem interface / check_state /
 * commit_step on it. The model holds no history of the path beyond what
 * its subsystems commit.
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>

#include <pneuma/core/capabilities.h>
#include <pneuma/core/constraint_distribution.h>
#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/local_access.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/loads/loads.h>
#include <pneuma/solvers/border.h>
#include <pneuma/solvers/linear_solver.h>
#include <pneuma/solvers/newton_solver.h> // NonlinearProblem

#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class Checkpoint;
  class InputLayout;

  /// Result of a finite-difference check of the tangent.
  struct TangentCheck
  {
    double relative_error = 0.;
    double tangent_norm   = 0.;
  };

  /// The coupled discrete system.
  class Model : public solvers::NonlinearProblem
  {
  public:
    /// The subsystems that @p layout activates, in registration order.
    Model(const MPI_Comm comm, const InputLayout &layout);
    ~Model() override;

    // ---- parameters
    void
    declare_parameters(dealii::ParameterHandler &prm,
                       const InputLayout        &layout);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    // ---- setup
    /// Set every subsystem up: unknowns, constraints, matrices.
    void
    setup();
    /// Adaptive refinement cycles after the first run (0: none).
    unsigned int
    refinement_cycles() const;
    /// Refine the meshes by the converged @p state and set up again.
    void
    refine(const solvers::BorderedVector &state);
    /// Rebuild the sparsity pattern and matrices (couplings have grown).
    void
    rebuild_matrices();
    /**
     * For runs whose strategies never assemble a tangent (explicit
     * dynamics, dynamic relaxation; before setup()): no sparsity pattern
     * and no matrix are built, so the setup is cheaper and the tangent's
     * memory is not held; residual assemblies (assemble_residual()), the
     * lumped mass and the border for a field work as before.
     */
    void
    set_matrix_free(const bool on)
    {
      matrix_free = on;
    }
    bool
    is_matrix_free() const
    {
      return matrix_free;
    }
    /// Ask every subsystem for its constraints again (they depend on a
    /// state, e.g. form finding's normal motion) and rebuild the matrices.
    void
    reconstrain()
    {
      make_constraints();
      rebuild_matrices();
    }

    // ---- access
    MPI_Comm
    mpi_communicator() const
    {
      return comm;
    }
    /// The subsystem of type T, or nullptr if the scene has none.
    template <typename T>
    T *
    find() const
    {
      for (const auto &s : subsystems)
        if (auto *p = dynamic_cast<T *>(s.get()))
          return p;
      return nullptr;
    }
    const std::vector<std::unique_ptr<Subsystem>> &
    all() const
    {
      return subsystems;
    }
    /// The subsystems with the capability @p C (core/capabilities.h), in
    /// order.
    template <typename C>
    std::vector<C *>
    with() const
    {
      std::vector<C *> found;
      for (const auto &s : subsystems)
        if (auto *p = dynamic_cast<C *>(s.get()))
          found.push_back(p);
      return found;
    }
    /// The loads shared by the subsystems (gravity, pressure curves).
    const loads::Loads &
    loads() const
    {
      return load_functions;
    }
    const dealii::IndexSet &
    locally_owned() const
    {
      return owned;
    }
    const dealii::IndexSet &
    locally_relevant() const
    {
      return relevant;
    }
    const dealii::AffineConstraints<double> &
    constraints() const
    {
      return update_constraints;
    }
    const dealii::AffineConstraints<double> &
    kinematic_constraints() const
    {
      return kinematic;
    }
    /// Global unknowns of subsystem @p s (field range).
    UnknownRange
    range(const Subsystem &s) const;
    /// First border row of subsystem @p s.
    unsigned int
    border_offset(const Subsystem &s) const;
    unsigned int
    n_border() const
    {
      return coupling.size();
    }
    dealii::types::global_dof_index
    n_dofs() const
    {
      return owned.size();
    }
    solvers::LinearSolver &
    linear_solver()
    {
      return solver;
    }
    dealii::TimerOutput &
    timer()
    {
      return *timers;
    }
    void
    set_timer(dealii::TimerOutput &t)
    {
      timers = &t;
    }
    /// The tangent and the border blocks of the last assemble().
    const LA::SparseMatrix &
    tangent_matrix() const
    {
      return tangent;
    }
    const solvers::BorderCoupling &
    border_coupling() const
    {
      return coupling;
    }
    /// The border blocks of the last assembly, of a residual or of a
    /// tangent (the chamber couplings come with every residual).
    const solvers::BorderCoupling &
    last_border_coupling() const
    {
      return *last_coupling;
    }
    unsigned int
    n_linear_solves() const
    {
      return linear_solves;
    }

    // ---- the state
    /// A field vector of the global layout (owned), and a ghosted one.
    LA::Vector
    make_field() const;
    /// The ghosted copy of @p field (a member buffer).
    const LA::Vector &
    ghost(const LA::Vector &field);
    /// Every subsystem's check that the scene is well posed (before any
    /// work of a run).
    void
    check_well_posed() const
    {
      for (const auto &s : subsystems)
        s->check_well_posed();
    }
    /// The reference state at pseudo time 0: prescribed values, every
    /// subsystem initialized.
    solvers::BorderedVector
    initial_state();
    /// Checkpoint: every subsystem's state at the converged state
    /// `*states[0]`, the field values of those that do not save their own
    /// and the border of each of @p states (then the other vectors the
    /// load path keeps: the last step's increment), and the solver counts.
    void
    save_checkpoint(Checkpoint &checkpoint,
                    const std::vector<const solvers::BorderedVector *> &states);
    /// Restart: the reference state (initial_state()), then the states of
    /// @p checkpoint at pseudo time @p t, the converged one first; throws
    /// InputError if the checkpoint belongs to another scene.
    std::vector<solvers::BorderedVector>
    load_checkpoint(const Checkpoint &checkpoint, const double t);
    /// Set up from the checkpoint in @p directory (its mesh) instead of
    /// the input's mesh; empty: a fresh run.
    void
    set_restart_directory(const std::string &directory)
    {
      restart = directory;
    }
    const std::string &
    restart_directory() const
    {
      return restart;
    }
    /**
     * Prepare the step to @p t from the converged @p state: prescribed
     * values, dependent dofs, contact candidates (matrices rebuilt if they
     * grow), border predictions. Returns why the step is impossible, or an
     * empty string.
     */
    std::string
    begin_step(const double t, solvers::BorderedVector &state);
    /// Why the converged @p state is not admissible, or an empty string.
    std::string
    check_state(const solvers::BorderedVector &state);
    /// Accept the converged @p state at @p t.
    void
    commit_step(const double t, const solvers::BorderedVector &state);
    /// The step begun last is rejected; @p t is the time of the last
    /// converged state.
    void
    reject_step(const double t);
    /// Renew reports that depend on the last assembly (contact points) at
    /// the converged @p state.
    void
    refresh(const solvers::BorderedVector &state);
    /**
     * The residual f_int - f_ext of every subsystem at the reported state
     * with only the kinematic constraints condensed: at a held dof it is
     * the force the support exerts, whichever subsystems load that dof
     * (a cable end takes its element's force and the contact forces on
     * it). Valid during add_statistics(): the one reaction path of every
     * subsystem.
     */
    const LA::Vector &
    support_residual() const
    {
      return support_forces;
    }
    /**
     * The residual f_int - f_ext of every subsystem at the reported state
     * with no constraint condensed: at a tied cable node it is the force
     * the tie exerts on it. Valid during add_statistics().
     */
    const LA::Vector &
    unconstrained_residual() const
    {
      return unconstrained_forces;
    }
    /// Statistics of every subsystem at @p state (call reduce() after).
    void
    add_statistics(Statistics                    &statistics,
                   const solvers::BorderedVector &state,
                   const double                   t);
    /// Write every subsystem's output files of @p state at @p step.
    void
    write_output(const std::string             &directory,
                 const unsigned int             step,
                 const double                   t,
                 const solvers::BorderedVector &state);
    /// Print only on rank 0 (quiet runs print nothing).
    dealii::ConditionalOStream &
    out()
    {
      return pcout;
    }

    /**
     * The model's tangent and border blocks are those of @p u at pseudo
     * time @p t (its last assemble(), no shift added since), so a check of
     * the converged state need not assemble again.
     */
    bool
    tangent_is_at(const solvers::BorderedVector &u, const double t) const;

    /// False if a subsystem says that its tangent, as last assembled, is
    /// not symmetric by construction (LinearSolverHints::symmetric_tangent:
    /// a smoothed contact normal; or, in the last assembly of a tangent,
    /// Assembly::symmetric: friction in slip); the same on every rank.
    bool
    symmetric_by_construction() const;

    /**
     * The inertia of Newton's last factorization if it is the LDL^T of the
     * unshifted tangent (Linear solver/direct/Factorization) at a field
     * within @p relative of @p u (|u - u_k| <= relative |u|, e.g. the
     * iterate before the last, vanishing update); false otherwise.
     */
    bool
    newton_inertia(const solvers::BorderedVector &u,
                   const double                   relative,
                   solvers::Inertia              &inertia) const;

    // ---- NonlinearProblem
    void
    assemble(const solvers::BorderedVector &u,
             solvers::BorderedVector       &residual) override;
    void
    solve_linear(const double                   shift,
                 const solvers::BorderedVector &rhs,
                 solvers::BorderedVector       &du) override;
    double
    initial_shift(const double factor) override;
    /// Assemble the regularisation matrix L (the subsystems'
    /// add_regularisation) with the tangent's sparsity, unless it has rows.
    void
    ensure_laplacian();
    void
    laplacian_vmult(const solvers::BorderedVector &x,
                    solvers::BorderedVector       &y) override;
    double
    load_norm() override;
    double
    start_prestress() override;
    void
    set_linear_tolerance(const double eta) override
    {
      solver.set_forcing(eta);
    }
    bool
    interrupted() override;
    std::vector<std::string>
    block_names() const override;
    std::vector<double>
    block_norms(const solvers::BorderedVector &r) const override;

    /// mean(|diag K|)/mean(diag L) over the unconstrained dofs of @p range
    /// (0 if L has no weight there): the stiffness scale that makes a
    /// continuation shift dimensionless.
    double
    diagonal_ratio(const UnknownRange                      &range,
                   const LA::SparseMatrix                  &K,
                   const LA::SparseMatrix                  &L,
                   const dealii::AffineConstraints<double> &constraints) const;

    /// Pseudo time of the loads of the state last begun, committed,
    /// rejected or assembled at (begin_step(), commit_step(),
    /// reject_step(), assemble(u, t, r)).
    double
    time() const
    {
      return current_time;
    }
    /// The residual and tangent at @p u at pseudo time @p t (the model
    /// is then at @p t).
    void
    assemble(const solvers::BorderedVector &u,
             const double                   t,
             solvers::BorderedVector       &residual)
    {
      current_time = t;
      assemble(u, residual);
    }

    /// Number of monitor points (Output/Monitor points), and the global
    /// index of displacement component @p c of point @p m on the rank that
    /// reports it (invalid on the others): subsystems with the
    /// MonitorPoints capability.
    unsigned int
    n_monitor_points() const
    {
      const auto *m = find<MonitorPoints>();
      return m ? m->n_monitor_points() : 0;
    }
    dealii::types::global_dof_index
    monitor_dof(const unsigned int m, const unsigned int c) const
    {
      return find<MonitorPoints>()->monitor_dof(m, c);
    }

    /**
     * The residual alone at @p u and pseudo time @p t (path following
     * differentiates it in t): no tangent; the tangent, the border blocks
     * and the applied loads of the last assemble() are kept.
     */
    void
    assemble_residual(const solvers::BorderedVector &u,
                      const double                   t,
                      solvers::BorderedVector       &residual);
    /// Solve J du = rhs again with the factorization of the last
    /// solve_linear() (another right-hand side, no factorization).
    void
    solve_again(const solvers::BorderedVector &rhs,
                solvers::BorderedVector       &du);
    /**
     * The tangent and border blocks at @p u and pseudo time @p t of the
     * stiffest state each point can reach (Inertia::stiffest_tangent),
     * into the model's tangent: the fictitious mass of dynamic relaxation.
     * No assembly is current afterwards.
     */
    void
    assemble_stiffest_tangent(const solvers::BorderedVector &u, const double t);
    /// The dependent dofs of an increment @p dx (owned) follow their
    /// masters (the update constraints: homogeneous), as after a solve.
    void
    distribute_increment(LA::Vector &dx) const;
    /// y = J x with the bordered Jacobian of the last assemble().
    void
    vmult(const solvers::BorderedVector &x, solvers::BorderedVector &y) const;
    /// Ramp the loads that act in full from t = @p t0 over [t0, t1]
    /// (Subsystem::ramp_initial_loads); true if some subsystem has any.
    bool
    ramp_initial_loads(const double t0, const double t1);
    /// True if some prescribed value (supports, rigid plates, cable ends)
    /// differs between pseudo times @p t0 and @p t1.
    bool
    prescribed_values_change(const double t0, const double t1) const;

    /**
     * Compare the assembled tangent at @p state plus a smooth perturbation
     * of size @p amplitude with central finite differences of the residual
     * (step @p h) at pseudo time @p t, on admissible states. With
     * @p path_constraint, the Jacobian of the system bordered by the
     * spherical arc-length constraint (solvers/path_following.h), the
     * load factor included.
     */
    TangentCheck
    check_tangent(const double t,
                  const double amplitude,
                  const double h,
                  const bool   path_constraint = false);

    /**
     * The tangent and border blocks at @p u and pseudo time @p t into
     * @p K (with the tangent's pattern: copy_from(tangent_matrix()) first)
     * and @p border, leaving the model's own tangent as it is (linear
     * buckling differences two tangents).
     */
    void
    assemble_tangent(const solvers::BorderedVector &u,
                     const double                   t,
                     LA::SparseMatrix              &K,
                     solvers::BorderCoupling       &border);
    /**
     * The mass matrix of every subsystem (Subsystem::add_mass) in the
     * tangent's pattern; the rows and columns of constrained dofs are zero
     * (their motion is not free: no inertia of their own).
     */
    void
    assemble_mass(LA::SparseMatrix &M) const;
    /**
     * The border unknowns (scaled, as in a state) that the subsystems'
     * border equations give for @p field at pseudo time @p t, without
     * Newton (BorderFromField, core/capabilities.h): what a strategy
     * without a matrix needs. Throws if a subsystem with border unknowns
     * cannot evaluate them.
     */
    dealii::Vector<double>
    border_for(const LA::Vector &field, const double t);
    /**
     * The same, with @p border the current border (scaled): the unknowns
     * of constraint rows (BorderConstraint) keep their values from it, and
     * those rows (model rows) with their values at @p field go to
     * @p constraints.
     */
    dealii::Vector<double>
    border_for(const LA::Vector              &field,
               const double                   t,
               const dealii::Vector<double>  &border,
               std::vector<BorderConstraint> &constraints);
    /**
     * The lumped (diagonal) mass of every subsystem with Inertia
     * (core/capabilities.h), each dependent dof's mass moved to its
     * masters in proportion to the squared weights (positive, the total
     * kept): for strategies without a matrix (explicit dynamics, dynamic
     * relaxation). Owned entries.
     */
    LA::Vector
    lumped_mass() const;
    /// The rigid translation along axis @p c (0..2) of every subsystem
    /// that has one (1 on the translation dofs of that component).
    LA::Vector
    rigid_translation(const unsigned int c) const;
    /// Mode shapes (owned vectors; their dependent dofs are filled here)
    /// to add, as fields named @p names, to the next write_output().
    void
    set_output_modes(const std::vector<std::string> &names,
                     const std::vector<LA::Vector>  &modes);

  private:
    /// One assembly pass at @p u and pseudo time @p t into @p residual,
    /// the tangent @p K and the applied loads @p f_ext (either may be
    /// nullptr) and the border blocks @p border.
    void
    assemble_into(const solvers::BorderedVector &u,
                  const double                   t,
                  solvers::BorderedVector       &residual,
                  LA::SparseMatrix              *K,
                  LA::Vector                    *f_ext,
                  solvers::BorderCoupling       &border);
    /// Dependent dofs (plates, ties, hanging nodes) follow their masters.
    void
    apply_kinematic_constraints(LA::Vector &field);
    void
    make_constraints();
    /// @p result = C^T @p r with C the kinematic constraints: the force on
    /// each dependent dof moved to its masters, the dependent entries
    /// zero (owned vectors).
    void
    condense_kinematic(const LA::Vector &r, LA::Vector &result) const;

    MPI_Comm                                comm;
    dealii::ConditionalOStream              pcout;
    std::vector<std::unique_ptr<Subsystem>> subsystems;
    std::vector<UnknownRange>               ranges;
    std::vector<unsigned int>               border_offsets;
    loads::Loads                            load_functions;
    solvers::LinearSolver                   solver;
    dealii::TimerOutput                    *timers = nullptr;
    std::unique_ptr<dealii::TimerOutput>    own_timer;

    dealii::IndexSet                  owned, relevant;
    dealii::AffineConstraints<double> kinematic, update_constraints;
    /// update_constraints.distribute() with its communication planned.
    ConstraintDistribution update_distribution;
    /// Some rank has kinematic constraints (the same on every rank).
    bool any_kinematic = false;
    /// The tangent, and the regularisation matrix L: empty (0 rows) until
    /// ensure_laplacian() assembles it, cleared after a solve used it.
    LA::SparseMatrix tangent, laplacian;
    LA::Vector       external, ghosted;
    /// The zero field every make_field() copies (one map for all fields).
    LA::Vector field_template;
    /// The plan of ghost().
    LA::GhostImport ghost_import;
    /// support_residual() of the last add_statistics().
    LA::Vector support_forces;
    /// unconstrained_residual() of the last add_statistics().
    LA::Vector              unconstrained_forces;
    solvers::BorderCoupling coupling;
    /// Border blocks of assemble_residual(), thrown away.
    solvers::BorderCoupling scratch_coupling;
    /// The coupling assemble_into() filled last.
    const solvers::BorderCoupling *last_coupling = &coupling;
    /// Pseudo time of the loads in assemble().
    double current_time = 0.;
    /// A step has been committed (or a checkpoint loaded): steps no longer
    /// start from the reference state (NewtonAids::first_guess).
    bool started = false;
    /// The last assembly of a tangent was symmetric for every subsystem
    /// (Assembly::symmetric).
    bool assembled_symmetric = true;
    /// No pattern and no matrices (set_matrix_free()).
    bool matrix_free = false;
    /// Mode shapes of the next write_output() (ghosted).
    std::vector<std::string> mode_names;
    std::vector<LA::Vector>  mode_fields;
    unsigned int             linear_solves = 0;
    std::string              restart;
    /// Solver counts at the last commit_step() (for checkpoints).
    std::vector<unsigned int> committed_counts = {0, 0, 0};
    /// The state, time and validity of the tangent's last assembly
    /// (tangent_is_at()).
    solvers::BorderedVector assembled_state;
    double                  assembled_time     = 0.;
    bool                    tangent_is_current = false;
    /// The field and shift of the last factorization (newton_inertia()).
    LA::Vector factorized_field;
    double     factorized_shift = -1.;
  };
} // namespace pneuma
