#pragma once

/**
 * @file
 * The reference mid-line of a cable as a `Triangulation<1,3>`: a polyline,
 * a closed ring, a helix around an axis, or the lines of a Gmsh mesh. Every
 * rank holds the whole cable mesh (p4est does not distribute 1D meshes).
 */

#include <deal.II/grid/tria.h>

#include <pneuma/cables/cable_parameters.h>

namespace pneuma
{
  namespace cables
  {
    /**
     * Build the mesh of @p cable into @p tria (straight elements between
     * nodes on the curve). Open cables are ordered: the first vertex of the
     * first cell is the start, the second vertex of the last cell the end.
     * Throws InputError naming the parameter or file.
     */
    void
    create_cable_mesh(const CableDefinition &cable, Triangulation<1, 3> &tria);

    /// Positions along a helix (or ring when pitch = 0) at parameter
    /// angles: centre + axial advance + radius (cos, sin) in the plane.
    Point<3>
    point_on_helix(const CableDefinition &cable, const double phi);
  } // namespace cables
} // namespace pneuma
