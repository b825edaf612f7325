#include <pneuma/cables/cable_subsystem.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>

#include <cmath>

namespace pneuma
{
  namespace cables
  {
    CableSubsystem::CableSubsystem(Model &model)
      : model(model)
      , cables(parameters, model.loads())
    {
    }

    void
    CableSubsystem::declare_switches(ParameterHandler &prm)
    {
      CableParameters::declare_count(prm);
    }

    bool
    CableSubsystem::is_active(const InputLayout &layout)
    {
      return !layout.numbered("Cables", "Cable", "Cables/Number of cables")
                .empty();
    }

    void
    CableSubsystem::declare_parameters(ParameterHandler  &prm,
                                       const InputLayout &layout)
    {
      parameters.declare_parameters(prm, layout);
    }

    void
    CableSubsystem::parse_parameters(ParameterHandler &prm)
    {
      parameters.parse_parameters(prm);
    }

    types::global_dof_index
    CableSubsystem::setup_unknowns(const types::global_dof_index first,
                                   const MPI_Comm                comm)
    {
      cables.setup(first, comm);
      return cables.n_dofs();
    }

    void
    CableSubsystem::add_locally_owned(IndexSet &owned) const
    {
      owned.add_indices(cables.locally_owned_dofs(owned.size()));
    }

    void
    CableSubsystem::add_locally_relevant(IndexSet &relevant)
    {
      relevant.add_indices(cables.all_dofs(relevant.size()));
    }

    void
    CableSubsystem::add_update_constraints(AffineConstraints<double> &c) const
    {
      cables.add_support_constraints(c);
    }

    void
    CableSubsystem::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      cables.add_sparsity(dsp, constraints);
    }

    void
    CableSubsystem::add_regularisation(
      const AffineConstraints<double> &constraints,
      LA::SparseMatrix                &L) const
    {
      cables.assemble_regularisation(constraints, L);
    }

    void
    CableSubsystem::add_mass(const AffineConstraints<double> &constraints,
                             LA::SparseMatrix                &M) const
    {
      cables.assemble_mass(constraints, M);
    }

    void
    CableSubsystem::add_lumped_mass(LA::Vector &m) const
    {
      cables.lumped_mass(m);
    }

    void
    CableSubsystem::largest_per_node(LA::Vector &v) const
    {
      cables.largest_per_node(v);
    }

    void
    CableSubsystem::add_mode_fields(const std::vector<std::string> &names,
                                    const std::vector<LA::Vector>  &modes)
    {
      cables.set_mode_fields(names, modes);
    }

    void
    CableSubsystem::add_near_null_space(
      const IndexSet                   &owned,
      std::vector<std::vector<double>> &modes) const
    {
      // Translations only (the section unknowns of a solid beam have none).
      for (unsigned int k = 0; k < owned.n_elements(); ++k)
        {
          const int c = cables.translation_component(owned.nth_index_in_set(k));
          if (c >= 0)
            modes[c][k] = 1.;
        }
    }

    double
    CableSubsystem::initial_shift(
      const double                     factor,
      const UnknownRange              &range,
      const LA::SparseMatrix          &K,
      const LA::SparseMatrix          &L,
      const LA::Vector                &external,
      const AffineConstraints<double> &constraints) const
    {
      // Asked only without a membrane (the membrane proposes first). A
      // hanging, unstressed cable is a mechanism, and the shift s of the
      // continuation acts as an axial force s in it. Under a load W (nodal
      // loads f) a first regularised step deflects the cable by about
      // W L/(8 s), i.e. turns it by W/(2 s), which stretches it by
      // (W/(2 s))^2/2 and adds an axial force EA times that; the step is
      // accepted if that error stays below the nodal load f:
      // s >= W sqrt(EA/(8 f)). Nor should s be below the total load, the
      // order of the forces the cable will carry.
      const MPI_Comm comm = model.mpi_communicator();
      double         load = 0., f_max = 0.;
      for (const auto i : model.locally_owned())
        {
          load += std::abs(external[i]);
          f_max = std::max(f_max, std::abs(external[i]));
        }
      load  = Utilities::MPI::sum(load, comm);
      f_max = Utilities::MPI::max(f_max, comm);
      const double s0 =
        f_max > 0.
          ? std::max(load,
                     load * std::sqrt(cables.axial_stiffness() / (8. * f_max)))
          : 0.;
      if (s0 > 0. && factor > 0.)
        return s0;
      // No load: mean(diag K)/mean(diag L) over the free cable dofs.
      return factor * model.diagonal_ratio(range, K, L, constraints);
    }

    void
    CableSubsystem::check_well_posed() const
    {
      // Before the first factorization: a cable with no support and nothing
      // that holds it would move as a rigid body.
      for (unsigned int k = 0; k < parameters.size(); ++k)
        {
          const auto &d = parameters[k];
          check_input(
            d.start_support != EndSupport::free
              || d.end_support != EndSupport::free || held.count(k),
            d.path,
            std::string("has no support (")
              + (d.closed() ? "a ring has no ends"
                            : "Start support and End support are free")
              + ") and no contact pair or tie holds it: it would move as a "
                "rigid body");
        }
    }

    void
    CableSubsystem::save_checkpoint(
      Checkpoint &checkpoint,
      const std::vector<const LA::Vector *> &) const
    {
      cables.save_checkpoint(checkpoint);
    }

    void
    CableSubsystem::load_checkpoint(const Checkpoint &checkpoint,
                                    const std::vector<LA::Vector *> &)
    {
      cables.load_checkpoint(checkpoint);
    }

    void
    CableSubsystem::first_guess(const double t, LA::Vector &field) const
    {
      cables.first_guess(t, field);
    }

    std::string
    CableSubsystem::begin_step(const double t, const LA::Vector &, bool &)
    {
      cables.check_prestress(t);
      return "";
    }

    bool
    CableSubsystem::ramp_initial_loads(const double t0, const double t1)
    {
      return cables.ramp_initial_loads(t0, t1);
    }

    void
    CableSubsystem::set_prescribed_values(const double t,
                                          LA::Vector  &field) const
    {
      cables.set_prescribed_values(t, field);
    }

    void
    CableSubsystem::assemble(const Assembly &a)
    {
      TimerOutput::Scope t(model.timer(), "cable assembly");
      cables.assemble(
        a.time, *a.field, *a.constraints, a.tangent, a.residual, a.external);
    }

    void
    CableSubsystem::commit_step(const double,
                                const LA::Vector &field,
                                const Vector<double> &)
    {
      cables.commit_step(field);
    }

    double
    CableSubsystem::force_scale(const LA::Vector &field) const
    {
      // The largest axial force at the current state, so that a
      // prestress-driven step without external load has a force scale.
      double n = 0.;
      for (const auto &r : cables.reports(model.time(), field))
        n = std::max({n, std::abs(r.max_force), std::abs(r.min_force)});
      return Utilities::MPI::max(n, model.mpi_communicator());
    }

    void
    CableSubsystem::add_statistics(Statistics       &statistics,
                                   const LA::Vector &field,
                                   const double      t) const
    {
      using S            = Statistics;
      constexpr auto all = S::all, report = S::report, summary = S::summary;
      constexpr auto root = S::Reduction::root;
      // The reports exist on rank 0, which owns the cable dofs; the end
      // reactions are the model's support residual (with contact, the
      // contact forces on the end too).
      auto reports = cables.reports(t, field, &model.support_residual());
      reports.resize(parameters.size());
      statistics.add_count(StatisticsGroup::run(),
                           "cable_elements",
                           cables.n_cells(),
                           summary);
      for (unsigned int k = 0; k < reports.size(); ++k)
        {
          const auto           &r = reports[k];
          const StatisticsGroup g{"cable", "cables", "cable", k + 1};
          statistics.add(g, "max_force", "N", r.max_force, all, root);
          statistics.add(g, "min_force", "N", r.min_force, all, root);
          statistics.add(g, "length", "m", r.length, all, root);
          statistics.add(
            g, "max_bending_moment", "N m", r.max_bending, summary, root);
          statistics.add(
            g, "max_torsion_moment", "N m", r.max_torsion, summary, root);
          statistics.add(
            g, "end_rotation", "rad", r.end_rotation, summary, root);
          statistics.add_vector(
            g, "start_reaction", "N", r.start_reaction, all, root);
          statistics.add_vector(
            g, "end_reaction", "N", r.end_reaction, report, root);
          statistics.add_vector(
            g, "start_u", "m", r.start_displacement, summary, root);
          statistics.add_vector(
            g, "end_u", "m", r.end_displacement, summary, root);
          statistics.add_vector(g, "mid_u", "m", r.mid_displacement, all, root);
        }
    }

    void
    CableSubsystem::write_output_files(const std::string &directory,
                                       const unsigned int step,
                                       const double       t,
                                       const LA::Vector  &field)
    {
      cables.write_output(directory, step, t, field);
    }
  } // namespace cables
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::cables::CableSubsystem,
                          "cables",
                          20,
                          pneuma::cables::CableSubsystem::declare_switches,
                          pneuma::cables::CableSubsystem::is_active)
