#pragma once

/**
 * @file
 * The "Geometry" subsection: which membrane surface to build (a variant of
 * geometry/surface_geometry.h, its constants in the subsection of its
 * name, or none for a scene of cables only) and how often to refine it.
 *
 * | Type            | placement and ids |
 * |-----------------|-------------------|
 * | disc            | radius a, centre 0, plane z = 0; material 0, rim boundary
 * 0 | | square          | side L, centre 0, plane z = 0; material 0, edges
 * x-,x+,y-,y+ = 0..3 | | sphere          | radius R, centre 0; material 0 | |
 * closed cylinder | radius R, axis x from 0 to L, flat caps; hull 0, cap at x =
 * 0 is 1, at x = L is 2 | | gmsh            | a 2D-in-3D .msh file; physical
 * surfaces = material ids, physical curves = boundary ids |
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>

#include <pneuma/geometry/surface_geometry.h>

#include <map>
#include <memory>
#include <string>

namespace pneuma
{
  namespace geometry
  {
    using namespace dealii;

    /// "Geometry" subsection: the surface of the scene.
    class SceneGenerator
    {
    public:
      /// "Geometry/Type" alone (none: the scene has no membrane).
      static void
      declare_type(ParameterHandler &prm);
      /// The other entries of "Geometry" (every variant's subsection).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Build the coarse mesh, attach manifolds and refine globally; or,
       * if @p saved names the mesh of a checkpoint, refine as saved there
       * (p4est, any number of ranks). Throws InputError naming @p saved if
       * it cannot be read.
       *
       * Before any refinement, the size guard: the refined mesh's cells
       * times @p unknowns_per_cell estimate the unknowns, and a run whose
       * estimated memory exceeds Geometry/Memory limit (default: this
       * machine's memory) stops with a message saying how much it would
       * need. A coarse mesh whose extent is not a length in metres
       * (1e-6 m to 1e6 m) is bad input too.
       */
      void
      create_triangulation(parallel::distributed::Triangulation<2, 3> &tria,
                           const std::string &saved             = "",
                           const double       unknowns_per_cell = 3.) const;

      /// Estimated memory [bytes] of a run with @p unknowns (the factorized
      /// tangent dominates; measured on the airbeam, benchmarks/).
      static double
      estimated_memory(const double unknowns, const double unknowns_per_cell);
      /**
       * Orientation of a cell: +1 if the deal.II normal at the cell centre
       * @p x (reference configuration) points outward, -1 otherwise.
       */
      double
      orientation(const Point<3> &x, const Tensor<1, 3> &normal) const
      {
        return surface->orientation(x, normal);
      }
      /// True for surfaces that enclose a volume.
      bool
      is_closed() const
      {
        return surface->is_closed();
      }
      /// The mesh file's direction for @p cell (that of its coarse cell;
      /// zero where the file gives none).
      template <class Iterator>
      Tensor<1, 3>
      cell_direction(const Iterator &cell) const
      {
        typename Triangulation<2, 3>::cell_iterator coarse(cell);
        while (coarse->level() > 0)
          coarse = coarse->parent();
        return surface->coarse_cell_direction(coarse->index());
      }
      /// The geometry type as named in the parameter file.
      const std::string &
      type() const
      {
        return geometry_type;
      }

    private:
      std::string  geometry_type;
      unsigned int refinements = 3;
      /// Size guard [GB]: 0 this machine's memory, < 0 no guard.
      double                                                  memory_limit = 0.;
      std::map<std::string, std::unique_ptr<SurfaceGeometry>> variants;
      std::unique_ptr<SurfaceGeometry>                        surface;
    };
  } // namespace geometry
} // namespace pneuma
