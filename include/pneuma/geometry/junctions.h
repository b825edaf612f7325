#pragma once

/**
 * @file
 * Junctions: lines where more than two membrane cells meet, e.g. where a
 * divider joins a hull, or where two tubes share a seam (doc/theory.md
 * "Junctions").
 *
 * p4est needs every cell edge to join at most two cells, so the coarse mesh
 * is split along junction lines: each material region gets its own copy of
 * the junction vertices, and the faces that the split creates get the
 * boundary id junction_boundary_id. After the dofs are distributed, the
 * coincident copies are tied together by constraints
 * \f$u_{copy} = u_{master}\f$ (the copy in a rigid plate, if any, is the
 * master), which restores the shared motion of the junction exactly.
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <set>
#include <utility>
#include <vector>

namespace pneuma
{
  namespace geometry
  {
    using namespace dealii;

    /// Boundary id of the faces created by splitting a junction.
    constexpr types::boundary_id junction_boundary_id = 254;

    /**
     * If @p in has lines shared by more than two cells, build in @p out the
     * same mesh with the junction vertices duplicated per material region
     * and return true; otherwise leave @p out untouched and return false.
     */
    bool
    split_junctions(const Triangulation<2, 3> &in, Triangulation<2, 3> &out);

    /// Ties between coincident dofs on junction faces.
    struct JunctionTies
    {
      /// (copy, master) pairs whose copy is locally relevant.
      std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
        ties;
      /// Every master: each rank must see them.
      IndexSet masters;

      /// Find the ties of the distributed mesh; a copy in a cell whose
      /// material id is in @p rigid_ids (rigid plates, prescribed regions)
      /// is the master.
      void
      find(const Mapping<2, 3>                 &mapping,
           const DoFHandler<2, 3>              &dof_handler,
           const std::set<types::material_id> &rigid_ids,
           const IndexSet                      &locally_relevant);

      /// Add u_copy = u_master for every tie not already constrained.
      void
      add_constraints(AffineConstraints<double> &constraints) const;

      /// The copies (to reject supports placed on them).
      std::set<types::global_dof_index>
      copies() const;
    };
  } // namespace geometry
} // namespace pneuma
