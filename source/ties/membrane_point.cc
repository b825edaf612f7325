#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <pneuma/ties/membrane_point.h>

namespace pneuma
{
  namespace ties
  {
    std::vector<MembranePoint>
    nearest_membrane_points(const Mapping<2, 3>                &mapping,
                            const DoFHandler<2, 3>             &dof_handler,
                            const std::set<types::material_id> &regions,
                            const Point<3>                     &x,
                            const double                        reach)
    {
      std::vector<MembranePoint> found;
      double                     best = std::numeric_limits<double>::infinity();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned()
              || (!regions.empty() && regions.count(cell->material_id()) == 0))
            continue;
          // The box of the vertices, enlarged by the reach and by a tenth
          // of its diagonal (curved cells bulge beyond their vertices).
          auto         box = cell->bounding_box();
          const double pad = reach + 0.1 * box.side_length(0)
                             + 0.1 * box.side_length(1)
                             + 0.1 * box.side_length(2);
          box.extend(pad);
          if (!box.point_inside(x))
            continue;
          Point<2> unit;
          try
            {
              unit = mapping.transform_real_to_unit_cell(cell, x);
            }
          catch (const typename Mapping<2, 3>::ExcTransformationFailed &)
            {
              continue;
            }
          for (unsigned int d = 0; d < 2; ++d)
            unit[d] = std::min(1., std::max(0., unit[d]));
          const double distance =
            mapping.transform_unit_to_real_cell(cell, unit).distance(x);
          MembranePoint p;
          p.distance  = distance;
          p.tolerance = 1e-8 * cell->diameter();
          p.cell      = cell;
          p.unit      = unit;
          best        = std::min(best, distance);
          found.push_back(p);
        }
      // Keep those as near as the nearest.
      std::vector<MembranePoint> nearest;
      for (const auto &p : found)
        if (p.distance <= best + p.tolerance)
          nearest.push_back(p);
      return nearest;
    }

    std::vector<Combination>
    interpolation(const Mapping<2, 3>             &mapping,
                  const MembranePoint             &p,
                  const std::vector<Tensor<1, 3>> &directions,
                  Tensor<1, 3>                    &normal)
    {
      const auto         &fe = p.cell->get_fe();
      const Quadrature<2> point(std::vector<Point<2>>{p.unit},
                                std::vector<double>{1.});
      FEValues<2, 3>      values(mapping,
                            fe,
                            point,
                            update_values | update_gradients
                              | update_normal_vectors);
      values.reinit(p.cell);
      normal = values.normal_vector(0);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      p.cell->get_dof_indices(dofs);
      std::vector<Combination> rows(3 * (1 + directions.size()));
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          const double       N = values.shape_value(i, 0);
          if (N != 0.)
            rows[c].emplace_back(dofs[i], N);
          const Tensor<1, 3> grad = values.shape_grad(i, 0);
          for (unsigned int v = 0; v < directions.size(); ++v)
            {
              const double g = grad * directions[v];
              if (g != 0.)
                rows[3 * (v + 1) + c].emplace_back(dofs[i], g);
            }
        }
      return rows;
    }
  } // namespace ties
} // namespace pneuma
