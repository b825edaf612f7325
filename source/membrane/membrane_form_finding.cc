/**
 * @file
 * The membrane in form finding (strategies/form_finding): its laws
 * replaced by the form-finding laws, nodes that move along the surface's
 * normal only, the reference surface moved by each update.
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
    MembraneSubsystem::compute_motion_directions()
    {
      // The consistent nodal normal int N_i n dA of every node of the
      // owned cells (their patches are owned or ghost cells), each cell's
      // part turned to agree with what the node has so far.
      const auto     &fe = dofs.get_fe();
      const QGauss<2> quadrature(fe_degree + 1);
      FEValues<2, 3>  fe_values(*mapping_cache,
                               fe,
                               quadrature,
                               update_values | update_normal_vectors
                                 | update_JxW_values);
      auto           &normal = motion_direction;
      normal.clear();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            for (unsigned int k = 0; k < n_nodes; ++k)
              {
                const unsigned int i = fe.component_to_system_index(0, k);
                Tensor<1, 3>       part;
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  part += fe_values.shape_value(i, q)
                          * fe_values.normal_vector(q) * fe_values.JxW(q);
                auto &n = normal[dof_indices[i]];
                n += (n * part < 0. ? -1. : 1.) * part;
              }
          }
    }

    void
    MembraneSubsystem::add_normal_motion_constraints(
      AffineConstraints<double> &c) const
    {
      const auto        &fe      = dofs.get_fe();
      const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      // Motion along the normal only: among the node's free components,
      // u_b = (n_b / n_a) u_a with a the one the normal is most along.
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int q = 0; q < n_nodes; ++q)
              {
                std::array<types::global_dof_index, 3> d;
                for (unsigned int k = 0; k < 3; ++k)
                  d[k] = dof_indices[fe.component_to_system_index(k, q)];
                const Tensor<1, 3>       &m = motion_direction.at(d[0]);
                const Tensor<1, 3>        n = m / m.norm();
                std::vector<unsigned int> free;
                for (unsigned int k = 0; k < 3; ++k)
                  if (!c.is_constrained(d[k]))
                    free.push_back(k);
                if (free.size() < 2)
                  continue;
                unsigned int a = free[0];
                for (const auto k : free)
                  if (std::abs(n[k]) > std::abs(n[a]))
                    a = k;
                for (const auto b : free)
                  if (b != a)
                    {
                      c.add_line(d[b]);
                      c.add_entry(d[b], d[a], n[b] / n[a]);
                    }
              }
          }
    }

    // ------------------------------------------------------------------
    // Form finding
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::begin_form_finding(const double lambda)
    {
      check_input(rigid_regions.empty(),
                  "Boundary conditions/Rigid regions",
                  "form finding moves the reference surface, which rigid "
                  "plates cannot follow; hold those regions with Fixed "
                  "regions instead");
      check_input(fe_degree >= 2,
                  "Discretisation/Polynomial degree",
                  "form finding needs degree 2: on the facets of degree 1 "
                  "the iteration is unstable (a catenoid collapses)");
      check_input(adaptive.cycles() == 0,
                  "Adaptive refinement/Cycles",
                  "form finding and adaptive refinement cannot be combined "
                  "(new cells would lie on the input's surface)");
      std::map<types::material_id, RegionMaterial> laws;
      for (const auto id : mesh_ids)
        {
          const RegionMaterial &m    = materials[id];
          const std::string     path = "Materials/Region " + std::to_string(id);
          const double          n1 = m.prestress[0], n2 = m.prestress[1];
          check_input(n1 > 0. && n2 > 0.,
                      path + "/Prestress",
                      "form finding needs a positive prestress in every "
                      "region (the membrane forces of the shape to find)");
          check_input(m.bending_factor == 0.,
                      path + "/Bending",
                      "form finding finds the shape of a membrane under its "
                      "prestress; a shell's bending would resist the "
                      "search (set Bending = none)");
          check_input(lambda == 0. || n1 == n2,
                      "Form finding/Homotopy factor",
                      "must be 0 where the prestress is anisotropic (" + path
                        + "/Prestress)");
          RegionMaterial f = m;
          f.law = std::make_shared<FormFindingLaw>(n1, n2, lambda, m.thickness);
          f.tension_field.reset();
          laws[id] = f;
        }
      assembler->set_form_finding(laws);
      form_finding = true;
      // Nodes move along the normals of the input surface.
      compute_motion_directions();

      if (reference_shift.size() == 0)
        {
          reference_shift.reinit(owned_dofs, relevant_dofs, comm);
          reference_shift = 0.;
        }
    }

    double
    MembraneSubsystem::move_reference(const LA::Vector &field)
    {
      // The membrane's part of the model's ghosted field.
      LA::Vector owned(owned_dofs, comm);
      for (const auto i : owned_dofs)
        owned[i] = field[i];
      owned.compress(VectorOperation::insert);
      const double change = owned.linfty_norm();
      LA::Vector   shift(owned_dofs, comm);
      shift = reference_shift;
      shift += owned;
      reference_shift = shift;
      // (MappingQCache imports the ghost values itself.)
      auto moved = std::make_unique<MappingQCache<2, 3>>(fe_degree);
      moved->initialize(*mapping_cache, dofs, owned, true);
      mapping_cache = std::move(moved);
      assembler->reinit(*mapping_cache, dofs, fe_degree);
      ++form_finding_updates;
      return change;
    }

    void
    MembraneSubsystem::end_form_finding()
    {
      assembler->set_form_finding({});
      form_finding = false;
    }

    double
    MembraneSubsystem::reference_area(
      const std::set<types::material_id> &excluded) const
    {
      const QGauss<2> quadrature(fe_degree + 1);
      FEValues<2, 3>  fe_values(*mapping_cache,
                               dofs.get_fe(),
                               quadrature,
                               update_JxW_values);
      double          area = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() && !excluded.count(cell->material_id()))
          {
            fe_values.reinit(cell);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              area += fe_values.JxW(q);
          }
      return Utilities::MPI::sum(area, comm);
    }

    double
    MembraneSubsystem::reference_diameter() const
    {
      std::array<double, 3> lo, hi;
      lo.fill(std::numeric_limits<double>::max());
      hi.fill(-std::numeric_limits<double>::max());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &x : mapping_cache->get_vertices(cell))
            for (unsigned int d = 0; d < 3; ++d)
              {
                lo[d] = std::min(lo[d], x[d]);
                hi[d] = std::max(hi[d], x[d]);
              }
      double sum = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        sum += std::pow(Utilities::MPI::max(hi[d], comm)
                          + Utilities::MPI::max(-lo[d], comm),
                        2);
      return std::sqrt(sum);
    }
  } // namespace membrane
} // namespace pneuma
