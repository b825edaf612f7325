#include <pneuma/contact/contact_subsystem.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      membrane::MembraneSubsystem &
      the_membrane(Model &model)
      {
        auto *m = model.find<membrane::MembraneSubsystem>();
        check_input(m != nullptr,
                    "Contact/Number of pairs",
                    "contact needs a membrane (Geometry/Type is none)");
        return *m;
      }
    } // namespace

    ContactSubsystem::ContactSubsystem(Model &model)
      : model(model)
      , membrane(the_membrane(model))
      , cables(model.find<cables::CableSubsystem>())
    {
    }

    bool
    ContactSubsystem::holds(const Subsystem &other) const
    {
      // Supported cables may hold the membrane they press on.
      return &other == &membrane;
    }

    void
    ContactSubsystem::declare_switches(ParameterHandler &prm)
    {
      ContactParameters::declare_count(prm);
    }

    bool
    ContactSubsystem::is_active(const InputLayout &layout)
    {
      return !layout.numbered("Contact", "Pair", "Contact/Number of pairs")
                .empty();
    }

    void
    ContactSubsystem::declare_parameters(ParameterHandler  &prm,
                                         const InputLayout &layout)
    {
      parameters.declare_parameters(prm, layout);
    }

    void
    ContactSubsystem::parse_parameters(ParameterHandler &prm)
    {
      parameters.parse_parameters(prm,
                                  cables ? cables->definitions().size() : 0);
      for (const auto &pair : parameters.all())
        cables->hold(pair.cable);
      contact = std::make_unique<ContactSystem>(parameters,
                                                membrane.geometry(),
                                                cables->system());
    }

    void
    ContactSubsystem::add_locally_relevant(IndexSet &relevant)
    {
      // Every master region must exist in the mesh.
      for (unsigned int k = 0; k < parameters.all().size(); ++k)
        for (const auto id : parameters.all()[k].regions)
          check_input(membrane.material_ids().count(id) > 0,
                      parameters.all()[k].path + "/Membrane regions",
                      "the mesh has no cells in region " + std::to_string(id));
      // Every rank sees the mid-lines of the paired cables.
      contact->setup(membrane.mapping(),
                     membrane.dof_handler(),
                     model.mpi_communicator());
      relevant.add_indices(contact->cable_dofs(relevant.size()));
      contact->update_candidates(nullptr);
    }

    void
    ContactSubsystem::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      contact->add_sparsity(dsp, constraints);
    }

    void
    ContactSubsystem::initialize(const LA::Vector &field, const double)
    {
      // Friction: points in contact at the start stick where they are.
      refresh(field);
      contact->commit_step();
    }

    std::string
    ContactSubsystem::begin_step(const double      time,
                                 const LA::Vector &field,
                                 bool             &grown)
    {
      // Facet or smoothed normal for this step; turning smoothed brings
      // the nodal normals' couplings into the pattern.
      if (contact->set_time(time))
        grown = true;
      // New candidates of the current state; the sparsity pattern grows if
      // they bring new couplings.
      TimerOutput::Scope t(model.timer(), "contact search");
      if (contact->update_candidates(&field))
        grown = true;
      return "";
    }

    void
    ContactSubsystem::assemble(const Assembly &a)
    {
      TimerOutput::Scope t(model.timer(), "contact");
      // The contact's own record is left as it was: what the assembly
      // finds goes to a scratch record (the state is recorded at
      // refresh()); a slipping point makes the tangent non-symmetric.
      contact::ContactRecord record = contact->new_record();
      contact->assemble(
        *a.field, *a.constraints, a.tangent, a.residual, record);
      if (a.symmetric)
        for (const auto &r : record.reports)
          if (r.slip_points > 0)
            *a.symmetric = false;
    }

    bool
    ContactSubsystem::symmetric_tangent() const
    {
      // The smoothed normal's force; Coulomb slip, t = mu N t_trial /
      // |t_trial|, is reported per assembly (Assembly::symmetric): the
      // tangent of a slipping point is not symmetric (Wriggers, ch. 5),
      // however small its asymmetric part measures.
      return !contact->smoothed();
    }

    std::string
    ContactSubsystem::check_state(const LA::Vector &field) const
    {
      TimerOutput::Scope t(model.timer(), "contact search");
      return contact->check_step(field);
    }

    void
    ContactSubsystem::save_checkpoint(
      Checkpoint &checkpoint,
      const std::vector<const LA::Vector *> &) const
    {
      contact->save_checkpoint(checkpoint);
    }

    void
    ContactSubsystem::load_checkpoint(const Checkpoint &checkpoint,
                                      const std::vector<LA::Vector *> &)
    {
      contact->load_checkpoint(checkpoint);
    }

    void
    ContactSubsystem::refresh(const LA::Vector &field)
    {
      contact->record_state(field, model.constraints());
    }

    void
    ContactSubsystem::commit_step(const double,
                                  const LA::Vector &field,
                                  const Vector<double> &)
    {
      // The reports and the friction anchors of the accepted state.
      refresh(field);
      contact->commit_step();
    }

    void
    ContactSubsystem::add_statistics(Statistics &statistics,
                                     const LA::Vector &,
                                     const double) const
    {
      constexpr auto all = Statistics::all, summary = Statistics::summary;
      const auto    &reports = contact->reports();
      for (unsigned int k = 0; k < reports.size(); ++k)
        {
          const auto           &r = reports[k];
          const StatisticsGroup g{"contact", "contact", "pair", k + 1};
          statistics.add_count(g, "active_points", r.active_points, all);
          statistics.add_count(g,
                               "points",
                               r.points,
                               all & ~Statistics::history);
          statistics.add(g, "total_force", "N", r.total_force, all);
          statistics.add_vector(g, "force", "N", r.force, all);
          statistics.add(g, "max_penetration", "m", r.max_penetration, all);
          statistics.add_count(g, "slip_points", r.slip_points, summary);
          statistics.add(g, "friction_force", "N", r.friction_force, summary);
        }
    }

    void
    ContactSubsystem::add_output_fields(const LA::Vector &, const double)
    {
      for (const auto &pair : parameters.all())
        cables->system().set_output_field(pair.cable,
                                          "contact_line_load",
                                          contact->cable_line_load(pair.cable));
      pressure_output =
        contact->membrane_pressure(membrane.triangulation().n_active_cells());
      membrane.data_out().add_data_vector(pressure_output,
                                          "contact_pressure",
                                          DataOut<2, 3>::type_cell_data);
    }
  } // namespace contact
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::contact::ContactSubsystem,
                          "contact",
                          40,
                          pneuma::contact::ContactSubsystem::declare_switches,
                          pneuma::contact::ContactSubsystem::is_active)
