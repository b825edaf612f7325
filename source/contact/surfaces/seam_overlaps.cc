/**
 * @file
 * The cell pairs of the surface contact that start closer than their half
 * thicknesses next to a seam (SurfaceContact::find_seams(), doc/theory.md
 * §20): left out of each other's contact, like the cells on the seam.
 */

#include <deal.II/numerics/rtree.h>

#include <pneuma/contact/surfaces/cell_search.h>
#include <pneuma/contact/surfaces/surface_contact.h>

#include <map>

namespace pneuma
{
  namespace contact
  {
    using namespace dealii;

    void
    SurfaceContact::find_seams()
    {
      seam.clear();
      seam_counts.assign(parameters.size(), 0);
      const auto patches = current_patches(nullptr);
      std::vector<std::pair<Tensor<1, 3>, Tensor<1, 3>>>   boxes;
      std::vector<std::pair<BoundingBox<3>, unsigned int>> all;
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          boxes.push_back(bounding_box(patches[c]));
          all.emplace_back(enlarged(boxes.back(), 0.), c);
        }
      const auto tree = pack_rtree(all);
      // The cells that share a corner with a cell, and the cell itself.
      std::map<unsigned int, std::vector<unsigned int>> around;
      const auto next_to = [&](const unsigned int c) -> const auto &
      {
        auto [it, fresh] = around.try_emplace(c);
        if (fresh)
          for (const unsigned int n :
               cells_near(tree, enlarged(boxes[c], 1e-9 * thickest)))
            if (n == c || touching(c, n))
              it->second.push_back(n);
        return it->second;
      };
      for (unsigned int k = 0; k < parameters.size(); ++k)
        {
          const SurfacePair &p = parameters[k];
          // The pairs (cell, opposite cell) closer than their offset at a
          // Gauss point, that share no corner.
          std::set<std::pair<unsigned int, unsigned int>> close;
          for (unsigned int side = 0; side < pairs[k].sides.size(); ++side)
            for (unsigned int c = 0; c < cells.size(); ++c)
              {
                const auto id = cells[c].material;
                if (!(side == 0 ? p.on_first(id) : p.on_second(id)))
                  continue;
                for (const unsigned int m :
                     cells_near(tree, enlarged(boxes[c], thickest)))
                  {
                    if (m == c || touching(c, m)
                        || !pairs[k].sides[side].opposite[m])
                      continue;
                    for (const auto &xi : points)
                      {
                        const Projection pm =
                          project(patches[m], position(patches[c], xi), 0.);
                        if (pm.inside && pm.distance < 0.99 * offset(c, m))
                          {
                            close.insert({std::min(c, m), std::max(c, m)});
                            break;
                          }
                      }
                  }
              }
          // Chained to the seam: grown from the pairs that touch.
          for (bool grown = true; grown;)
            {
              grown = false;
              for (const auto &[a, b] : close)
                {
                  if (seam.count({a, b}))
                    continue;
                  bool chained = false;
                  for (const unsigned int a2 : next_to(a))
                    for (const unsigned int b2 : next_to(b))
                      if (!(a2 == a && b2 == b) && a2 != b2
                          && (touching(a2, b2)
                              || seam.count(
                                {std::min(a2, b2), std::max(a2, b2)})))
                        chained = true;
                  if (chained)
                    {
                      seam.insert({a, b});
                      ++seam_counts[k];
                      grown = true;
                    }
                }
            }
        }
    }
  } // namespace contact
} // namespace pneuma
