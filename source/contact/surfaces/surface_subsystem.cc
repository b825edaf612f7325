#include <pneuma/contact/surfaces/surface_subsystem.h>
#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>

#include <iomanip>
#include <sstream>

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
                    "Surface contact/Number of pairs",
                    "surface contact needs a membrane (Geometry/Type is none)");
        return *m;
      }
    } // namespace

    SurfaceSubsystem::SurfaceSubsystem(Model &model)
      : model(model)
      , membrane(the_membrane(model))
    {
    }

    void
    SurfaceSubsystem::declare_switches(ParameterHandler &prm)
    {
      SurfaceParameters::declare_count(prm);
    }

    bool
    SurfaceSubsystem::is_active(const InputLayout &layout)
    {
      return !layout
                .numbered("Surface contact",
                          "Pair",
                          "Surface contact/Number of pairs")
                .empty();
    }

    void
    SurfaceSubsystem::declare_parameters(ParameterHandler  &prm,
                                         const InputLayout &layout)
    {
      parameters.declare_parameters(prm, layout);
    }

    void
    SurfaceSubsystem::parse_parameters(ParameterHandler &prm)
    {
      parameters.parse_parameters(prm);
    }

    void
    SurfaceSubsystem::add_locally_relevant(IndexSet &relevant)
    {
      const auto &ids = membrane.material_ids();
      for (const auto &p : parameters.pairs)
        for (const auto &set : {p.first, p.second})
          for (const auto id : set)
            check_input(ids.count(id) > 0,
                        p.path
                          + (set == p.first ? "/Regions" : "/Opposite regions"),
                        "the mesh has no cells in region "
                          + std::to_string(id));
      contact = std::make_unique<SurfaceContact>(parameters.pairs,
                                                 membrane.material_regions());
      contact->setup(membrane.mapping(),
                     membrane.dof_handler(),
                     model.mpi_communicator());
      relevant.add_indices(contact->relevant_dofs(relevant.size()));
      contact->commit(nullptr);
      contact->update_candidates(nullptr);
    }

    void
    SurfaceSubsystem::finish_setup()
    {
      for (unsigned int k = 0; k < contact->size(); ++k)
        {
          const auto &p       = parameters.pairs[k];
          const auto [lo, hi] = contact->penalty_range(k);
          std::ostringstream s;
          s << std::setprecision(3) << p.path << ": "
            << (p.self() ? "self-contact" : "two sides") << "; penalty ";
          if (p.penalty > 0.)
            s << p.penalty << " Pa/m (given)";
          else
            s << lo << " to " << hi << " Pa/m (" << p.penalty_factor
              << " E t / h^2; Penalty = 0)";
          s << "; search distance ";
          if (p.search_distance > 0.)
            s << p.search_distance << " m (given)";
          else
            s << "4 x the last step's motion, from "
              << contact->search_distance(k) << " m (a quarter of the "
              << "largest cell)";
          if (const unsigned int n = contact->seam_pairs(k))
            s << "; " << n
              << " cell pairs next to a seam start closer than their half "
                 "thicknesses and are left out of each other's contact, like "
                 "the cells on the seam";
          model.out() << s.str() << std::endl;
        }
    }

    void
    SurfaceSubsystem::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      contact->add_sparsity(dsp, constraints);
    }

    void
    SurfaceSubsystem::initialize(const LA::Vector &field, const double)
    {
      throw_if_any(model.mpi_communicator(), contact->check(field, true));
      refresh(field);
    }

    std::string
    SurfaceSubsystem::begin_step(const double,
                                 const LA::Vector &field,
                                 bool             &grown)
    {
      TimerOutput::Scope t(model.timer(), "surface contact search");
      if (contact->update_candidates(&field))
        grown = true;
      return "";
    }

    void
    SurfaceSubsystem::assemble(const Assembly &a)
    {
      TimerOutput::Scope t(model.timer(), "surface contact");
      contact->assemble(
        *a.field, *a.constraints, a.tangent, a.residual, nullptr);
    }

    std::string
    SurfaceSubsystem::check_state(const LA::Vector &field) const
    {
      TimerOutput::Scope t(model.timer(), "surface contact search");
      return contact->check(field, false);
    }

    void
    SurfaceSubsystem::refresh(const LA::Vector &field)
    {
      // Every refresh is of an accepted state (a committed step, the end
      // of a strategy, a restored checkpoint): the sides of the next
      // step's points are measured in it, so a restart takes them from the
      // restored state, not from the reference.
      contact->commit(&field);
      record(field);
    }

    void
    SurfaceSubsystem::record(const LA::Vector &field)
    {
      contact->assemble(
        field, model.constraints(), nullptr, nullptr, &recorded);
    }

    void
    SurfaceSubsystem::commit_step(const double,
                                  const LA::Vector &field,
                                  const Vector<double> &)
    {
      refresh(field);
    }

    void
    SurfaceSubsystem::add_statistics(Statistics &statistics,
                                     const LA::Vector &,
                                     const double) const
    {
      constexpr auto all = Statistics::all;
      for (unsigned int k = 0; k < recorded.reports.size(); ++k)
        {
          const SurfaceReport  &r = recorded.reports[k];
          const StatisticsGroup g{"surface", "surface_contact", "pair", k + 1};
          statistics.add(g, "total_force", "N", r.total_force, all);
          statistics.add_vector(
            g, "force", "N", {{r.force[0], r.force[1], r.force[2]}}, all);
          statistics.add(g, "contact_area", "m^2", r.area, all);
          statistics.add(g, "penetration", "m", r.penetration, all);
          statistics.add(g, "energy", "J", r.energy, Statistics::report);
          statistics.add_count(g,
                               "active_points",
                               r.active_points,
                               Statistics::report);
          statistics.add_count(g,
                               "points",
                               r.points,
                               all & ~Statistics::history);
          if (statistics.is_summary())
            {
              const auto [lo, hi] = contact->penalty_range(k);
              statistics.add(g, "penalty_min", "Pa/m", lo, Statistics::summary);
              statistics.add(g, "penalty_max", "Pa/m", hi, Statistics::summary);
            }
        }
    }

    void
    SurfaceSubsystem::add_output_fields(const LA::Vector &field, const double)
    {
      record(field);
      const auto &of = contact->surface_cell_of_active();
      pressure_output.reinit(of.size());
      gap_output.reinit(of.size());
      double reach = 0.;
      for (unsigned int k = 0; k < contact->size(); ++k)
        reach = std::max(reach, contact->search_distance(k));
      for (unsigned int i = 0; i < of.size(); ++i)
        if (of[i] >= 0)
          {
            const double area = recorded.cell_area[of[i]];
            pressure_output[i] =
              area > 0. ? recorded.cell_force[of[i]] / area : 0.;
            // A cell with no other cell within reach: the reach.
            gap_output[i] = std::min(recorded.cell_gap[of[i]], reach);
          }
      auto &out = membrane.data_out();
      out.add_data_vector(pressure_output,
                          "surface_contact_pressure",
                          DataOut<2, 3>::type_cell_data);
      out.add_data_vector(gap_output,
                          "surface_contact_gap",
                          DataOut<2, 3>::type_cell_data);
    }
  } // namespace contact
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::contact::SurfaceSubsystem,
                          "surface contact",
                          46,
                          pneuma::contact::SurfaceSubsystem::declare_switches,
                          pneuma::contact::SurfaceSubsystem::is_active)
