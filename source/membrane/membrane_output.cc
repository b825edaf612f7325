/**
 * @file
 * The membrane's fields and files: the VTU fields of a state and of
 * mode shapes, the VTU series, and its mesh and field in checkpoints
 * (p4est) and in adaptive refinement.
 */

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <pneuma/core/checkpoint.h>
#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>
#include <pneuma/core/reproducible_output.h>
#include <pneuma/core/share_constraints.h>
#include <pneuma/membrane/face_assembly.h>
#include <pneuma/membrane/form_finding_law.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/postprocess/membrane_fields.h>
#include <pneuma/postprocess/membrane_probes.h>

#include <fstream>
#include <limits>
#include <sstream>

namespace pneuma
{
  namespace membrane
  {
    void
    MembraneSubsystem::save_checkpoint(
      Checkpoint                            &checkpoint,
      const std::vector<const LA::Vector *> &fields) const
    {
      // The displacements (and the path's other vectors) travel with the
      // mesh (p4est), so a restart may use another number of ranks.
      std::vector<LA::Vector>         ghosted(fields.size());
      std::vector<const LA::Vector *> pointers;
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          LA::Vector owned(owned_dofs, comm);
          for (const auto i : owned_dofs)
            owned[i] = (*fields[k])[i];
          owned.compress(VectorOperation::insert);
          ghosted[k].reinit(owned_dofs, relevant_dofs, comm);
          ghosted[k] = owned;
          pointers.push_back(&ghosted[k]);
        }
      parallel::distributed::SolutionTransfer<2, LA::Vector, 3> transfer(dofs);
      transfer.prepare_for_serialization(pointers);
      mesh.save(checkpoint.directory() + "/membrane.mesh");
      checkpoint.put("membrane/pvd", series);
    }

    void
    MembraneSubsystem::load_checkpoint(const Checkpoint &checkpoint,
                                       const std::vector<LA::Vector *> &fields)
    {
      std::vector<LA::Vector>   owned(fields.size());
      std::vector<LA::Vector *> pointers;
      for (auto &v : owned)
        {
          v.reinit(owned_dofs, comm);
          pointers.push_back(&v);
        }
      parallel::distributed::SolutionTransfer<2, LA::Vector, 3> transfer(dofs);
      transfer.deserialize(pointers);
      for (unsigned int k = 0; k < fields.size(); ++k)
        for (const auto i : owned_dofs)
          (*fields[k])[i] = owned[k][i];
      series = checkpoint.get<VtuSeries>("membrane/pvd");
    }

    void
    MembraneSubsystem::refine(const LA::Vector &field)
    {
      adaptive.refine(*mapping_cache, dofs, field, mesh);
      cache_mapping();
    }

    // ------------------------------------------------------------------
    // Output
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::add_output_fields(const LA::Vector &field, const double)
    {
      output = std::make_unique<DataOut<2, 3>>();
      output->attach_dof_handler(dofs);
      const std::vector<std::string> names(3, "displacement");
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          3, DataComponentInterpretation::component_is_part_of_vector);
      output->add_data_vector(field,
                              names,
                              DataOut<2, 3>::type_dof_data,
                              interpretation);
      postprocess::CellFields fields = postprocess::membrane_cell_fields(
        *mapping_cache, dofs, reference_geometry(), materials, scene, field);
      if (shell)
        shell->cell_fields(field, fields.names, fields.values);
      output_cell_data.clear();
      output_cell_data.reserve(fields.names.size() + 1);
      for (unsigned int i = 0; i < fields.names.size(); ++i)
        {
          output_cell_data.emplace_back(fields.values[i]);
          output->add_data_vector(output_cell_data.back(),
                                  fields.names[i],
                                  DataOut<2, 3>::type_cell_data);
        }
      output_cell_data.emplace_back(mesh.n_active_cells());
      output_cell_data.back() = mesh.locally_owned_subdomain();
      output->add_data_vector(output_cell_data.back(), "subdomain");
    }

    void
    MembraneSubsystem::add_mode_fields(const std::vector<std::string> &names,
                                       const std::vector<LA::Vector>  &modes)
    {
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          3, DataComponentInterpretation::component_is_part_of_vector);
      for (unsigned int k = 0; k < modes.size(); ++k)
        output->add_data_vector(modes[k],
                                std::vector<std::string>(3, names[k]),
                                DataOut<2, 3>::type_dof_data,
                                interpretation);
    }

    void
    MembraneSubsystem::write_output_files(const std::string &directory,
                                          const unsigned int step,
                                          const double       t,
                                          const LA::Vector &)
    {
      output->build_patches(*mapping_cache,
                            fe_degree,
                            DataOut<2, 3>::curved_inner_cells);
      // No date and time in the files: a run repeated is byte-identical.
      DataOutBase::VtkFlags flags;
      flags.print_date_and_time = false;
      output->set_flags(flags);
      const std::string pvtu = output->write_vtu_with_pvtu_record(
        directory + "/", series.name(), step, comm, 4);
      series.add(step, t, pvtu);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          remove_date(directory + "/" + pvtu);
          AssertThrow(series.write_pvd(directory),
                      ExcMessage("cannot write " + series.name() + ".pvd"));
        }
      output.reset();
    }
  } // namespace membrane
} // namespace pneuma
