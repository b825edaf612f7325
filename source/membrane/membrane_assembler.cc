#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/membrane/membrane_assembler.h>
#include <pneuma/membrane/surface_kinematics.h>

namespace pneuma
{
  namespace membrane
  {
    MembraneAssembler::MembraneAssembler(
      const geometry::SceneGenerator &geometry,
      const MaterialRegions          &materials,
      const loads::Loads             &loads)
      : geometry(geometry)
      , materials(materials)
      , loads(loads)
    {
    }

    void
    MembraneAssembler::reinit(const Mapping<2, 3>    &mapping_,
                              const DoFHandler<2, 3> &dof_handler_,
                              const unsigned int      degree_)
    {
      mapping     = &mapping_;
      dof_handler = &dof_handler_;
      degree      = degree_;
    }

    namespace
    {
      /// Outward orientation of a cell from its quadrature data.
      double
      cell_orientation(const geometry::SceneGenerator &geometry,
                       const FEValues<2, 3>           &fe_values)
      {
        Point<3>     x;
        Tensor<1, 3> n;
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          {
            x += fe_values.quadrature_point(q) / fe_values.n_quadrature_points;
            n += fe_values.normal_vector(q);
          }
        return geometry.orientation(x, n);
      }
    } // namespace

    void
    MembraneAssembler::assemble(const LA::Vector                &u,
                                const AffineConstraints<double> &constraints,
                                const AssemblyRequest           &request) const
    {
      Assert(mapping != nullptr, ExcNotInitialized());
      const auto        &fe = dof_handler->get_fe();
      const QGauss<2>    quadrature(degree + 1);
      const QGauss<1>    face_quadrature(degree + 1);
      FEValues<2, 3>     fe_values(*mapping,
                               fe,
                               quadrature,
                               update_values | update_gradients
                                 | update_normal_vectors
                                 | update_quadrature_points
                                 | update_JxW_values);
      FEFaceValues<2, 3> fe_face_values(*mapping,
                                        fe,
                                        face_quadrature,
                                        update_values | update_quadrature_points
                                          | update_JxW_values);

      const unsigned int n_dofs = fe.n_dofs_per_cell();
      const unsigned int n_q    = quadrature.size();
      FullMatrix<double> cell_matrix(n_dofs, n_dofs);
      Vector<double>     cell_residual(n_dofs), cell_external(n_dofs);
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      std::vector<double>                  local_u(n_dofs);

      std::vector<unsigned int>          component(n_dofs);
      std::vector<std::array<double, 2>> dN(n_dofs);
      std::vector<double>                N(n_dofs);
      std::vector<SymmetricTensor<2, 2>> B(n_dofs), DB(n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        component[i] = fe.system_to_component_index(i).first;

      // Form finding: the form-finding laws, and no load.
      const bool loaded      = form_finding_laws.empty();
      const bool want_matrix = request.tangent != nullptr;
      const bool want_vector =
        request.residual != nullptr || request.external != nullptr;
      const double       t = request.time;
      const Tensor<1, 3> g =
        loaded && loads.has_gravity() ? loads.gravity(t) : Tensor<1, 3>();


      for (const auto &cell : dof_handler->active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          fe_values.reinit(cell);
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < n_dofs; ++i)
            local_u[i] = u[dof_indices[i]];
          cell_matrix   = 0;
          cell_residual = 0;
          cell_external = 0;

          const RegionMaterial &material =
            loaded ? materials[cell->material_id()]
                   : form_finding_laws.at(cell->material_id());
          const double       H    = material.thickness;
          const Tensor<1, 3> warp = material.warp(geometry, cell);
          const double       sign = cell_orientation(geometry, fe_values);
          const bool         pressurised =
            loaded && loads.pressure_acts_on(cell->material_id());

          for (unsigned int q = 0; q < n_q; ++q)
            {
              const TangentFrame frame =
                tangent_frame(sign * fe_values.normal_vector(q), warp);
              Tensor<2, 3> Gu;
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const Tensor<1, 3> grad =
                    fe_values.shape_grad_component(i, q, component[i]);
                  dN[i][0] = grad * frame.e[0];
                  dN[i][1] = grad * frame.e[1];
                  N[i] = fe_values.shape_value_component(i, q, component[i]);
                  for (unsigned int d = 0; d < 3; ++d)
                    Gu[component[i]][d] += local_u[i] * grad[d];
                }
              const auto                  a = deformed_tangents(frame, Gu);
              const SymmetricTensor<2, 2> C = right_cauchy_green(a);
              SymmetricTensor<2, 2>       S;
              SymmetricTensor<4, 2>       D;
              material.law->evaluate(C, S, D);
              const double dA = fe_values.JxW(q);

              const Point<3>    &X = fe_values.quadrature_point(q);
              const double       p = pressurised ? loads.pressure(X, t) : 0.;
              const Tensor<1, 3> area_vector = cross_product_3d(a[0], a[1]);
              Tensor<1, 3>       dead_load   = material.density * H * g;
              if (loaded && loads.has_surface_load())
                dead_load += loads.surface_load(X, t);

              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int c = component[i];
                  B[i][0][0]           = a[0][c] * dN[i][0];
                  B[i][1][1]           = a[1][c] * dN[i][1];
                  B[i][0][1] = 0.5 * (a[0][c] * dN[i][1] + a[1][c] * dN[i][0]);
                  if (want_vector)
                    {
                      const double f_ext =
                        (p * area_vector[c] + dead_load[c]) * N[i] * dA;
                      cell_residual(i) += H * (S * B[i]) * dA - f_ext;
                      cell_external(i) += f_ext;
                    }
                }

              if (!want_matrix)
                continue;
              // Derivatives of a_1 x a_2 along unit displacement of
              // component d: e_d x a_2 (via a_1) and a_1 x e_d (via a_2).
              std::array<Tensor<1, 3>, 3> e_x_a2, a1_x_e;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  Tensor<1, 3> e_d;
                  e_d[d]    = 1.;
                  e_x_a2[d] = cross_product_3d(e_d, a[1]);
                  a1_x_e[d] = cross_product_3d(a[0], e_d);
                }
              for (unsigned int j = 0; j < n_dofs; ++j)
                DB[j] = D * B[j];
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int ci = component[i];
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    {
                      const unsigned int cj = component[j];
                      double             k  = H * (B[i] * DB[j]);
                      if (ci == cj)
                        k +=
                          H
                          * (dN[i][0]
                               * (S[0][0] * dN[j][0] + S[0][1] * dN[j][1])
                             + dN[i][1]
                                 * (S[1][0] * dN[j][0] + S[1][1] * dN[j][1]));
                      if (p != 0.)
                        k -= p * N[i]
                             * (dN[j][0] * e_x_a2[cj][ci]
                                + dN[j][1] * a1_x_e[cj][ci]);
                      cell_matrix(i, j) += k * dA;
                    }
                }
            }

          // Dead line loads on listed boundaries.
          if (loaded && want_vector && !loads.line_load_boundaries().empty())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary()
                  && loads.line_load_boundaries().count(
                    cell->face(f)->boundary_id()))
                {
                  fe_face_values.reinit(cell, f);
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    {
                      const Tensor<1, 3> load =
                        loads.line_load(fe_face_values.quadrature_point(q), t);
                      for (unsigned int i = 0; i < n_dofs; ++i)
                        {
                          const double f_ext =
                            load[component[i]]
                            * fe_face_values.shape_value_component(i,
                                                                   q,
                                                                   component[i])
                            * fe_face_values.JxW(q);
                          cell_residual(i) -= f_ext;
                          cell_external(i) += f_ext;
                        }
                    }
                }

          if (request.cell_terms)
            request.cell_terms(cell,
                               fe_values,
                               local_u,
                               want_matrix ? &cell_matrix : nullptr,
                               request.residual ? &cell_residual : nullptr,
                               dof_indices);

          LA::distribute(constraints,
                         cell_matrix,
                         cell_residual,
                         dof_indices,
                         want_matrix ? request.tangent : nullptr,
                         request.residual);
          if (request.external)
            constraints.distribute_local_to_global(cell_external,
                                                   dof_indices,
                                                   *request.external);
        }

      if (request.residual)
        request.residual->compress(VectorOperation::add);
      if (request.external)
        request.external->compress(VectorOperation::add);
      if (request.tangent)
        request.tangent->compress(VectorOperation::add);
    }

    void
    MembraneAssembler::surface_laplacian(
      const AffineConstraints<double> &constraints,
      LA::SparseMatrix                &L) const
    {
      const auto                          &fe = dof_handler->get_fe();
      const QGauss<2>                      quadrature(degree + 1);
      FEValues<2, 3>                       fe_values(*mapping,
                               fe,
                               quadrature,
                               update_gradients | update_JxW_values);
      const unsigned int                   n_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
      L = 0.;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            cell_matrix = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (fe.system_to_component_index(j).first == ci)
                      cell_matrix(i, j) +=
                        fe_values.shape_grad_component(i, q, ci)
                        * fe_values.shape_grad_component(j, q, ci)
                        * fe_values.JxW(q);
                }
            constraints.distribute_local_to_global(cell_matrix, dof_indices, L);
          }
      L.compress(VectorOperation::add);
    }

    void
    MembraneAssembler::mass_matrix(const AffineConstraints<double> &constraints,
                                   LA::SparseMatrix                &M) const
    {
      const auto                          &fe = dof_handler->get_fe();
      const QGauss<2>                      quadrature(degree + 1);
      FEValues<2, 3>                       fe_values(*mapping,
                               fe,
                               quadrature,
                               update_values | update_JxW_values);
      const unsigned int                   n_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const RegionMaterial &m     = materials[cell->material_id()];
            const double          rho_h = m.density * m.thickness;
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            cell_matrix = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (fe.system_to_component_index(j).first == ci)
                      cell_matrix(i, j) +=
                        rho_h * fe_values.shape_value_component(i, q, ci)
                        * fe_values.shape_value_component(j, q, ci)
                        * fe_values.JxW(q);
                }
            constraints.distribute_local_to_global(cell_matrix, dof_indices, M);
          }
      M.compress(VectorOperation::add);
    }

    double
    MembraneAssembler::enclosed_volume(const LA::Vector &u) const
    {
      const auto                      &fe = dof_handler->get_fe();
      const QGauss<2>                  quadrature(degree + 1);
      FEValues<2, 3>                   fe_values(*mapping,
                               fe,
                               quadrature,
                               update_values | update_gradients
                                 | update_normal_vectors
                                 | update_quadrature_points
                                 | update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, 3>>        grad_u(quadrature.size());
      std::vector<Tensor<1, 3>>        u_q(quadrature.size());
      double                           volume = 0.;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[displacement].get_function_gradients(u, grad_u);
            fe_values[displacement].get_function_values(u, u_q);
            const double sign = cell_orientation(geometry, fe_values);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const TangentFrame frame =
                  tangent_frame(sign * fe_values.normal_vector(q));
                const auto     a = deformed_tangents(frame, grad_u[q]);
                const Point<3> x = fe_values.quadrature_point(q) + u_q[q];
                volume += x * cross_product_3d(a[0], a[1]) * fe_values.JxW(q);
              }
          }
      return Utilities::MPI::sum(volume, dof_handler->get_communicator()) / 3.;
    }

    double
    MembraneAssembler::surface_area(const LA::Vector &u) const
    {
      const auto                      &fe = dof_handler->get_fe();
      const QGauss<2>                  quadrature(degree + 1);
      FEValues<2, 3>                   fe_values(*mapping,
                               fe,
                               quadrature,
                               update_gradients | update_normal_vectors
                                 | update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, 3>>        grad_u(quadrature.size());
      double                           area = 0.;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[displacement].get_function_gradients(u, grad_u);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const auto a =
                  deformed_tangents(tangent_frame(fe_values.normal_vector(q)),
                                    grad_u[q]);
                area += cross_product_3d(a[0], a[1]).norm() * fe_values.JxW(q);
              }
          }
      return Utilities::MPI::sum(area, dof_handler->get_communicator());
    }
  } // namespace membrane
} // namespace pneuma
