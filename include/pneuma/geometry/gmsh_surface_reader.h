#pragma once

/**
 * @file
 * Reading a Gmsh surface mesh (quadrilaterals in 3D) into raw vertex and
 * cell lists, before any Triangulation exists.
 *
 * deal.II's GridIn::read_msh builds the Triangulation at once, and its cell
 * reordering (GridTools::consistently_order_cells) does not terminate on
 * surfaces where a line is shared by more than two cells, as where a
 * waterbeam's small tube, its divider and its hull meet (five cells on one
 * line). pneuma therefore reads the file itself, splits such junction lines
 * (junctions.h) and only then orders the cells and creates the mesh with
 * deal.II. Both ASCII formats that Gmsh writes are read: MSH 2.2 and MSH 4.1.
 *
 * Physical surfaces give the material ids of the quadrilaterals; physical
 * curves give the boundary ids of boundary lines; quadrilaterals outside
 * any physical surface get material id 0 (as in GridIn).
 */

#include <deal.II/base/point.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace pneuma
{
  namespace geometry
  {
    using namespace dealii;

    /// A surface mesh as lists: the input of create_triangulation().
    struct SurfaceMeshData
    {
      std::vector<Point<3>> vertices;
      /// Quadrilaterals with vertices in deal.II (lexicographic) order.
      std::vector<CellData<2>> cells;
      /// Triangles in Gmsh's (counter-clockwise) order, when read with
      /// triangles allowed (a rigid obstacle's surface).
      std::vector<std::array<unsigned int, 3>> triangles;
      /// Lines with a physical curve tag, as boundary ids.
      std::vector<CellData<1>> tagged_lines;
      /// Per cell: the vector of the $ElementData view named "warp" for
      /// its element (zero where the file gives none).
      std::vector<Tensor<1, 3>> cell_warp;
    };

    /// A line of a surface mesh by its two vertex indices, smaller first.
    using MeshLine = std::pair<unsigned int, unsigned int>;

    /// Line @p e (deal.II numbering, 0..3) of the quadrilateral @p cell.
    inline MeshLine
    cell_line(const CellData<2> &cell, const unsigned int e)
    {
      static constexpr unsigned int ends[4][2] = {{0, 2},
                                                  {1, 3},
                                                  {0, 1},
                                                  {2, 3}};
      const unsigned int            a          = cell.vertices[ends[e][0]],
                         b                     = cell.vertices[ends[e][1]];
      return {std::min(a, b), std::max(a, b)};
    }

    /// The same line given by two vertex indices in either order.
    inline MeshLine
    mesh_line(const unsigned int a, const unsigned int b)
    {
      return {std::min(a, b), std::max(a, b)};
    }

    /**
     * Read the quadrilaterals and tagged lines of the Gmsh file @p file
     * (and its triangles if @p triangles). Throws an InputError naming
     * @p parameter and the file when the file is missing, binary, of an
     * unknown version, truncated, or holds higher-order cells or (unless
     * @p triangles) triangles.
     */
    SurfaceMeshData
    read_gmsh_surface(const std::string &file,
                      const std::string &parameter,
                      const bool         triangles = false);

    /**
     * Drop unused vertices, orient the cells consistently and create
     * @p tria from @p data (every line must join at most two cells).
     */
    void
    create_from_surface_data(SurfaceMeshData &data, Triangulation<2, 3> &tria);
  } // namespace geometry
} // namespace pneuma
