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
    CellKinematics::CellKinematics(const Mapping<2, 3>               &mapping,
                                   const DoFHandler<2, 3>            &dofs,
                                   const membrane::ReferenceGeometry &reference)
      : quadrature(dofs.get_fe().degree + 1)
      , fe_values(mapping,
                  dofs.get_fe(),
                  quadrature,
                  update_gradients | update_normal_vectors | update_JxW_values)
      , reference(reference)
      , grad_u(quadrature.size())
      , u_node(dofs.get_fe().n_dofs_per_cell() / 3)
      , a(quadrature.size())
      , C_q(quadrature.size())
    {
      // The reference data are by locally owned cell, in order.
      owned_index.assign(dofs.get_triangulation().n_active_cells(), -1);
      int k = 0;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          owned_index[cell->active_cell_index()] = k++;
    }

    void
    CellKinematics::reinit(const DoFHandler<2, 3>::active_cell_iterator &cell,
                           const LA::Vector                             &u,
                           const Tensor<1, 3>                           &warp)
    {
      fe_values.reinit(cell);
      fe_values[FEValuesExtractors::Vector(0)].get_function_gradients(u,
                                                                      grad_u);
      const int                      k = owned_index[cell->active_cell_index()];
      const membrane::TyingGeometry *tying_geometry =
        k >= 0 ? reference.tying(k) : nullptr;
      if (!tying_geometry)
        {
          for (unsigned int q = 0; q < n_points(); ++q)
            {
              const auto frame =
                membrane::tangent_frame(fe_values.normal_vector(q), warp);
              a[q]   = membrane::deformed_tangents(frame, grad_u[q]);
              C_q[q] = membrane::right_cauchy_green(a[q]);
            }
          return;
        }
      // Assumed strains, in the assembly's frame.
      const auto *dofs = reference.dof_indices(k);
      for (unsigned int i = 0; i < 3 * u_node.size(); ++i)
        u_node[reference.node(i)][reference.component(i)] = u[dofs[i]];
      const auto &rule = reference.assumed_strains();
      rule.state(*tying_geometry, u_node, tying);
      for (unsigned int q = 0; q < n_points(); ++q)
        {
          membrane::TangentFrame frame;
          for (unsigned int d = 0; d < 3; ++d)
            for (unsigned int al = 0; al < 2; ++al)
              frame.e[al][d] = reference.point(k, q).E[al][d];
          frame.N = cross_product_3d(frame.e[0], frame.e[1]);
          a[q]    = membrane::deformed_tangents(frame, grad_u[q]);
          C_q[q]  = rule.right_cauchy_green(*tying_geometry, tying, q);
        }
    }

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
    cell_wrinkling(const CellKinematics           &points,
                   const membrane::RegionMaterial &material)
    {
      CellWrinkling result;
      result.minor_force = std::numeric_limits<double>::max();
      for (unsigned int q = 0; q < points.n_points(); ++q)
        {
          const auto  &a     = points.tangents(q);
          const auto   state = material.tension_field->state(points.C(q));
          const double w     = points.JxW(q);
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
    membrane_strain_energy(const Mapping<2, 3>               &mapping,
                           const DoFHandler<2, 3>            &dof_handler,
                           const membrane::ReferenceGeometry &reference,
                           const membrane::MaterialRegions   &materials,
                           const geometry::SceneGenerator    &geometry,
                           const LA::Vector                  &u)
    {
      CellKinematics points(mapping, dof_handler, reference);
      double         energy = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &material = materials[cell->material_id()];
            points.reinit(cell, u, material.warp(geometry, cell));
            for (unsigned int q = 0; q < points.n_points(); ++q)
              energy += material.thickness
                        * material.law->strain_energy(points.C(q))
                        * points.JxW(q);
          }
      return energy;
    }

    namespace
    {
      /// The names of the membrane cell fields (the wrinkling ones where a
      /// region wrinkles).
      std::vector<std::string>
      cell_field_names(const bool wrinkling)
      {
        std::vector<std::string> names = {"membrane_force_xx",
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
        if (wrinkling)
          for (const std::string name : {"wrinkling_state",
                                         "wrinkle_direction_x",
                                         "wrinkle_direction_y",
                                         "wrinkle_direction_z",
                                         "relaxed_compression",
                                         "wrinkled_fraction",
                                         "slack_fraction"})
            names.push_back(name);
        return names;
      }
    } // namespace

    CellFields
    membrane_cell_fields(const Mapping<2, 3>               &mapping,
                         const DoFHandler<2, 3>            &dof_handler,
                         const membrane::ReferenceGeometry &reference,
                         const membrane::MaterialRegions   &materials,
                         const geometry::SceneGenerator    &geometry,
                         const LA::Vector                  &u)
    {
      CellFields f;
      f.names = cell_field_names(materials.any_wrinkling());
      const bool         wrinkling = materials.any_wrinkling();
      const unsigned int n_cells =
        dof_handler.get_triangulation().n_active_cells();
      f.values.assign(f.names.size(), Vector<double>(n_cells));

      CellKinematics points(mapping, dof_handler, reference);
      unsigned int   non_finite = 0;

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &material = materials[cell->material_id()];
            points.reinit(cell, u, material.warp(geometry, cell));
            SymmetricTensor<2, 3> n_avg;
            SymmetricTensor<2, 2> E_avg;
            Tensor<1, 3>          normal_avg;
            double                l3 = 0., area = 0.;
            for (unsigned int q = 0; q < points.n_points(); ++q)
              {
                const auto           &a = points.tangents(q);
                const auto           &C = points.C(q);
                SymmetricTensor<2, 2> S;
                SymmetricTensor<4, 2> D;
                material.law->evaluate(C, S, D);
                const double w = points.JxW(q);
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
                const CellWrinkling c = cell_wrinkling(points, material);
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
    wrinkling_summary(const Mapping<2, 3>               &mapping,
                      const DoFHandler<2, 3>            &dof_handler,
                      const membrane::ReferenceGeometry &reference,
                      const membrane::MaterialRegions   &materials,
                      const geometry::SceneGenerator    &geometry,
                      const LA::Vector                  &u)
    {
      WrinklingSummary result;
      auto            &areas = result.areas;
      double           minor = std::numeric_limits<double>::max();
      CellKinematics   points(mapping, dof_handler, reference);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &material = materials[cell->material_id()];
            if (!material.tension_field)
              continue;
            points.reinit(cell, u, material.warp(geometry, cell));
            const CellWrinkling c = cell_wrinkling(points, material);
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
