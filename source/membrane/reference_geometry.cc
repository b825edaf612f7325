#include <deal.II/base/quadrature_lib.h>

#include <pneuma/core/input_error.h>
#include <pneuma/membrane/reference_geometry.h>
#include <pneuma/membrane/surface_kinematics.h>

namespace pneuma
{
  namespace membrane
  {
    std::array<std::array<unsigned int, 3>, max_cell_nodes>
    node_dofs(const FiniteElement<2, 3> &fe)
    {
      const unsigned int n_dofs = fe.n_dofs_per_cell();
      AssertThrow(n_dofs % 3 == 0 && n_dofs / 3 <= max_cell_nodes,
                  ExcMessage("membranes need FE_Q^3 of degree 1 or 2"));
      std::array<std::array<unsigned int, 3>, max_cell_nodes> dof{};
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const auto [c, a] = fe.system_to_component_index(i);
          dof[a][c]         = i;
        }
      return dof;
    }

    double
    cell_orientation(const geometry::SceneGenerator &geometry,
                     const FEValues<2, 3>           &fe_values)
    {
      dealii::Point<3> x;
      Tensor<1, 3>     n;
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          x += fe_values.quadrature_point(q) / fe_values.n_quadrature_points;
          n += fe_values.normal_vector(q);
        }
      return geometry.orientation(x, n);
    }

    bool
    uses_assumed_strains(const RegionMaterial    &material,
                         const types::material_id id,
                         const unsigned int       degree)
    {
      switch (material.membrane_strains)
        {
          case MembraneStrains::assumed:
            check_input(
              degree == 2,
              "Materials/Region " + std::to_string(id) + "/Membrane strains",
              "assumed strains need Q2 cells (Discretisation/Polynomial "
              "degree = 2), the mesh has degree "
                + std::to_string(degree));
            return true;
          case MembraneStrains::displacement:
            return false;
          default:
            return material.bending_factor > 0. && degree == 2;
        }
    }

    std::unique_ptr<FEValues<2, 3>>
    ReferenceGeometry::start_assumed_strains(const MaterialRegions &materials,
                                             const Mapping<2, 3>   &mapping,
                                             const FiniteElement<2, 3> &fe,
                                             const unsigned int         degree)
    {
      bool any = false;
      for (const auto id : materials.ids())
        any |= uses_assumed_strains(materials[id], id, degree);
      if (!any)
        return nullptr;
      assumed = std::make_unique<AssumedStrains>(fe);
      return std::make_unique<FEValues<2, 3>>(mapping,
                                              fe,
                                              assumed->tying_points(),
                                              update_jacobians);
    }

    void
    ReferenceGeometry::add_tying_cell(const unsigned int    k,
                                      const FEValues<2, 3> &at_gauss,
                                      const FEValues<2, 3> &at_tying)
    {
      double frames[TyingGeometry::n_q][2][3];
      for (unsigned int q = 0; q < n_q; ++q)
        std::copy(&points[std::size_t(k) * n_q + q].E[0][0],
                  &points[std::size_t(k) * n_q + q].E[0][0] + 6,
                  &frames[q][0][0]);
      tying_of[k] = tying_cells.size();
      tying_cells.emplace_back();
      assumed->reference(at_tying, at_gauss, frames, tying_cells.back());
    }

    ReferenceGeometry::ReferenceGeometry(
      const geometry::SceneGenerator &geometry,
      const MaterialRegions          &materials,
      const Mapping<2, 3>            &mapping,
      const DoFHandler<2, 3>         &dof_handler,
      const unsigned int              degree)
    {
      const auto     &fe = dof_handler.get_fe();
      const QGauss<2> quadrature(degree + 1);
      FEValues<2, 3>  fe_values(mapping,
                               fe,
                               quadrature,
                               update_values | update_gradients
                                 | update_normal_vectors
                                 | update_quadrature_points | update_JxW_values
                                 | update_inverse_jacobians);
      const auto      at_tying =
        start_assumed_strains(materials, mapping, fe, degree);
      n_q                       = quadrature.size();
      const unsigned int n_dofs = fe.n_dofs_per_cell();
      n_node                    = n_dofs / 3;
      node_of.resize(n_dofs);
      component_of.resize(n_dofs);
      // The first dof of each node: its scalar shape function.
      const auto by_node = node_dofs(fe);
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          component_of[i] = fe.system_to_component_index(i).first;
          node_of[i]      = fe.system_to_component_index(i).second;
        }
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          ++n_owned;
      dofs.resize(std::size_t(n_owned) * n_dofs);
      points.resize(std::size_t(n_owned) * n_q);
      derivatives.resize(std::size_t(n_owned) * n_q * n_node);
      values.resize(n_q * n_node);

      if (assumed)
        tying_of.assign(n_owned, -1);
      std::vector<types::global_dof_index> cell_dofs(n_dofs);
      unsigned int                         k = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          fe_values.reinit(cell);
          cell->get_dof_indices(cell_dofs);
          std::copy(cell_dofs.begin(),
                    cell_dofs.end(),
                    dofs.begin() + std::size_t(k) * n_dofs);
          const Tensor<1, 3> warp =
            materials[cell->material_id()].warp(geometry, cell);
          const double sign = cell_orientation(geometry, fe_values);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const TangentFrame frame =
                tangent_frame(sign * fe_values.normal_vector(q), warp);
              Point &p = points[std::size_t(k) * n_q + q];
              for (unsigned int d = 0; d < 3; ++d)
                {
                  p.E[0][d] = frame.e[0][d];
                  p.E[1][d] = frame.e[1][d];
                  p.X[d]    = fe_values.quadrature_point(q)[d];
                }
              p.JxW = fe_values.JxW(q);
              for (unsigned int a = 0; a < n_node; ++a)
                {
                  const Tensor<1, 3> grad =
                    fe_values.shape_grad_component(by_node[a][0], q, 0);
                  auto &dN =
                    derivatives[(std::size_t(k) * n_q + q) * n_node + a];
                  dN[0] = grad * frame.e[0];
                  dN[1] = grad * frame.e[1];
                  if (k == 0)
                    values[q * n_node + a] =
                      fe_values.shape_value_component(by_node[a][0], q, 0);
                }
            }
          if (assumed
              && uses_assumed_strains(materials[cell->material_id()],
                                      cell->material_id(),
                                      degree))
            {
              at_tying->reinit(cell);
              add_tying_cell(k, fe_values, *at_tying);
            }
          ++k;
        }
      // Shape values on a rank without cells: from the reference cell.
      if (n_owned == 0)
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int a = 0; a < n_node; ++a)
            values[q * n_node + a] =
              fe.shape_value_component(by_node[a][0], quadrature.point(q), 0);
    }
  } // namespace membrane
} // namespace pneuma
