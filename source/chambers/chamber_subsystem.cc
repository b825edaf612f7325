#include <pneuma/chambers/chamber_subsystem.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>

namespace pneuma
{
  namespace chambers
  {
    namespace
    {
      membrane::MembraneSubsystem &
      the_membrane(Model &model)
      {
        auto *m = model.find<membrane::MembraneSubsystem>();
        check_input(m != nullptr,
                    "Chambers/Number of chambers",
                    "chambers need a membrane (Geometry/Type is none)");
        return *m;
      }
    } // namespace

    ChamberSubsystem::ChamberSubsystem(Model &model)
      : model(model)
      , membrane(the_membrane(model))
      , assembler(membrane.geometry(), parameters)
      , system(parameters, assembler)
    {
      membrane.add_cell_terms(*this);
    }

    void
    ChamberSubsystem::declare_switches(ParameterHandler &prm)
    {
      ChamberParameters::declare_count(prm);
    }

    bool
    ChamberSubsystem::is_active(const InputLayout &layout)
    {
      return !layout
                .numbered("Chambers", "Chamber", "Chambers/Number of chambers")
                .empty();
    }

    void
    ChamberSubsystem::declare_parameters(ParameterHandler  &prm,
                                         const InputLayout &layout)
    {
      parameters.declare_parameters(prm, layout);
    }

    void
    ChamberSubsystem::parse_parameters(ParameterHandler &prm)
    {
      parameters.parse_parameters(prm);
    }

    types::global_dof_index
    ChamberSubsystem::setup_unknowns(const types::global_dof_index,
                                     const MPI_Comm)
    {
      system.setup_groups();
      return 0;
    }

    void
    ChamberSubsystem::finish_setup()
    {
      assembler.reinit(membrane.mapping(),
                       membrane.dof_handler(),
                       membrane.degree(),
                       [this]() -> const membrane::ReferenceGeometry & {
                         return membrane.reference_geometry();
                       });
      assembler.check_chambers();
    }

    Vector<double>
    ChamberSubsystem::own_part(const Vector<double> &border) const
    {
      const unsigned int offset = model.border_offset(*this);
      Vector<double>     part(n_border_unknowns());
      for (unsigned int j = 0; j < part.size(); ++j)
        part[j] = border[offset + j];
      return part;
    }

    void
    ChamberSubsystem::initialize(const LA::Vector &field, const double t)
    {
      system.initialize(field, t);
    }

    std::string
    ChamberSubsystem::begin_step(const double      t,
                                 const LA::Vector &field,
                                 bool &)
    {
      return system.begin_step(field, t);
    }

    void
    ChamberSubsystem::begin(const Assembly &a)
    {
      pass_loads = system.loads(own_part(*a.border));
      pass       = std::make_unique<ChamberAssembler::Pass>(
        assembler, *a.field, *a.constraints, pass_loads, measures, true);
    }

    std::unique_ptr<membrane::CellTerms::Scratch>
    ChamberSubsystem::new_scratch() const
    {
      return std::make_unique<ChamberAssembler::Pass::Scratch>(assembler);
    }

    std::unique_ptr<membrane::CellTerms::Record>
    ChamberSubsystem::new_record() const
    {
      return std::make_unique<ChamberAssembler::Pass::Record>();
    }

    void
    ChamberSubsystem::cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
                           const membrane::ReferenceGeometry &reference,
                           const unsigned int                 cell_index,
                           const std::vector<double>         &local_u,
                           FullMatrix<double>                *cell_matrix,
                           Vector<double>                    *cell_residual,
                           membrane::CellTerms::Scratch      &scratch,
                           membrane::CellTerms::Record       &record) const
    {
      pass->compute(cell,
                    reference,
                    cell_index,
                    local_u,
                    cell_matrix,
                    cell_residual,
                    static_cast<ChamberAssembler::Pass::Scratch &>(scratch),
                    static_cast<ChamberAssembler::Pass::Record &>(record));
    }

    void
    ChamberSubsystem::commit(
      const membrane::CellTerms::Record          &record,
      const std::vector<types::global_dof_index> &dof_indices)
    {
      pass->commit(static_cast<const ChamberAssembler::Pass::Record &>(record),
                   dof_indices);
    }

    void
    ChamberSubsystem::end()
    {
      pass->finish();
      pass.reset();
    }

    void
    ChamberSubsystem::assemble(const Assembly &a)
    {
      // The measures come from the membrane's pass (this subsystem's cell
      // terms), which runs first.
      const unsigned int offset = model.border_offset(*this);
      Vector<double>     residual;
      system.set_time(a.time);
      system.evaluate(
        own_part(*a.border), measures, residual, *a.coupling, offset);
      for (unsigned int j = 0; j < residual.size(); ++j)
        (*a.border_residual)[offset + j] = residual[j];
    }

    void
    ChamberSubsystem::add_loads(const LA::Vector                &u,
                                const AffineConstraints<double> &constraints,
                                const double,
                                LA::Vector &residual,
                                LA::Vector &external) const
    {
      // Chamber loads: -f into the residual, +f into the applied loads.
      LA::Vector chamber_part(residual);
      chamber_part = 0.;
      std::vector<ChamberMeasures> m;
      assembler.assemble(u,
                         constraints,
                         system.converged_loads(),
                         &chamber_part,
                         nullptr,
                         m,
                         false);
      residual += chamber_part;
      external -= chamber_part;
    }

    void
    ChamberSubsystem::commit_step(const double          t,
                                  const LA::Vector     &field,
                                  const Vector<double> &border)
    {
      system.unpack(border);
      system.commit_step(field, t, model.out());
    }

    void
    ChamberSubsystem::save_checkpoint(
      Checkpoint &checkpoint,
      const std::vector<const LA::Vector *> &) const
    {
      system.save_checkpoint(checkpoint);
    }

    void
    ChamberSubsystem::load_checkpoint(const Checkpoint &checkpoint,
                                      const std::vector<LA::Vector *> &)
    {
      system.load_checkpoint(checkpoint);
      restored = true;
    }

    void
    ChamberSubsystem::refresh(const LA::Vector &field)
    {
      if (restored)
        system.record(field);
      restored = false;
    }

    double
    ChamberSubsystem::force_scale(const LA::Vector &) const
    {
      return system.force_scale();
    }

    double
    ChamberSubsystem::start_prestress(const LA::Vector &) const
    {
      double virial = 0., area = 0.;
      for (unsigned int c = 0; c < std::min(pass_loads.size(), measures.size());
           ++c)
        {
          if (pass_loads[c].gas && pass_loads[c].gas_pressure > 0.)
            virial += 3. * pass_loads[c].gas_pressure * measures[c].volume;
          area += measures[c].wall_area;
        }
      return area > 0. && virial > 0. ? virial / (2. * area) : 0.;
    }

    Vector<double>
    ChamberSubsystem::border_for(
      const LA::Vector              &field,
      const double                   t,
      const Vector<double>          &border,
      std::vector<BorderConstraint> &constraints) const
    {
      return system.border_for(field, t, border, constraints);
    }

    void
    ChamberSubsystem::add_statistics(Statistics &statistics,
                                     const LA::Vector &,
                                     const double) const
    {
      constexpr auto all = Statistics::all, report = Statistics::report;
      const auto    &reports = system.reports();
      for (unsigned int c = 0; c < reports.size(); ++c)
        {
          const auto           &r = reports[c];
          const StatisticsGroup g{"c", "chambers", "chamber", c + 1};
          statistics.add(g, "pressure", "Pa", r.pressure, all);
          statistics.add(
            g, "absolute_pressure", "Pa", r.absolute_pressure, report);
          statistics.add(g, "volume", "m^3", r.volume, all);
          statistics.add(g, "gas_volume", "m^3", r.gas_volume, report);
          statistics.add(g, "liquid_volume", "m^3", r.liquid_volume, all);
          statistics.add(g, "level", "m", r.level, all);
          statistics.add(g, "wetted_area", "m^2", r.wetted_area, report);
          statistics.add(g, "gas_amount", "m^3", r.gas_amount, report);
          statistics.add(
            g, "pv_kappa", "Pa m^(3 kappa)", r.pv_kappa, Statistics::summary);
        }
    }

    void
    ChamberSubsystem::add_output_fields(const LA::Vector &field, const double)
    {
      output_cells = assembler.cell_data(field, system.converged_loads());
      auto &out    = membrane.data_out();
      out.add_data_vector(output_cells.chamber,
                          "chamber",
                          DataOut<2, 3>::type_cell_data);
      out.add_data_vector(output_cells.wetted,
                          "wetted",
                          DataOut<2, 3>::type_cell_data);
      out.add_data_vector(output_cells.pressure,
                          "chamber_pressure",
                          DataOut<2, 3>::type_cell_data);
    }
  } // namespace chambers
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::chambers::ChamberSubsystem,
                          "chambers",
                          30,
                          pneuma::chambers::ChamberSubsystem::declare_switches,
                          pneuma::chambers::ChamberSubsystem::is_active)
