#pragma once

/**
 * @file
 * Junctions: lines where more than two membrane cells meet, e.g. where a
 * divider joins a hull, or where two tubes share a seam (doc/theory.md
 * "Junctions").
 *
 * p4est needs every cell edge to join at most two cells, so the coarse mesh
 * is split along junction lines before the Triangulation is made: around
 * each junction vertex, the cells that are joined through ordinary
 * (two-cell) lines form a fan, and each fan gets its own copy of the vertex.
 * Every junction line thus becomes a boundary line of each cell on it, with
 * the boundary id junction_boundary_id, also where one region lies on both
 * sides of it (a tube whose seam is its junction with a hull and a divider).
 * After the dofs are distributed, the coincident copies are tied together by
 * constraints \f$u_{copy} = u_{master}\f$ (the copy in a rigid plate, if
 * any, is the master), which restores the shared motion of the junction
 * exactly.
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <pneuma/geometry/gmsh_surface_reader.h>

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
     * Split the junction lines of @p data (lines of more than two cells) by
     * fans as described above, and tag the faces that the split creates
     * with junction_boundary_id. Returns the number of junction lines.
     */
    unsigned int
    split_junctions(SurfaceMeshData &data);

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
      find(const Mapping<2, 3>                &mapping,
           const DoFHandler<2, 3>             &dof_handler,
           const std::set<types::material_id> &rigid_ids,
           const IndexSet                     &locally_relevant);

      /// Add u_copy = u_master for every tie not already constrained.
      void
      add_constraints(AffineConstraints<double> &constraints) const;

      /// The copies (to reject supports placed on them).
      std::set<types::global_dof_index>
      copies() const;
    };
  } // namespace geometry
} // namespace pneuma
