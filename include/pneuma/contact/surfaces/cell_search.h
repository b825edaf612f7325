#pragma once

/**
 * @file
 * Box queries of the surface contact's cells (contact/surfaces/): cell
 * boxes enlarged by a reach, and the cells of an R-tree (deal.II's
 * pack_rtree of (box, cell) pairs) whose boxes meet a box, in cell order so
 * that every rank and thread count lists them alike.
 */

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

namespace pneuma
{
  namespace contact
  {
    /// @p box (lower and upper corners) grown by @p reach on every side.
    inline dealii::BoundingBox<3>
    enlarged(const std::pair<dealii::Tensor<1, 3>, dealii::Tensor<1, 3>> &box,
             const double                                                 reach)
    {
      dealii::Point<3> lower, upper;
      for (unsigned int i = 0; i < 3; ++i)
        {
          lower[i] = box.first[i] - reach;
          upper[i] = box.second[i] + reach;
        }
      return dealii::BoundingBox<3>({lower, upper});
    }

    /// Cells of @p tree whose boxes touch @p box, in cell order.
    template <class Tree>
    std::vector<unsigned int>
    cells_near(const Tree &tree, const dealii::BoundingBox<3> &box)
    {
      std::vector<std::pair<dealii::BoundingBox<3>, unsigned int>> hits;
      tree.query(boost::geometry::index::intersects(box),
                 std::back_inserter(hits));
      std::vector<unsigned int> found;
      for (const auto &hit : hits)
        found.push_back(hit.second);
      std::sort(found.begin(), found.end());
      return found;
    }
  } // namespace contact
} // namespace pneuma
