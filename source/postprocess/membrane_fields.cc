#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>

#include <pneuma/core/output.h>
#include <pneuma/membrane/surface_kinematics.h>
#include <pneuma/membrane/tension_field.h>
#include <pneuma/postprocess/membrane_fields.h>

#include <array>
#include <cmath>
#include <limits>

namespace pneuma
{
  namespace postprocess
  {
    namespace
    {
      /// The FEValues of the membrane's cells at the assembly's Gauss
      /// points (degree + 1) and the displacement gradients there.
      struct CellGradients
      {
        CellGradients(const Mapping<2, 3>    &mapping,
                      const DoFHandler<2, 3> &dofs)
          : quadrature(dofs.get_fe().degree + 1)
          , fe_values(mapping,
                      dofs.get_fe(),
                      quadrature,
                      update_gradients | update_normal_vectors
                        | update_JxW_values)
          , grad_u(quadrature.size())
        {
        }
        /// Reinitialize on @p cell and gather the gradients of @p u.
        void
        reinit(const DoFHandler<2, 3>::active_cell_iterator &cell,
               const LA::Vector                             &u)
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(
            u, grad_u);
        }
        const QGauss<2>           quadrature;
        FEValues<2, 3>            fe_values;
        std::vector<Tensor<2, 3>> grad_u;
      };
    } // namespace

    PrincipalForces
    in_plane_principal(const SymmetricTensor<2, 3> &n,
                       const Tensor<1, 3>          &normal)
    {
      const auto   eig = eigenvectors(n);
      unsigned int kn  = 0;
      for (unsigned int e = 1; e < 3; ++e)
        if (std::abs(eig[e].second * normal)
            > std::abs(eig[kn].second * normal))
          kn = e;
      const unsigned int k1 = (kn == 0) ? 1 : 0;
      const unsigned int k2 = (kn == 2) ? 1 : 2;
      return {eig[k1].first, eig[k2].first, eig[k1].second, eig[k2].second};
    }

    CellWrinkling
    cell_wrinkling(const FEValues<2, 3>            &fe_values,
                   const std::vector<Tensor<2, 3>> &grad_u,
                   const membrane::RegionMaterial  &material,
                   const Tensor<1, 3>              &warp)
    {
      CellWrinkling result;
      result.minor_force = std::numeric_limits<double>::max();
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          const auto frame =
            membrane::tangent_frame(fe_values.normal_vector(q), warp);
          const auto a = membrane::deformed_tangents(frame, grad_u[q]);
          const auto state =
            material.tension_field->state(membrane::right_cauchy_green(a));
          const double w = fe_values.JxW(q);
          result.areas[state.kind] += w;
          result.compression +=
            w * material.thickness * std::min(state.plain_minor_stress, 0.);
          result.minor_force =
            std::min(result.minor_force,
                     material.thickness * state.plain_minor_stress);
          if (state.kind == membrane::WrinklingState::wrinkled)
            {
              // The tension direction, current, sign-aligned.
              Tensor<1, 3> d = state.tension_direction[0] * a[0]
                               + state.tension_direction[1] * a[1];
              d /= d.norm();
              result.direction += (d * result.direction < 0. ? -w : w) * d;
            }
        }
      return result;
    }

    double
    membrane_strain_energy(const Mapping<2, 3>             &mapping,
                           const DoFHandler<2, 3>          &dof_handler,
                           const membrane::MaterialRegions &materials,
                           const geometry::SceneGenerator  &geometry,
                           const LA::Vector                &u)
    {
      CellGradients points(mapping, dof_handler);
      const auto   &fe_values = points.fe_values;
      const auto   &grad_u    = points.grad_u;
      double        energy    = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            points.reinit(cell, u);
            const auto        &material = materials[cell->material_id()];
            const Tensor<1, 3> warp     = material.warp(geometry, cell);
            for (unsigned int q = 0; q < points.quadrature.size(); ++q)
              {
                const auto frame =
                  membrane::tangent_frame(fe_values.normal_vector(q), warp);
                const auto a = membrane::deformed_tangents(frame, grad_u[q]);
                energy +=
                  material.thickness
                  * material.law->strain_energy(membrane::right_cauchy_green(a))
                  * fe_values.JxW(q);
              }
          }
      return energy;
    }

    CellFields
    membrane_cell_fields(const Mapping<2, 3>             &mapping,
                         const DoFHandler<2, 3>          &dof_handler,
                         const membrane::MaterialRegions &materials,
                         const geometry::SceneGenerator  &geometry,
                         const LA::Vector                &u)
    {
      CellFields f;
      f.names = {"membrane_force_xx",
                 "membrane_force_yy",
                 "membrane_force_zz",
                 "membrane_force_xy",
                 "membrane_force_xz",
                 "membrane_force_yz",
                 "N1",
                 "N2",
                 "N1_direction_x",
                 "N1_direction_y",
                 "N1_direction_z",
                 "N2_direction_x",
                 "N2_direction_y",
                 "N2_direction_z",
                 "E1",
                 "E2",
                 "thickness_stretch",
                 "material_region"};
      // Wrinkling fields only where a region wrinkles.
      const bool wrinkling = materials.any_wrinkling();
      if (wrinkling)
        for (const std::string name : {"wrinkling_state",
                                       "wrinkle_direction_x",
                                       "wrinkle_direction_y",
                                       "wrinkle_direction_z",
                                       "relaxed_compression",
                                       "wrinkled_fraction",
                                       "slack_fraction"})
          f.names.push_back(name);
      const unsigned int n_cells =
        dof_handler.get_triangulation().n_active_cells();
      f.values.assign(f.names.size(), Vector<double>(n_cells));

      CellGradients points(mapping, dof_handler);
      const auto   &quadrature = points.quadrature;
      const auto   &fe_values  = points.fe_values;
      const auto   &grad_u     = points.grad_u;
      unsigned int  non_finite = 0;

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            points.reinit(cell, u);
            const auto           &material = materials[cell->material_id()];
            const Tensor<1, 3>    warp     = material.warp(geometry, cell);
            SymmetricTensor<2, 3> n_avg;
            SymmetricTensor<2, 2> E_avg;
            Tensor<1, 3>          normal_avg;
            double                l3 = 0., area = 0.;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const auto frame =
                  membrane::tangent_frame(fe_values.normal_vector(q), warp);
                const auto a = membrane::deformed_tangents(frame, grad_u[q]);
                const auto C = membrane::right_cauchy_green(a);
                SymmetricTensor<2, 2> S;
                SymmetricTensor<4, 2> D;
                material.law->evaluate(C, S, D);
                const double w = fe_values.JxW(q);
                n_avg +=
                  w * membrane::membrane_forces(a, S, material.thickness);
                E_avg += w * 0.5 * (C - unit_symmetric_tensor<2>());
                l3 += w * material.law->thickness_stretch(C);
                normal_avg += w * cross_product_3d(a[0], a[1]);
                area += w;
              }
            n_avg /= area;
            E_avg /= area;
            l3 /= area;
            // Forces that are not finite (a law evaluated where it cannot
            // be) are never written: counted and reported below.
            if (!std::isfinite(n_avg.norm() + E_avg.norm() + l3))
              {
                ++non_finite;
                continue;
              }
            const unsigned int k = cell->active_cell_index();
            f.values[0][k]       = n_avg[0][0];
            f.values[1][k]       = n_avg[1][1];
            f.values[2][k]       = n_avg[2][2];
            f.values[3][k]       = n_avg[0][1];
            f.values[4][k]       = n_avg[0][2];
            f.values[5][k]       = n_avg[1][2];
            const PrincipalForces principal =
              in_plane_principal(n_avg, normal_avg);
            f.values[6][k] = principal.N1;
            f.values[7][k] = principal.N2;
            for (unsigned int d = 0; d < 3; ++d)
              {
                f.values[8 + d][k]  = principal.direction_1[d];
                f.values[11 + d][k] = principal.direction_2[d];
              }
            // Principal strains m +- r with r = |((E11 - E22)/2, E12)|:
            // the root of a sum of squares, never of a round-off negative
            // discriminant (nearly isotropic strain, e.g. on end plates).
            const double m = 0.5 * (E_avg[0][0] + E_avg[1][1]);
            const double r =
              std::hypot(0.5 * (E_avg[0][0] - E_avg[1][1]), E_avg[0][1]);
            f.values[14][k] = m + r;
            f.values[15][k] = m - r;
            f.values[16][k] = l3;
            f.values[17][k] = cell->material_id();
            if (wrinkling && material.tension_field)
              {
                // The areas of summary.json's wrinkled_area and
                // slack_area, cell by cell: the same function.
                const CellWrinkling c =
                  cell_wrinkling(fe_values, grad_u, material, warp);
                // The state that covers most of the cell.
                unsigned int s = 0;
                for (unsigned int i = 1; i < 3; ++i)
                  if (c.areas[i] > c.areas[s])
                    s = i;
                f.values[18][k]   = s;
                const double norm = c.direction.norm();
                for (unsigned int d = 0; d < 3; ++d)
                  f.values[19 + d][k] = norm > 0. ? c.direction[d] / norm : 0.;
                f.values[22][k] = c.compression / area;
                f.values[23][k] = c.areas[1] / area;
                f.values[24][k] = c.areas[2] / area;
              }
          }
      // On every rank alike: the writer is collective.
      non_finite =
        Utilities::MPI::sum(non_finite, dof_handler.get_communicator());
      if (non_finite > 0)
        throw NonFiniteOutput("the membrane forces of the state are not "
                              "finite in "
                              + std::to_string(non_finite)
                              + " cell(s); it is not written");
      return f;
    }

    WrinklingSummary
    wrinkling_summary(const Mapping<2, 3>             &mapping,
                      const DoFHandler<2, 3>          &dof_handler,
                      const membrane::MaterialRegions &materials,
                      const geometry::SceneGenerator  &geometry,
                      const LA::Vector                &u)
    {
      WrinklingSummary result;
      auto            &areas = result.areas;
      double           minor = std::numeric_limits<double>::max();
      CellGradients    points(mapping, dof_handler);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &material = materials[cell->material_id()];
            if (!material.tension_field)
              continue;
            points.reinit(cell, u);
            const CellWrinkling c =
              cell_wrinkling(points.fe_values,
                             points.grad_u,
                             material,
                             material.warp(geometry, cell));
            for (unsigned int i = 0; i < 3; ++i)
              areas[i] += c.areas[i];
            minor = std::min(minor, c.minor_force);
          }
      const MPI_Comm comm = dof_handler.get_communicator();
      for (auto &a : areas)
        a = Utilities::MPI::sum(a, comm);
      result.minor_force = Utilities::MPI::min(minor, comm);
      return result;
    }
  } // namespace postprocess
} // namespace pneuma
