#pragma once

/**
 * @file
 * A material point of the membrane as a linear combination of its
 * unknowns: the point of the reference surface nearest to a given point,
 * searched among the locally owned cells, and the interpolation of the
 * displacement and of its surface gradient there (doc/theory.md §15).
 */

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace pneuma
{
  namespace ties
  {
    using namespace dealii;

    /// One row of a linear combination: sum of weight x dof.
    using Combination = std::vector<std::pair<types::global_dof_index, double>>;

    /// The membrane point nearest to a point X of space.
    struct MembranePoint
    {
      /// Distance from X to the reference surface.
      double distance = std::numeric_limits<double>::infinity();
      /// 1e-8 of the cell's diameter: points as near as this are alike.
      double tolerance = 0.;
      /// The owned cell and the unit-cell coordinates of the point.
      DoFHandler<2, 3>::active_cell_iterator cell;
      Point<2>                               unit;
    };

    /**
     * The points of the reference surface nearest to @p x among the
     * locally owned cells whose material id is in @p regions (empty: all)
     * and whose bounding box, enlarged by @p reach, holds @p x: the
     * least-squares projection onto each such cell, clamped to the cell.
     * Every cell whose point is as near as the nearest (to 1e-8 of its
     * diameter) is returned: a point on a cell edge or vertex lies in all
     * the cells around it, whose one-sided gradients a caller averages.
     */
    std::vector<MembranePoint>
    nearest_membrane_points(const Mapping<2, 3>                &mapping,
                            const DoFHandler<2, 3>             &dof_handler,
                            const std::set<types::material_id> &regions,
                            const Point<3>                     &x,
                            const double                        reach);

    /**
     * The displacement at @p p as combinations of the membrane unknowns,
     * one per component: u_c(p) = sum_i N_i(xi) u_i with the dofs i of
     * component c. For each vector of @p directions (reference vectors A)
     * also the directional derivative (grad_S u) A, three combinations per
     * vector after the displacement's. @p normal receives the reference
     * unit normal at the point.
     */
    std::vector<Combination>
    interpolation(const Mapping<2, 3>             &mapping,
                  const MembranePoint             &p,
                  const std::vector<Tensor<1, 3>> &directions,
                  Tensor<1, 3>                    &normal);
  } // namespace ties
} // namespace pneuma
