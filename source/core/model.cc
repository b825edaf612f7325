#include <deal.II/base/array_view.h>
#include <deal.II/lac/sparsity_tools.h>

#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/model.h>
#include <pneuma/core/output.h>
#include <pneuma/solvers/path_following.h>

#include <algorithm>
#include <cmath>

namespace pneuma
{
  using namespace dealii;

  namespace
  {
    std::vector<SubsystemEntry> &
    registry()
    {
      static std::vector<SubsystemEntry> entries;
      return entries;
    }
  } // namespace

  bool
  register_subsystem(const SubsystemEntry &entry)
  {
    auto &entries = registry();
    entries.push_back(entry);
    std::stable_sort(entries.begin(),
                     entries.end(),
                     [](const auto &a, const auto &b) {
                       return a.order < b.order;
                     });
    return true;
  }

  const std::vector<SubsystemEntry> &
  subsystem_entries()
  {
    return registry();
  }

  Model::Model(const MPI_Comm comm, const InputLayout &layout)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
  {
    for (const auto &entry : subsystem_entries())
      if (entry.is_active(layout))
        subsystems.push_back(entry.create(*this));
    // Checked before any TimerOutput exists: one destroyed while an input
    // error propagates prints deal.II's multi-line MPI warning on stderr.
    check_input(!subsystems.empty(),
                "Geometry/Type",
                "the scene has nothing to solve: no membrane (Type is "
                "none) and no cables (Cables/Number of cables)");
    own_timer = std::make_unique<TimerOutput>(comm,
                                              pcout,
                                              TimerOutput::never,
                                              TimerOutput::wall_times);
    timers    = own_timer.get();
  }

  /// The direct solver refers to the tangent: release it first.
  Model::~Model()
  {
    solver.reset();
  }

  // ------------------------------------------------------------------
  // Parameters
  // ------------------------------------------------------------------
  void
  Model::declare_parameters(ParameterHandler &prm, const InputLayout &layout)
  {
    for (const auto &entry : subsystem_entries())
      entry.declare_switches(prm);
    load_functions.declare_parameters(prm);
    solver.declare_parameters(prm);
    for (const auto &s : subsystems)
      s->declare_parameters(prm, layout);
  }

  void
  Model::parse_parameters(ParameterHandler &prm)
  {
    load_functions.parse_parameters(prm);
    solver.parse_parameters(prm);
    for (const auto &s : subsystems)
      s->parse_parameters(prm);
    for (const auto &s : subsystems)
      s->check_parameters(*this);
  }

  // ------------------------------------------------------------------
  // Setup
  // ------------------------------------------------------------------
  UnknownRange
  Model::range(const Subsystem &s) const
  {
    for (unsigned int k = 0; k < subsystems.size(); ++k)
      if (subsystems[k].get() == &s)
        return ranges[k];
    Assert(false, ExcInternalError());
    return {};
  }

  unsigned int
  Model::border_offset(const Subsystem &s) const
  {
    for (unsigned int k = 0; k < subsystems.size(); ++k)
      if (subsystems[k].get() == &s)
        return border_offsets[k];
    Assert(false, ExcInternalError());
    return 0;
  }

  void
  Model::setup()
  {
    started = false;
    // Field unknowns in subsystem order, then the border.
    types::global_dof_index first    = 0;
    unsigned int            n_border = 0;
    ranges.clear();
    border_offsets.clear();
    for (const auto &s : subsystems)
      {
        const auto n = s->setup_unknowns(first, comm);
        ranges.push_back({first, n});
        first += n;
        border_offsets.push_back(n_border);
        n_border += s->n_border_unknowns();
      }
    owned = IndexSet(first);
    for (const auto &s : subsystems)
      s->add_locally_owned(owned);
    relevant = IndexSet(first);
    relevant.add_indices(owned);
    for (const auto &s : subsystems)
      s->add_locally_relevant(relevant);
    owned.compress();
    relevant.compress();

    make_constraints();
    external.reinit(owned, comm);
    field_template.reinit(owned, comm);
    ghosted.reinit(owned, relevant, comm);
    coupling.reinit(n_border, external);
    scratch_coupling.reinit(n_border, external);
    for (const auto &s : subsystems)
      s->finish_setup();
    rebuild_matrices();

    // AMG near-null space: translations (and rotations where a subsystem
    // has them) over the owned dofs.
    std::vector<std::vector<double>> modes(
      6, std::vector<double>(owned.n_elements(), 0.));
    for (const auto &s : subsystems)
      if (auto *h = dynamic_cast<const LinearSolverHints *>(s.get()))
        h->add_near_null_space(owned, modes);
    std::vector<std::vector<bool>> translations(
      3, std::vector<bool>(owned.n_elements()));
    double rotation_norm = 0.;
    for (unsigned int k = 0; k < owned.n_elements(); ++k)
      {
        for (unsigned int c = 0; c < 3; ++c)
          translations[c][k] = modes[c][k] != 0.;
        for (unsigned int c = 3; c < 6; ++c)
          rotation_norm += std::abs(modes[c][k]);
      }
    solver.set_constant_modes(translations);
    solver.set_symmetric_possible(symmetric_by_construction());
    if (solver.type() == solvers::LinearSolverType::amg
        && Utilities::MPI::sum(rotation_norm, comm) > 0.)
      solver.set_rigid_body_modes(modes);
    solver.reset();
  }

  unsigned int
  Model::refinement_cycles() const
  {
    unsigned int n = 0;
    for (const auto &s : subsystems)
      if (const auto *r = dynamic_cast<const Refinable *>(s.get()))
        n = std::max(n, r->refinement_cycles());
    return n;
  }

  void
  Model::refine(const solvers::BorderedVector &state)
  {
    ghost(state.field);
    for (const auto &s : subsystems)
      if (auto *r = dynamic_cast<Refinable *>(s.get()))
        r->refine(ghosted);
    setup();
  }

  void
  Model::make_constraints()
  {
    // Kinematic constraints first (hanging nodes, rigid plates, ties),
    // then the prescribed components of the Newton update.
    kinematic.clear();
    kinematic.reinit(relevant);
    for (const auto &s : subsystems)
      s->add_kinematic_constraints(kinematic);
    // Every rank knows the constraints of all the dofs it sees, also of
    // ghosts no cell of its touches (a membrane contact's masters on
    // other ranks): assembling into such a row condenses it.
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      kinematic.make_consistent_in_parallel(owned, relevant, comm);
    kinematic.close();
    // Whether any rank has kinematic constraints: applying them is a
    // collective operation, and a rank that owns no plate or hanging node
    // must still take part (a local test hung 2 ranks on a tube with one
    // rigid end plate).
    any_kinematic = Utilities::MPI::max(static_cast<unsigned int>(
                                          kinematic.n_constraints() > 0),
                                        comm)
                    > 0;

    update_constraints.clear();
    update_constraints.reinit(relevant);
    update_constraints.merge(kinematic);
    for (const auto &s : subsystems)
      s->add_update_constraints(update_constraints);
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      update_constraints.make_consistent_in_parallel(owned, relevant, comm);
    update_constraints.close();
    update_distribution.reinit(update_constraints, owned, comm);
  }

  void
  Model::rebuild_matrices()
  {
    // Strategies without a tangent need no pattern and no matrix.
    if (matrix_free)
      {
        tangent.clear();
        laplacian.clear();
        return;
      }
    DynamicSparsityPattern dsp(relevant);
    for (const auto &s : subsystems)
      s->add_sparsity(dsp, update_constraints);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    solver.reset();
    tangent.reinit(owned, owned, dsp, comm);
    laplacian.clear();
  }

  void
  Model::ensure_laplacian()
  {
    // Built when a shift or the continuation needs it and freed after
    // the solve that used it: a matrix of the tangent's size that most
    // runs need once (the stiffened start) or never.
    if (laplacian.m() > 0)
      return;
    laplacian.reinit(tangent);
    for (const auto &s : subsystems)
      if (const auto *a = dynamic_cast<const NewtonAids *>(s.get()))
        a->add_regularisation(update_constraints, laplacian);
  }

  // ------------------------------------------------------------------
  // State
  // ------------------------------------------------------------------
  LA::Vector
  Model::make_field() const
  {
    // A copy shares the template's map: vectors of one map copy and
    // import into each other without collective checks of their layouts.
    return field_template;
  }

  const LA::Vector &
  Model::ghost(const LA::Vector &field)
  {
    ghost_import(field, ghosted);
    return ghosted;
  }

  void
  Model::apply_kinematic_constraints(LA::Vector &field)
  {
    // Dependent dofs follow their masters after prescribed values changed.
    if (!any_kinematic)
      return;
    ghost(field);
    for (const auto i : owned)
      if (kinematic.is_constrained(i))
        {
          double v = kinematic.get_inhomogeneity(i);
          for (const auto &e : *kinematic.get_constraint_entries(i))
            v += e.second * ghosted[e.first];
          field[i] = v;
        }
    field.compress(VectorOperation::insert);
  }

  solvers::BorderedVector
  Model::initial_state()
  {
    current_time = 0.;
    solvers::BorderedVector state;
    state.field = make_field();
    for (const auto &s : subsystems)
      s->set_prescribed_values(0., state.field);
    ghost(state.field);
    for (const auto &s : subsystems)
      s->initialize(ghosted, 0.);
    state.border.reinit(n_border());
    return state;
  }

  namespace
  {
    /// Does @p s save its own field in checkpoints (else the model
    /// gathers it)?
    bool
    saves_own_field(const Subsystem &s)
    {
      const auto *c = dynamic_cast<const Checkpointed *>(&s);
      return c && c->saves_own_field();
    }
  } // namespace

  void
  Model::save_checkpoint(
    Checkpoint                                         &checkpoint,
    const std::vector<const solvers::BorderedVector *> &states)
  {
    AssertThrow(!states.empty(), ExcInternalError());
    // Ghosted copies of every state's field, the converged one first.
    std::vector<LA::Vector>         fields(states.size());
    std::vector<const LA::Vector *> pointers;
    for (unsigned int j = 0; j < states.size(); ++j)
      {
        fields[j].reinit(ghosted);
        fields[j] = states[j]->field;
        pointers.push_back(&fields[j]);
      }
    std::vector<std::string> names;
    for (const auto &s : subsystems)
      names.push_back(s->name());
    checkpoint.put("model/subsystems", names);
    checkpoint.put("model/dofs", static_cast<std::uint64_t>(n_dofs()));
    checkpoint.put("model/states", static_cast<unsigned int>(states.size()));
    // The counts at the last converged step: work of a step a signal cut
    // short is done again after the restart.
    checkpoint.put("model/counts", committed_counts);
    for (unsigned int j = 0; j < states.size(); ++j)
      {
        const std::string suffix = j == 0 ? "" : "/" + std::to_string(j);
        checkpoint.put("model/border" + suffix,
                       std::vector<double>(states[j]->border.begin(),
                                           states[j]->border.end()));
        for (unsigned int k = 0; k < subsystems.size(); ++k)
          if (!saves_own_field(*subsystems[k]))
            {
              // The owned entries of the range, gathered in index order.
              const UnknownRange                            r = ranges[k];
              std::vector<std::pair<std::uint64_t, double>> local;
              for (types::global_dof_index i = r.first; i < r.first + r.size;
                   ++i)
                if (owned.is_element(i))
                  local.emplace_back(i - r.first, states[j]->field[i]);
              const auto          all = Utilities::MPI::gather(comm, local, 0);
              std::vector<double> values(r.size, 0.);
              for (const auto &part : all)
                for (const auto &[i, v] : part)
                  values[i] = v;
              checkpoint.put("model/field/" + subsystems[k]->name() + suffix,
                             values);
            }
      }
    for (const auto *s : with<Checkpointed>())
      s->save_checkpoint(checkpoint, pointers);
  }

  std::vector<solvers::BorderedVector>
  Model::load_checkpoint(const Checkpoint &checkpoint, const double t)
  {
    started = true;
    std::vector<std::string> names;
    for (const auto &s : subsystems)
      names.push_back(s->name());
    const auto saved =
      checkpoint.get<std::vector<std::string>>("model/subsystems");
    const auto dofs = checkpoint.get<std::uint64_t>("model/dofs");
    const auto list = [](const std::vector<std::string> &v) {
      std::string s;
      for (const auto &n : v)
        s += (s.empty() ? "" : ", ") + n;
      return s;
    };
    check_input(saved == names && dofs == n_dofs(),
                "--restart " + checkpoint.directory(),
                "the checkpoint is of another scene (" + std::to_string(dofs)
                  + " unknowns in " + list(saved) + "; this input has "
                  + std::to_string(n_dofs()) + " in " + list(names) + ")");
    // The reference state first (reference volumes, initial contact),
    // then the checkpoint's states over it (the converged one first).
    const solvers::BorderedVector        reference = initial_state();
    std::vector<solvers::BorderedVector> states(
      checkpoint.get<unsigned int>("model/states"), reference);
    std::vector<LA::Vector *> fields;
    for (unsigned int j = 0; j < states.size(); ++j)
      {
        const std::string suffix = j == 0 ? "" : "/" + std::to_string(j);
        const auto        border =
          checkpoint.get<std::vector<double>>("model/border" + suffix);
        check_input(border.size() == n_border(),
                    "--restart " + checkpoint.directory(),
                    "the checkpoint has another number of chamber unknowns");
        for (unsigned int i = 0; i < border.size(); ++i)
          states[j].border[i] = border[i];
        for (unsigned int k = 0; k < subsystems.size(); ++k)
          if (!saves_own_field(*subsystems[k]))
            {
              const auto values = checkpoint.get<std::vector<double>>(
                "model/field/" + subsystems[k]->name() + suffix);
              const UnknownRange r = ranges[k];
              for (types::global_dof_index i = r.first; i < r.first + r.size;
                   ++i)
                if (owned.is_element(i))
                  states[j].field[i] = values[i - r.first];
            }
        fields.push_back(&states[j].field);
      }
    for (auto *s : with<Checkpointed>())
      s->load_checkpoint(checkpoint, fields);
    for (auto &state : states)
      state.field.compress(VectorOperation::insert);
    const auto counts =
      checkpoint.get<std::vector<unsigned int>>("model/counts");
    linear_solves = counts[0];
    solver.set_counts(counts[1], counts[2]);
    committed_counts = counts;
    current_time     = t;
    // Reports of the restored state (chamber volumes, contact forces).
    refresh(states[0]);
    return states;
  }

  namespace
  {
    /// The border of the subsystems' current values (scaled), each at its
    /// offset.
    Vector<double>
    subsystem_border(const std::vector<std::unique_ptr<Subsystem>> &subsystems,
                     const std::vector<unsigned int>               &offsets,
                     const unsigned int                             n)
    {
      Vector<double> border(n);
      for (unsigned int k = 0; k < subsystems.size(); ++k)
        {
          const Vector<double> b = subsystems[k]->border();
          for (unsigned int j = 0; j < b.size(); ++j)
            border[offsets[k] + j] = b[j];
        }
      return border;
    }
  } // namespace

  std::string
  Model::begin_step(const double t, solvers::BorderedVector &state)
  {
    current_time = t;
    if (!started)
      for (const auto &s : subsystems)
        if (const auto *a = dynamic_cast<const NewtonAids *>(s.get()))
          a->first_guess(t, state.field);
    for (const auto &s : subsystems)
      s->set_prescribed_values(t, state.field);
    apply_kinematic_constraints(state.field);
    ghost(state.field);
    bool grown = false;
    for (const auto &s : subsystems)
      {
        const std::string error = s->begin_step(t, ghosted, grown);
        if (!error.empty())
          return error;
      }
    if (grown)
      rebuild_matrices();
    // The subsystems' predictions; the others keep the strategy's (the
    // last state, or its extrapolation).
    const Vector<double> predicted =
      subsystem_border(subsystems, border_offsets, n_border());
    if (state.border.size() != n_border())
      state.border = predicted;
    else
      for (unsigned int k = 0; k < subsystems.size(); ++k)
        if (subsystems[k]->predicts_border())
          for (unsigned int j = 0; j < subsystems[k]->n_border_unknowns(); ++j)
            state.border[border_offsets[k] + j] =
              predicted[border_offsets[k] + j];
    return "";
  }

  std::string
  Model::check_state(const solvers::BorderedVector &state)
  {
    ghost(state.field);
    for (const auto &s : subsystems)
      {
        const std::string reason = s->check_state(ghosted);
        if (!reason.empty())
          return reason;
      }
    return "";
  }

  void
  Model::commit_step(const double t, const solvers::BorderedVector &state)
  {
    current_time     = t;
    started          = true;
    committed_counts = {linear_solves,
                        solver.n_factorizations(),
                        solver.n_krylov_iterations()};
    ghost(state.field);
    for (unsigned int k = 0; k < subsystems.size(); ++k)
      {
        const unsigned int n = subsystems[k]->n_border_unknowns();
        Vector<double>     b(n);
        for (unsigned int j = 0; j < n; ++j)
          b[j] = state.border[border_offsets[k] + j];
        subsystems[k]->commit_step(t, ghosted, b);
      }
  }

  void
  Model::reject_step(const double t)
  {
    current_time = t;
    for (const auto &s : subsystems)
      s->reject_step();
  }

  void
  Model::refresh(const solvers::BorderedVector &state)
  {
    ghost(state.field);
    for (const auto &s : subsystems)
      s->refresh(ghosted);
  }

  void
  Model::add_statistics(Statistics                    &statistics,
                        const solvers::BorderedVector &state,
                        const double                   t)
  {
    ghost(state.field);
    // The one residual assembly of a report: every subsystem's residual
    // with no constraint condensed (at a tied node the tie's force), and
    // from it the support residual C^T r (at a held dof the force the
    // support exerts, whichever subsystems load it).
    {
      TimerOutput::Scope        ts(*timers, "assembly");
      AffineConstraints<double> none;
      none.reinit(relevant);
      none.close();
      unconstrained_forces = make_field();
      Vector<double> border_residual(n_border());
      Assembly       a;
      a.time            = t;
      a.field           = &ghosted;
      a.border          = &state.border;
      a.constraints     = &none;
      a.residual        = &unconstrained_forces;
      a.border_residual = &border_residual;
      a.coupling        = &scratch_coupling;
      for (const auto &s : subsystems)
        s->assemble(a);
    }
    condense_kinematic(unconstrained_forces, support_forces);
    for (const auto &s : subsystems)
      s->add_statistics(statistics, ghosted, t);
  }

  void
  Model::condense_kinematic(const LA::Vector &r, LA::Vector &result) const
  {
    result = r;
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    std::vector<types::global_dof_index> dependent;
    for (const auto &line : kinematic.get_lines())
      if (owned.is_element(line.index))
        {
          const double f = r[line.index];
          for (const auto &[master, weight] : line.entries)
            {
              indices.push_back(master);
              values.push_back(weight * f);
            }
          dependent.push_back(line.index);
        }
    // Masters owned by other ranks are sent to them in compress().
    result.add(indices, values);
    result.compress(VectorOperation::add);
    for (const auto i : dependent)
      result[i] = 0.;
    result.compress(VectorOperation::insert);
  }

  void
  Model::write_output(const std::string             &directory,
                      const unsigned int             step,
                      const double                   t,
                      const solvers::BorderedVector &state)
  {
    // Never write a non-finite state (the norm is the same on every
    // rank: all of them throw).
    if (!std::isfinite(state.field.l2_norm()))
      throw NonFiniteOutput("the state at t = " + std::to_string(t)
                            + " is not finite (NaN or inf); it is not "
                              "written");
    ghost(state.field);
    for (const auto &s : subsystems)
      if (auto *o = dynamic_cast<OutputFiles *>(s.get()))
        o->add_output_fields(ghosted, t);
    if (!mode_fields.empty())
      for (const auto &s : subsystems)
        if (auto *o = dynamic_cast<OutputFiles *>(s.get()))
          o->add_mode_fields(mode_names, mode_fields);
    for (const auto &s : subsystems)
      if (auto *o = dynamic_cast<OutputFiles *>(s.get()))
        o->write_output_files(directory, step, t, ghosted);
    mode_names.clear();
    mode_fields.clear();
  }

  Vector<double>
  Model::border_for(const LA::Vector &field, const double t)
  {
    // The multipliers keep the subsystems' last values.
    std::vector<BorderConstraint> constraints;
    return border_for(field,
                      t,
                      subsystem_border(subsystems, border_offsets, n_border()),
                      constraints);
  }

  Vector<double>
  Model::border_for(const LA::Vector              &field,
                    const double                   t,
                    const Vector<double>          &current,
                    std::vector<BorderConstraint> &constraints)
  {
    ghost(field);
    Vector<double> border(n_border());
    constraints.clear();
    for (unsigned int k = 0; k < subsystems.size(); ++k)
      {
        const unsigned int n = subsystems[k]->n_border_unknowns();
        if (n == 0)
          continue;
        const auto *b =
          dynamic_cast<const BorderFromField *>(subsystems[k].get());
        AssertThrow(b != nullptr,
                    ExcMessage("the " + subsystems[k]->name()
                               + " cannot evaluate their border unknowns "
                                 "for a given field"));
        const unsigned int offset = border_offsets[k];
        Vector<double>     own(n);
        for (unsigned int j = 0; j < n; ++j)
          own[j] = current[offset + j];
        std::vector<BorderConstraint> own_constraints;
        const Vector<double>          part =
          b->border_for(ghosted, t, own, own_constraints);
        for (unsigned int j = 0; j < n; ++j)
          border[offset + j] = part[j];
        for (auto c : own_constraints)
          {
            c.row += offset;
            constraints.push_back(c);
          }
      }
    return border;
  }

  LA::Vector
  Model::lumped_mass() const
  {
    LA::Vector m = make_field();
    for (const auto *i : with<Inertia>())
      i->add_lumped_mass(m);
    // Each dependent dof's mass goes to its masters in proportion to the
    // squared weights (Hinton, Rock & Zienkiewicz's diagonal scaling, per
    // dof): C^T m would move it by the weights themselves, which are
    // negative for a rigid plate's nodes outside its master triangle and
    // leave a master without mass. A hanging node's (1/2, 1/2) and a tie's
    // 1 are the same either way.
    std::vector<types::global_dof_index> indices, dependent;
    std::vector<double>                  values;
    for (const auto &line : kinematic.get_lines())
      if (owned.is_element(line.index))
        {
          double sum = 0.;
          for (const auto &entry : line.entries)
            sum += entry.second * entry.second;
          for (const auto &[master, weight] : line.entries)
            {
              indices.push_back(master);
              values.push_back(m[line.index] * weight * weight / sum);
            }
          dependent.push_back(line.index);
        }
    LA::Vector condensed(m);
    condensed.add(indices, values);
    condensed.compress(VectorOperation::add);
    for (const auto i : dependent)
      condensed[i] = 0.;
    condensed.compress(VectorOperation::insert);
    return condensed;
  }

  LA::Vector
  Model::rigid_translation(const unsigned int c) const
  {
    std::vector<std::vector<double>> modes(
      6, std::vector<double>(owned.n_elements(), 0.));
    for (const auto &s : subsystems)
      if (auto *h = dynamic_cast<const LinearSolverHints *>(s.get()))
        h->add_near_null_space(owned, modes);
    LA::Vector r(owned, comm);
    for (unsigned int k = 0; k < owned.n_elements(); ++k)
      r[owned.nth_index_in_set(k)] = modes[c][k];
    r.compress(VectorOperation::insert);
    return r;
  }

  void
  Model::set_output_modes(const std::vector<std::string> &names,
                          const std::vector<LA::Vector>  &modes)
  {
    mode_names = names;
    mode_fields.clear();
    for (const auto &m : modes)
      {
        LA::Vector owned_mode(m);
        update_constraints.distribute(owned_mode);
        AssertThrow(std::isfinite(owned_mode.l2_norm()),
                    ExcMessage("refusing to write a non-finite mode"));
        mode_fields.emplace_back(owned, relevant, comm);
        mode_fields.back() = owned_mode;
      }
  }

  void
  Model::assemble_tangent(const solvers::BorderedVector &u,
                          const double                   t,
                          LA::SparseMatrix              &K,
                          solvers::BorderCoupling       &border)
  {
    solvers::BorderedVector residual;
    residual.field.reinit(u.field);
    border.reinit(n_border(), external);
    K = 0.;
    assemble_into(u, t, residual, &K, nullptr, border);
  }

  void
  Model::assemble_mass(LA::SparseMatrix &M) const
  {
    M.reinit(tangent);
    M = 0.;
    for (const auto &s : subsystems)
      if (const auto *i = dynamic_cast<const Inertia *>(s.get()))
        i->add_mass(update_constraints, M);
    for (const auto i : owned)
      if (update_constraints.is_constrained(i))
        M.set(i, i, 0.);
    M.compress(VectorOperation::insert);
  }

  // ------------------------------------------------------------------
  // The nonlinear problem seen by Newton
  // ------------------------------------------------------------------
  void
  Model::assemble(const solvers::BorderedVector &u,
                  solvers::BorderedVector       &residual)
  {
    tangent  = 0.;
    external = 0.;
    assemble_into(u, current_time, residual, &tangent, &external, coupling);
    solver.set_symmetric_possible(symmetric_by_construction());
    assembled_state    = u;
    assembled_time     = current_time;
    tangent_is_current = true;
  }

  bool
  Model::symmetric_by_construction() const
  {
    if (!assembled_symmetric)
      return false;
    for (const auto &s : subsystems)
      if (const auto *h = dynamic_cast<const LinearSolverHints *>(s.get());
          h && !h->symmetric_tangent())
        return false;
    return true;
  }

  bool
  Model::tangent_is_at(const solvers::BorderedVector &u, const double t) const
  {
    if (!tangent_is_current || assembled_time != t
        || assembled_state.border.size() != u.border.size()
        || assembled_state.field.size() != u.field.size())
      return false;
    for (unsigned int j = 0; j < u.border.size(); ++j)
      if (assembled_state.border[j] != u.border[j])
        return false;
    LA::Vector d(u.field);
    d -= assembled_state.field;
    return d.linfty_norm() == 0.;
  }

  bool
  Model::newton_inertia(const solvers::BorderedVector &u,
                        const double                   relative,
                        solvers::Inertia              &inertia) const
  {
    if (factorized_shift != 0. || factorized_field.size() != u.field.size()
        || !solver.inertia(inertia))
      return false;
    LA::Vector d(u.field);
    d -= factorized_field;
    return d.l2_norm() <= relative * u.field.l2_norm();
  }

  void
  Model::assemble_into(const solvers::BorderedVector &u,
                       const double                   t,
                       solvers::BorderedVector       &residual,
                       LA::SparseMatrix              *K,
                       LA::Vector                    *f_ext,
                       solvers::BorderCoupling       &border)
  {
    TimerOutput::Scope ts(*timers, K ? "assembly" : "residual assembly");
    ghost(u.field);
    residual.field = 0.;
    residual.border.reinit(n_border());
    Assembly a;
    a.time            = t;
    a.field           = &ghosted;
    a.border          = &u.border;
    a.constraints     = &update_constraints;
    a.residual        = &residual.field;
    a.tangent         = K;
    a.external        = f_ext;
    a.border_residual = &residual.border;
    a.coupling        = &border;
    if (&border == &coupling || &border == &scratch_coupling)
      last_coupling = &border; // (not a caller's own blocks)
    // A subsystem's symmetry can change with its state (friction slip).
    bool symmetric = true;
    a.symmetric    = K ? &symmetric : nullptr;
    for (const auto &s : subsystems)
      s->assemble(a);
    if (K)
      assembled_symmetric = symmetric;
  }

  void
  Model::assemble_residual(const solvers::BorderedVector &u,
                           const double                   t,
                           solvers::BorderedVector       &residual)
  {
    assemble_into(u, t, residual, nullptr, nullptr, scratch_coupling);
  }

  void
  Model::solve_again(const solvers::BorderedVector &rhs,
                     solvers::BorderedVector       &du)
  {
    TimerOutput::Scope t(*timers, "linear solve");
    if (n_border() == 0)
      {
        solver.solve(tangent, du.field, rhs.field);
        du.border.reinit(0);
      }
    else
      coupling.solve(solver, tangent, rhs, du);
    update_distribution.distribute(du.field);
  }

  void
  Model::assemble_stiffest_tangent(const solvers::BorderedVector &u,
                                   const double                   t)
  {
    current_time = t;
    for (auto *i : with<Inertia>())
      i->stiffest_tangent(true);
    solvers::BorderedVector r = u;
    tangent                   = 0.;
    external                  = 0.;
    assemble_into(u, t, r, &tangent, &external, coupling);
    for (auto *i : with<Inertia>())
      i->stiffest_tangent(false);
    tangent_is_current = false;
  }

  void
  Model::distribute_increment(LA::Vector &dx) const
  {
    update_distribution.distribute(dx);
  }

  void
  Model::vmult(const solvers::BorderedVector &x,
               solvers::BorderedVector       &y) const
  {
    if (n_border() == 0)
      {
        tangent.vmult(y.field, x.field);
        y.border.reinit(0);
      }
    else
      coupling.vmult(tangent, x, y);
  }

  bool
  Model::ramp_initial_loads(const double t0, const double t1)
  {
    bool any = false;
    for (const auto &s : subsystems)
      if (auto *a = dynamic_cast<NewtonAids *>(s.get()))
        any = a->ramp_initial_loads(t0, t1) || any;
    // The loads at a given pseudo time changed: no assembly is current.
    tangent_is_current = false;
    return any;
  }

  bool
  Model::prescribed_values_change(const double t0, const double t1) const
  {
    LA::Vector a = make_field(), b = make_field();
    for (const auto &s : subsystems)
      {
        s->set_prescribed_values(t0, a);
        s->set_prescribed_values(t1, b);
      }
    a -= b;
    return a.linfty_norm() > 0.;
  }

  void
  Model::solve_linear(const double                   shift,
                      const solvers::BorderedVector &rhs,
                      solvers::BorderedVector       &du)
  {
    {
      TimerOutput::Scope t(*timers, "linear solve");
      if (shift > 0.)
        {
          ensure_laplacian();
          tangent.add(shift, laplacian);
          tangent_is_current = false;
          laplacian.clear();
        }
      solver.factorize(tangent);
      factorized_field = assembled_state.field;
      factorized_shift = shift;
    }
    solve_again(rhs, du);
    ++linear_solves;
  }

  double
  Model::initial_shift(const double factor)
  {
    // The first subsystem that proposes a shift sets it (the membrane
    // when there is one: stiff cables must not slow its continuation).
    ensure_laplacian();
    for (const auto &s : subsystems)
      if (const auto *a = dynamic_cast<const NewtonAids *>(s.get()))
        {
          const double shift = a->initial_shift(factor,
                                                range(*s),
                                                tangent,
                                                laplacian,
                                                external,
                                                update_constraints);
          if (shift > 0.)
            return shift;
        }
    return 0.;
  }

  double
  Model::diagonal_ratio(const UnknownRange              &range,
                        const LA::SparseMatrix          &K,
                        const LA::SparseMatrix          &L,
                        const AffineConstraints<double> &constraints) const
  {
    double k_sum = 0., m_sum = 0.;
    for (const auto i : owned)
      if (i >= range.first && i < range.first + range.size
          && !constraints.is_constrained(i))
        {
          k_sum += std::abs(K.diag_element(i));
          m_sum += L.diag_element(i);
        }
    k_sum = Utilities::MPI::sum(k_sum, comm);
    m_sum = Utilities::MPI::sum(m_sum, comm);
    return m_sum > 0. ? k_sum / m_sum : 0.;
  }

  void
  Model::laplacian_vmult(const solvers::BorderedVector &x,
                         solvers::BorderedVector       &y)
  {
    ensure_laplacian();
    laplacian.vmult(y.field, x.field);
    // Rows of dependent and prescribed dofs carry only the diagonal that
    // the condensation leaves; the residual has no such rows, and neither
    // may its regularisation (else the regularised residual keeps a part
    // that no update can remove).
    update_constraints.set_zero(y.field);
    y.border.reinit(x.border.size());
  }

  double
  Model::start_prestress()
  {
    // The virials of the applied loads and of the chambers' pressures
    // add up (each proposal is its virial over its own walls' area).
    double force = 0.;
    for (const auto &s : subsystems)
      if (const auto *a = dynamic_cast<const NewtonAids *>(s.get()))
        force += std::max(0., a->start_prestress(external));
    return force;
  }

  double
  Model::load_norm()
  {
    // External loads, and each subsystem's force scale at the current
    // state (Newton assembles before it asks): chamber loads, the largest
    // cable force (a prestress-driven step without external load).
    const double f   = external.l2_norm();
    double       sum = f * f;
    for (const auto *a : with<NewtonAids>())
      {
        const double c = a->force_scale(ghosted);
        sum += c * c;
      }
    return std::sqrt(sum);
  }

  bool
  Model::interrupted()
  {
    return interrupt_signal(comm) != 0;
  }

  std::vector<std::string>
  Model::block_names() const
  {
    std::vector<std::string> names;
    for (unsigned int k = 0; k < subsystems.size(); ++k)
      if (ranges[k].size > 0 || subsystems[k]->n_border_unknowns() > 0)
        names.push_back(subsystems[k]->name());
    return names;
  }

  std::vector<double>
  Model::block_norms(const solvers::BorderedVector &r) const
  {
    std::vector<double> squares;
    std::vector<bool>   on_border;
    for (unsigned int k = 0; k < subsystems.size(); ++k)
      {
        const unsigned int nb = subsystems[k]->n_border_unknowns();
        if (ranges[k].size == 0 && nb == 0)
          continue;
        double sum = 0.;
        if (ranges[k].size > 0)
          {
            const auto end = ranges[k].first + ranges[k].size;
            for (const auto i : owned)
              if (i >= ranges[k].first && i < end)
                sum += r.field[i] * r.field[i];
            on_border.push_back(false);
          }
        else
          {
            for (unsigned int j = 0; j < nb; ++j)
              sum += std::pow(r.border[border_offsets[k] + j], 2);
            on_border.push_back(true);
          }
        squares.push_back(sum);
      }
    // Field parts are summed over the ranks, border parts are replicated.
    std::vector<double> field_part(squares.size(), 0.);
    for (unsigned int b = 0; b < squares.size(); ++b)
      if (!on_border[b])
        field_part[b] = squares[b];
    {
      auto in_ = field_part;
      Utilities::MPI::sum(ArrayView<const double>(in_),
                          comm,
                          ArrayView<double>(field_part));
    }
    for (unsigned int b = 0; b < squares.size(); ++b)
      squares[b] = std::sqrt(on_border[b] ? squares[b] : field_part[b]);
    return squares;
  }

  // ------------------------------------------------------------------
  // Finite-difference check of the tangent
  // ------------------------------------------------------------------
  TangentCheck
  Model::check_tangent(const double t,
                       const double amplitude,
                       const double h,
                       const bool   path_constraint)
  {
    current_time = t;
    // A smooth random state: random nodal values scaled by amplitude.
    solvers::BorderedVector u;
    u.field = make_field();
    for (const auto i : owned)
      u.field[i] =
        amplitude * (2. * std::sin(1.7 * i + 0.3) * std::cos(0.37 * i));
    u.field.compress(VectorOperation::insert);
    // An admissible state: prescribed values zero, dependent dofs (rigid
    // plates, junction copies) following their masters.
    update_constraints.set_zero(u.field);
    update_constraints.distribute(u.field);

    // The direction d acts on the independent dofs: K d with the condensed
    // tangent, and the residual is perturbed along d with its dependent
    // dofs distributed (C d).
    solvers::BorderedVector direction(u);
    for (const auto i : owned)
      direction.field[i] = std::cos(0.91 * i + 0.1);
    direction.field.compress(VectorOperation::insert);
    update_constraints.set_zero(direction.field);

    if (n_border() > 0)
      {
        // The border unknowns of the reference state at t, then predicted
        // at u, and taken off equilibrium.
        LA::Vector zero = make_field();
        ghost(zero);
        bool grown = false;
        for (const auto &s : subsystems)
          if (s->n_border_unknowns() > 0)
            s->initialize(ghosted, t);
        ghost(u.field);
        u.border.reinit(n_border());
        for (unsigned int k = 0; k < subsystems.size(); ++k)
          if (subsystems[k]->n_border_unknowns() > 0)
            {
              subsystems[k]->begin_step(t, ghosted, grown);
              const Vector<double> b = subsystems[k]->border();
              for (unsigned int j = 0; j < b.size(); ++j)
                u.border[border_offsets[k] + j] = b[j];
            }
        direction.border.reinit(u.border.size());
        for (unsigned int j = 0; j < u.border.size(); ++j)
          {
            u.border[j] *= 1.01;
            direction.border[j] = 0.3 + 0.1 * j;
          }
      }

    // Central differences of a problem's residual along d (its dependent
    // dofs distributed) against J d.
    const auto compare = [&](solvers::NonlinearProblem     &problem,
                             const solvers::BorderedVector &x,
                             const solvers::BorderedVector &d,
                             const solvers::BorderedVector &Jd) {
      solvers::BorderedVector full(d), xp(x), xm(x), rp(x), rm(x);
      update_constraints.distribute(full.field);
      xp.add(h, full);
      xm.add(-h, full);
      problem.assemble(xp, rp);
      problem.assemble(xm, rm);
      rp -= rm;
      rp *= 1. / (2. * h);
      TangentCheck check;
      check.tangent_norm = Jd.l2_norm();
      rp -= Jd;
      check.relative_error =
        rp.l2_norm() / std::max(check.tangent_norm, 1e-300);
      return check;
    };

    solvers::BorderedVector r(u), Jd(u);
    if (path_constraint)
      {
        // The bordered system about a centre off the state, with the load
        // factor moving too.
        using P = solvers::PathConstraintProblem;
        P                       problem(*this, 1e-6);
        solvers::BorderedVector center(u);
        for (const auto i : owned)
          center.field[i] -= 0.3 * amplitude * std::sin(0.53 * i + 0.2);
        center.field.compress(VectorOperation::insert);
        problem.set_scales(std::max(u.field.l2_norm(), 1e-300), 1., 1e3, 1.);
        problem.set_constraint(solvers::Control::arc_length,
                               P::extend(center, t - 0.05),
                               0.1);
        const auto x = P::extend(u, t);
        const auto d = P::extend(direction, 0.3);
        problem.assemble(x, r);
        problem.vmult(d, Jd);
        return compare(problem, x, d, Jd);
      }
    assemble(u, r);
    vmult(direction, Jd);
    return compare(*this, u, direction, Jd);
  }
} // namespace pneuma
