#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/data_out.h>

#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>
#include <pneuma/postprocess/membrane_fields.h>

#include "simulator_impl.h"

#include <filesystem>
#include <iomanip>

namespace pneuma
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::Anything(),
                      "Where solution.pvd, history.csv, summary.json and "
                      "parameters.prm are written (created if missing).");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write solution-NNNN.pvtu/.vtu and solution.pvd.");
    prm.declare_entry("VTU interval",
                      "1",
                      Patterns::Integer(0),
                      "Write VTU every this many converged steps (0: only "
                      "the initial and final states).");
    prm.declare_entry("Monitor points",
                      "",
                      Patterns::Anything(),
                      "Points 'x,y,z; x,y,z; ...' [m]: the displacement of "
                      "the nearest mesh vertex is written to history.csv "
                      "and summary.json.");
    prm.declare_entry("Quiet",
                      "false",
                      Patterns::Bool(),
                      "Print nothing while running (tests, scripted studies).");
    prm.declare_entry("Test output",
                      "false",
                      Patterns::Bool(),
                      "Also write a file 'output' in the working directory "
                      "with physics-level numbers at fixed precision (used "
                      "by the regression tests).");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory    = prm.get("Directory");
    write_vtu    = prm.get_bool("Write VTU");
    vtu_interval = prm.get_integer("VTU interval");
    test_output  = prm.get_bool("Test output");
    quiet        = prm.get_bool("Quiet");
    monitor_points.clear();
    for (const auto &item :
         Utilities::split_string_list(prm.get("Monitor points"), ';'))
      {
        const Point<3> p = loads::parse_point(item, "Output/Monitor points");
        monitor_points.push_back(p);
      }
    check_input(!directory.empty(), "Output/Directory", "must not be empty");
    prm.leave_subsection();
  }

  void
  Simulator::Impl::write_refinement_table(
    const std::vector<RunSummary::Cycle> &cycles) const
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream table(output.directory + "/refinement.csv");
    table << "cycle,cells,dofs,newton_iterations,exit_code,volume";
    for (unsigned int m = 0; m < output.monitor_points.size(); ++m)
      table << ",m" << m << "_ux,m" << m << "_uy,m" << m << "_uz";
    table << "\n" << std::setprecision(10);
    for (unsigned int k = 0; k < cycles.size(); ++k)
      {
        const auto &c = cycles[k];
        table << k << "," << c.n_cells << "," << c.n_dofs << ","
              << c.n_newton_iterations << "," << c.exit_code << ","
              << c.volume;
        for (const auto &u : c.monitor_displacements)
          table << "," << u[0] << "," << u[1] << "," << u[2];
        table << "\n";
      }
  }

  void
  Simulator::Impl::prepare_output_directory()
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        std::filesystem::create_directories(output.directory, ec);
        std::ofstream probe(output.directory + "/history.csv");
        if (!probe)
          throw InputError("Output/Directory",
                           "cannot write into '" + output.directory + "'");
      }
    MPI_Barrier(comm);
    pvd_records.clear();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        history =
          std::make_unique<std::ofstream>(output.directory + "/history.csv");
        *history << "step,time,newton_iterations,wall_seconds";
        if (geometry.is_closed())
          *history << ",volume";
        for (unsigned int m = 0; m < output.monitor_points.size(); ++m)
          *history << ",m" << m << "_ux,m" << m << "_uy,m" << m << "_uz";
        for (unsigned int c = 1; c <= chamber_parameters.chambers.size(); ++c)
          for (const char *name : {"pressure",
                                   "absolute_pressure",
                                   "volume",
                                   "gas_volume",
                                   "liquid_volume",
                                   "level",
                                   "wetted_area",
                                   "gas_amount"})
            *history << ",c" << c << "_" << name;
        for (unsigned int k = 1; k <= cable_parameters.size(); ++k)
          for (const char *name : {"max_force",
                                   "min_force",
                                   "length",
                                   "start_rx",
                                   "start_ry",
                                   "start_rz",
                                   "end_rx",
                                   "end_ry",
                                   "end_rz",
                                   "mid_ux",
                                   "mid_uy",
                                   "mid_uz"})
            *history << ",cable" << k << "_" << name;
        for (unsigned int k = 1; k <= contact_parameters.all().size(); ++k)
          for (const char *name : {"active_points",
                                   "total_force",
                                   "fx",
                                   "fy",
                                   "fz",
                                   "max_penetration"})
            *history << ",contact" << k << "_" << name;
        *history << "\n";
      }
  }

  void
  Simulator::Impl::locate_monitor_points()
  {
    monitor_dofs.clear();
    monitor_positions.clear();
    if (!has_membrane())
      return;
    for (const auto &p : output.monitor_points)
      {
        double local_min = std::numeric_limits<double>::max();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto v : cell->vertex_indices())
              local_min = std::min(local_min, cell->vertex(v).distance(p));
        const double global_min = Utilities::MPI::min(local_min, comm);
        // The lowest rank that owns a vertex at that distance reports it.
        std::array<types::global_dof_index, 3> dofs;
        dofs.fill(numbers::invalid_dof_index);
        std::array<double, 3> position{{0., 0., 0.}};
        bool                  found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && !found)
            for (const auto v : cell->vertex_indices())
              if (cell->vertex(v).distance(p) <= global_min * (1 + 1e-12)
                  && locally_owned.is_element(cell->vertex_dof_index(v, 0)))
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      dofs[c]     = cell->vertex_dof_index(v, c);
                      position[c] = cell->vertex(v)[c];
                    }
                  found = true;
                  break;
                }
        const unsigned int me = Utilities::MPI::this_mpi_process(comm);
        const unsigned int reporter =
          Utilities::MPI::min(found ? me : numbers::invalid_unsigned_int, comm);
        if (me != reporter)
          {
            dofs.fill(numbers::invalid_dof_index);
            position.fill(0.);
          }
        for (unsigned int c = 0; c < 3; ++c)
          position[c] = Utilities::MPI::sum(position[c], comm);
        monitor_dofs.push_back(dofs);
        monitor_positions.push_back(position);
      }
  }

  std::vector<std::array<double, 3>>
  Simulator::Impl::monitor_displacements()
  {
    std::vector<std::array<double, 3>> values;
    for (const auto &dofs : monitor_dofs)
      {
        std::array<double, 3> u{{0., 0., 0.}};
        for (unsigned int c = 0; c < 3; ++c)
          {
            if (dofs[c] != numbers::invalid_dof_index)
              u[c] = solution[dofs[c]];
            u[c] = Utilities::MPI::sum(u[c], comm);
          }
        values.push_back(u);
      }
    return values;
  }

  void
  Simulator::Impl::write_history_row(const unsigned int step,
                                     const double       t,
                                     const unsigned int newton_iterations)
  {
    ghosted = solution;
    const double volume =
      geometry.is_closed() ? assembler.enclosed_volume(ghosted) : 0.;
    const auto monitors = monitor_displacements();
    const auto cables   = cable_states();
    if (history)
      {
        *history << step << ',' << std::setprecision(10) << t << ','
                 << newton_iterations << ',' << std::setprecision(4)
                 << wall_clock.wall_time() << std::setprecision(10);
        if (geometry.is_closed())
          *history << ',' << volume;
        for (const auto &u : monitors)
          *history << ',' << u[0] << ',' << u[1] << ',' << u[2];
        for (const auto &c : chamber_system.reports())
          *history << ',' << c.pressure << ',' << c.absolute_pressure << ','
                   << c.volume << ',' << c.gas_volume << ',' << c.liquid_volume
                   << ',' << c.level << ',' << c.wetted_area << ','
                   << c.gas_amount;
        for (const auto &c : cables)
          {
            *history << ',' << c.max_force << ',' << c.min_force << ','
                     << c.length;
            for (const auto *v : {&c.start_reaction,
                                  &c.end_reaction,
                                  &c.mid_displacement})
              *history << ',' << (*v)[0] << ',' << (*v)[1] << ',' << (*v)[2];
          }
        for (const auto &c : contact_states())
          *history << ',' << c.active_points << ',' << c.total_force << ','
                   << c.force[0] << ',' << c.force[1] << ',' << c.force[2]
                   << ',' << c.max_penetration;
        *history << std::endl;
      }
  }

  void
  Simulator::Impl::write_vtu(const unsigned int step, const double t)
  {
    TimerOutput::Scope timer_scope(timer, "output");
    ghosted = solution;
    // Never write a non-finite state.
    AssertThrow(std::isfinite(solution.l2_norm()),
                ExcMessage("refusing to write a non-finite solution"));
    if (!contact_system.empty())
      for (const auto &pair : contact_parameters.all())
        cable_system.set_output_field(pair.cable,
                                      "contact_line_load",
                                      contact_system.cable_line_load(
                                        pair.cable));
    if (!cable_system.empty())
      cable_system.write_output(output.directory, step, t, ghosted);
    if (!has_membrane())
      return;

    const postprocess::CellFields fields = postprocess::membrane_cell_fields(
      *mapping, dof_handler, materials, ghosted);
    DataOut<2, 3> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<std::string> names(3, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(3,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(ghosted,
                             names,
                             DataOut<2, 3>::type_dof_data,
                             interpretation);
    for (unsigned int i = 0; i < fields.names.size(); ++i)
      data_out.add_data_vector(fields.values[i],
                               fields.names[i],
                               DataOut<2, 3>::type_cell_data);
    chambers::ChamberCellData chamber_cells;
    if (!chamber_parameters.empty())
      {
        chamber_cells = chamber_assembler.cell_data(
          ghosted, chamber_system.converged_loads());
        data_out.add_data_vector(chamber_cells.chamber,
                                 "chamber",
                                 DataOut<2, 3>::type_cell_data);
        data_out.add_data_vector(chamber_cells.wetted,
                                 "wetted",
                                 DataOut<2, 3>::type_cell_data);
        data_out.add_data_vector(chamber_cells.pressure,
                                 "chamber_pressure",
                                 DataOut<2, 3>::type_cell_data);
      }
    Vector<float> contact_pressure;
    if (!contact_system.empty())
      {
        contact_pressure =
          contact_system.membrane_pressure(triangulation.n_active_cells());
        data_out.add_data_vector(contact_pressure,
                                 "contact_pressure",
                                 DataOut<2, 3>::type_cell_data);
      }
    Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = triangulation.locally_owned_subdomain();
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(*mapping, degree, DataOut<2, 3>::curved_inner_cells);
    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      output.directory + "/", "solution", step, comm, 4);
    pvd_records.emplace_back(t, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream pvd(output.directory + "/solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvd_records);
      }
  }

  void
  Simulator::Impl::compute_reactions(std::array<double, 3> &reaction,
                                     std::array<double, 3> &applied)
  {
    // Residual with hanging-node and rigid-plate forces condensed onto the
    // independent dofs: at a prescribed dof, f_int - f_ext is the force the
    // support exerts on the structure (the reaction). Membrane only; the
    // cable supports are in the cable reports.
    reaction.fill(0.);
    applied.fill(0.);
    if (!has_membrane())
      return;
    LA::Vector residual(solution), ext(solution);
    ghosted = solution;
    membrane::AssemblyRequest request;
    request.time     = current_time;
    request.residual = &residual;
    request.external = &ext;
    assembler.assemble(ghosted, kinematic_constraints, request);
    if (!chamber_parameters.empty())
      {
        // Chamber loads: -f into the residual, +f into the applied loads.
        LA::Vector chamber_part(solution);
        chamber_part = 0.;
        std::vector<chambers::ChamberMeasures> measures;
        chamber_assembler.assemble(ghosted,
                                   kinematic_constraints,
                                   chamber_system.converged_loads(),
                                   &chamber_part,
                                   nullptr,
                                   measures,
                                   false);
        residual += chamber_part;
        ext -= chamber_part;
      }
    reaction.fill(0.);
    applied.fill(0.);
    // Component of each owned dof.
    for (unsigned int c = 0; c < 3; ++c)
      {
        std::vector<bool> mask(3, false);
        mask[c] = true;
        const IndexSet component_dofs =
          DoFTools::extract_dofs(dof_handler, ComponentMask(mask));
        for (const auto i : component_dofs)
          {
            applied[c] += ext[i];
            if (constraints.is_constrained(i)
                && constraints.get_constraint_entries(i)->empty())
              reaction[c] += residual[i];
          }
        reaction[c] = Utilities::MPI::sum(reaction[c], comm);
        applied[c]  = Utilities::MPI::sum(applied[c], comm);
      }
  }

  void
  Simulator::Impl::write_summary(const RunSummary &summary)
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream json(output.directory + "/summary.json");
    json << std::setprecision(10);
    json << "{\n"
         << "  \"exit_code\": " << summary.exit_code << ",\n"
         << "  \"message\": \"" << summary.message << "\",\n"
         << "  \"cells\": " << summary.n_cells << ",\n"
         << "  \"dofs\": " << summary.n_dofs << ",\n"
         << "  \"mpi_ranks\": " << Utilities::MPI::n_mpi_processes(comm)
         << ",\n"
         << "  \"steps\": " << summary.n_steps << ",\n"
         << "  \"cutbacks\": " << summary.n_cutbacks << ",\n"
         << "  \"newton_iterations\": " << summary.n_newton_iterations << ",\n"
         << "  \"linear_solves\": " << summary.n_linear_solves << ",\n"
         << "  \"factorizations\": " << summary.n_factorizations << ",\n"
         << "  \"krylov_iterations\": " << summary.n_krylov_iterations << ",\n"
         << "  \"final_time\": " << summary.final_time << ",\n"
         << "  \"initial_volume\": " << summary.initial_volume << ",\n"
         << "  \"volume\": " << summary.volume << ",\n"
         << "  \"reaction\": [" << summary.reaction[0] << ", "
         << summary.reaction[1] << ", " << summary.reaction[2] << "],\n"
         << "  \"applied_load\": [" << summary.applied_load[0] << ", "
         << summary.applied_load[1] << ", " << summary.applied_load[2] << "],\n"
         << "  \"chambers\": [";
    for (unsigned int c = 0; c < summary.chambers.size(); ++c)
      {
        const auto &r = summary.chambers[c];
        json << (c ? ",\n" : "\n") << "    {\"chamber\": " << c + 1
             << ", \"pressure\": " << r.pressure
             << ", \"absolute_pressure\": " << r.absolute_pressure
             << ", \"volume\": " << r.volume
             << ", \"gas_volume\": " << r.gas_volume
             << ", \"liquid_volume\": " << r.liquid_volume
             << ", \"level\": " << r.level
             << ", \"wetted_area\": " << r.wetted_area
             << ", \"gas_amount\": " << r.gas_amount << "}";
      }
    json << (summary.chambers.empty() ? "" : "\n  ") << "],\n"
         << "  \"cable_elements\": " << summary.n_cable_cells << ",\n"
         << "  \"cables\": [";
    const auto triple = [&json](const std::array<double, 3> &v) {
      json << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
    };
    for (unsigned int k = 0; k < summary.cables.size(); ++k)
      {
        const auto &c = summary.cables[k];
        json << (k ? ",\n" : "\n") << "    {\"cable\": " << k + 1
             << ", \"max_force\": " << c.max_force
             << ", \"min_force\": " << c.min_force
             << ", \"length\": " << c.length
             << ", \"max_bending_moment\": " << c.max_bending
             << ", \"max_torsion_moment\": " << c.max_torsion
             << ", \"end_rotation\": " << c.end_rotation
             << ", \"start_reaction\": ";
        triple(c.start_reaction);
        json << ", \"end_reaction\": ";
        triple(c.end_reaction);
        json << ", \"start_displacement\": ";
        triple(c.start_displacement);
        json << ", \"end_displacement\": ";
        triple(c.end_displacement);
        json << ", \"mid_displacement\": ";
        triple(c.mid_displacement);
        json << "}";
      }
    json << (summary.cables.empty() ? "" : "\n  ") << "],\n"
         << "  \"contact\": [";
    for (unsigned int k = 0; k < summary.contact.size(); ++k)
      {
        const auto &c = summary.contact[k];
        json << (k ? ",\n" : "\n") << "    {\"pair\": " << k + 1
             << ", \"active_points\": " << c.active_points
             << ", \"points\": " << c.points
             << ", \"total_force\": " << c.total_force
             << ", \"max_penetration\": " << c.max_penetration
             << ", \"slip_points\": " << c.slip_points
             << ", \"friction_force\": " << c.friction_force
             << ", \"force\": ";
        triple(c.force);
        json << "}";
      }
    json << (summary.contact.empty() ? "" : "\n  ") << "],\n"
         << "  \"monitor_points\": [";
    for (unsigned int m = 0; m < summary.monitor_displacements.size(); ++m)
      {
        const auto &x = summary.monitor_positions[m];
        const auto &u = summary.monitor_displacements[m];
        json << (m ? ",\n" : "\n") << "    {\"position\": [" << x[0] << ", "
             << x[1] << ", " << x[2] << "], \"displacement\": [" << u[0] << ", "
             << u[1] << ", " << u[2] << "]}";
      }
    json << "\n  ],\n  \"timings\": {";
    const auto times = timer.get_summary_data(TimerOutput::total_wall_time);
    bool       first = true;
    for (const auto &t : times)
      {
        json << (first ? "" : ",") << "\n    \"" << t.first
             << "\": " << t.second;
        first = false;
      }
    json << "\n  },\n  \"wall_seconds\": " << summary.wall_seconds << "\n}\n";

    if (output.test_output)
      {
        // Physics-level numbers only (no timings), for numdiff.
        std::ofstream out("output");
        out << std::scientific << std::setprecision(4);
        out << "exit_code " << summary.exit_code << "\n"
            << "cells " << summary.n_cells << "\n"
            << "dofs " << summary.n_dofs << "\n"
            << "final_time " << summary.final_time << "\n";
        if (geometry.is_closed())
          out << "volume " << summary.volume << "\n";
        for (unsigned int m = 0; m < summary.monitor_displacements.size(); ++m)
          {
            const auto &u = summary.monitor_displacements[m];
            out << "monitor " << m << " u = " << u[0] << " " << u[1] << " "
                << u[2] << "\n";
          }
        for (unsigned int c = 0; c < summary.chambers.size(); ++c)
          {
            const auto &r = summary.chambers[c];
            out << "chamber " << c + 1 << " p = " << r.pressure
                << " V = " << r.volume << " V_liquid = " << r.liquid_volume
                << " level = " << r.level << "\n";
          }
        for (unsigned int k = 0; k < summary.cables.size(); ++k)
          {
            const auto &c = summary.cables[k];
            out << "cable " << k + 1 << " N_max = " << c.max_force
                << " N_min = " << c.min_force << " length = " << c.length
                << " start_reaction = " << c.start_reaction[0] << " "
                << c.start_reaction[1] << " " << c.start_reaction[2]
                << " mid_u = " << c.mid_displacement[0] << " "
                << c.mid_displacement[1] << " " << c.mid_displacement[2]
                << "\n";
          }
        for (unsigned int k = 0; k < summary.contact.size(); ++k)
          {
            const auto &c = summary.contact[k];
            out << "contact " << k + 1 << " active " << c.active_points << "/"
                << c.points << " total_force = " << c.total_force
                << " force = " << c.force[0] << " " << c.force[1] << " "
                << c.force[2] << " max_penetration = " << c.max_penetration
                << "\n";
          }
      }
  }
} // namespace pneuma
