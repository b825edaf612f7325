#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/cell_id.h>

#include <pneuma/core/input_error.h>
#include <pneuma/membrane/surface_kinematics.h>
#include <pneuma/membrane/tension_field.h>
#include <pneuma/postprocess/membrane_probes.h>

#include <cmath>
#include <limits>

namespace pneuma
{
  namespace postprocess
  {
    namespace
    {
      /// @p d with its largest component positive.
      Tensor<1, 3>
      signed_direction(const Tensor<1, 3> &d)
      {
        unsigned int k = 0;
        for (unsigned int i = 1; i < 3; ++i)
          if (std::abs(d[i]) > std::abs(d[k]))
            k = i;
        return d[k] < 0. ? -d : d;
      }

      /// A locally owned cell holding @p p and the point's unit
      /// coordinates there; the distance from @p p to the surface point
      /// relative to the cell's diameter (infinite: none found). A point
      /// on a cell's edge lies in several: the one of the least CellId
      /// (the same on every rank count).
      double
      find_cell(const Mapping<2, 3>                    &mapping,
                const DoFHandler<2, 3>                 &dof_handler,
                const Point<3>                         &p,
                DoFHandler<2, 3>::active_cell_iterator &found,
                Point<2>                               &unit)
      {
        double best = std::numeric_limits<double>::infinity();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              // The vertices' box, widened by a cell diameter for curved
              // (mapped) cells.
              const double h   = cell->diameter();
              bool         out = false;
              for (unsigned int d = 0; d < 3 && !out; ++d)
                {
                  double lo = std::numeric_limits<double>::max(), hi = -lo;
                  for (const auto v : cell->vertex_indices())
                    {
                      lo = std::min(lo, cell->vertex(v)[d]);
                      hi = std::max(hi, cell->vertex(v)[d]);
                    }
                  out = p[d] < lo - 0.5 * h || p[d] > hi + 0.5 * h;
                }
              if (out)
                continue;
              try
                {
                  const Point<2> xi =
                    mapping.transform_real_to_unit_cell(cell, p);
                  if (!GeometryInfo<2>::is_inside_unit_cell(xi, 1e-10))
                    continue;
                  double distance =
                    mapping.transform_unit_to_real_cell(cell, xi).distance(p)
                    / h;
                  if (distance < 1e-10)
                    distance = 0.;
                  if (distance < best
                      || (distance == best && cell->id() < found->id()))
                    {
                      best  = distance;
                      found = cell;
                      unit  = GeometryInfo<2>::project_to_unit_cell(xi);
                    }
                }
              catch (const typename Mapping<2, 3>::ExcTransformationFailed &)
                {
                }
            }
        return best;
      }
    } // namespace

    std::vector<ProbeValues>
    membrane_probes(const Mapping<2, 3>             &mapping,
                    const DoFHandler<2, 3>          &dof_handler,
                    const membrane::MaterialRegions &materials,
                    const geometry::SceneGenerator  &geometry,
                    const LA::Vector                &u,
                    const std::vector<Point<3>>     &points,
                    const std::string               &entry)
    {
      const MPI_Comm           comm = dof_handler.get_communicator();
      const unsigned int       me   = Utilities::MPI::this_mpi_process(comm);
      std::vector<ProbeValues> values(points.size());
      const FEValuesExtractors::Vector displacement(0);
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          DoFHandler<2, 3>::active_cell_iterator cell;
          Point<2>                               unit;
          const double                           distance =
            find_cell(mapping, dof_handler, points[k], cell, unit);
          // Off the surface everywhere: no rank evaluates it.
          const double nearest = Utilities::MPI::min(distance, comm);
          // The same on every rank, so every rank throws.
          check_input(nearest < 1e-3,
                      entry,
                      "point " + std::to_string(k)
                        + " does not lie on the membrane's reference "
                          "surface");
          // Of the ranks that hold it as near, the one of the least cell.
          const auto ids = Utilities::MPI::all_gather(
            comm, distance <= nearest ? cell->id().to_string() : "");
          unsigned int reporter = numbers::invalid_unsigned_int;
          for (unsigned int r = 0; r < ids.size(); ++r)
            if (!ids[r].empty()
                && (reporter == numbers::invalid_unsigned_int
                    || CellId(ids[r]) < CellId(ids[reporter])))
              reporter = r;
          if (me != reporter)
            continue;

          const Quadrature<2> quadrature(std::vector<Point<2>>{unit},
                                         std::vector<double>{1.});
          FEValues<2, 3>      fe_values(mapping,
                                   dof_handler.get_fe(),
                                   quadrature,
                                   update_gradients | update_normal_vectors);
          fe_values.reinit(cell);
          std::vector<Tensor<2, 3>> grad_u(1);
          fe_values[displacement].get_function_gradients(u, grad_u);
          const auto &material = materials[cell->material_id()];
          const auto  frame =
            membrane::tangent_frame(fe_values.normal_vector(0),
                                    material.warp(geometry, cell));
          const auto a = membrane::deformed_tangents(frame, grad_u[0]);
          const auto C = membrane::right_cauchy_green(a);
          SymmetricTensor<2, 2> S;
          SymmetricTensor<4, 2> D;
          material.law->evaluate(C, S, D);
          auto &v  = values[k];
          v.forces = in_plane_principal(
            membrane::membrane_forces(a, S, material.thickness),
            cross_product_3d(a[0], a[1]));
          v.forces.direction_1 = signed_direction(v.forces.direction_1);
          v.forces.direction_2 = signed_direction(v.forces.direction_2);
          if (material.tension_field)
            {
              const auto state  = material.tension_field->state(C);
              v.wrinkling_state = state.kind;
              v.plain_minor_force =
                material.thickness * state.plain_minor_stress;
              if (state.kind == membrane::WrinklingState::wrinkled)
                {
                  const Tensor<1, 3> d = state.tension_direction[0] * a[0]
                                         + state.tension_direction[1] * a[1];
                  v.wrinkle_direction = signed_direction(d / d.norm());
                }
            }
        }
      return values;
    }
  } // namespace postprocess
} // namespace pneuma
