#pragma once

/**
 * @file
 * The membrane surface of a scene: one variant per geometry (disc, square,
 * sphere, closed cylinder, Gmsh mesh), each one .cc file in
 * source/geometry/shapes/ with one registration line (core/registry.h).
 * A variant builds the coarse mesh with its material ids, attaches the
 * manifolds that refinement and higher-order mappings follow, and knows
 * which side of each cell is outside (pressure pushes outward).
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria.h>

#include <pneuma/core/registry.h>

namespace pneuma
{
  namespace geometry
  {
    using namespace dealii;

    /// Manifold id of the curved part of a built-in surface.
    constexpr types::manifold_id curved_manifold = 1;

    /**
     * Check that @p value, the length @p parameter [m] of a geometry, is
     * positive and at most 1e6 m (lengths are in metres: a larger one is a
     * typing error, e.g. 1e300, and would overflow the mesh's extent).
     */
    void
    check_length(double value, const std::string &parameter);

    /**
     * The coarse cells along a cylinder of @p length and @p radius: @p given
     * if not 0, else nearly square cells (4 around). An InputError names
     * @p path's Radius if that needs more than 1000 (a radius in the wrong
     * units would otherwise make a coarse mesh of 10^12 cells).
     */
    unsigned int
    cylinder_cells_along(double             length,
                         double             radius,
                         unsigned int       given,
                         const std::string &path);

    /// One kind of membrane surface.
    class SurfaceGeometry
    {
    public:
      virtual ~SurfaceGeometry() = default;
      /// Declare (and bind) its constants in the current subsection.
      virtual void
      declare_parameters(ParameterHandler &prm) = 0;
      /// Check them; messages name @p path.
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &path) = 0;
      /// The coarse mesh with the material ids of its regions.
      virtual void
      create_coarse_mesh(Triangulation<2, 3> &coarse) const = 0;
      /// Manifolds of the distributed mesh (before refinement).
      virtual void
      attach_manifolds(parallel::distributed::Triangulation<2, 3> &tria) const
      {
        (void)tria;
      }
      /// +1 if the deal.II normal @p n at the reference point @p x points
      /// outward, -1 otherwise.
      virtual double
      orientation(const Point<3> &x, const Tensor<1, 3> &n) const = 0;
      /// True for surfaces that enclose a volume.
      virtual bool
      is_closed() const = 0;
      /// A direction given by the mesh file for coarse cell @p index (a
      /// fabric's warp; zero: none).
      virtual Tensor<1, 3>
      coarse_cell_direction(const unsigned int index) const
      {
        (void)index;
        return {};
      }
    };

    /// The registry of surface geometries.
    using GeometryRegistry = Registry<SurfaceGeometry>;
  } // namespace geometry
} // namespace pneuma
