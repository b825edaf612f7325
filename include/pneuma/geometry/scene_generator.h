#pragma once

/**
 * @file
 * Built-in membrane geometries and Gmsh import for the codimension-one
 * membrane mesh (`Triangulation<2,3>`), with manifolds so that refinement and
 * higher-order mappings follow the true curved geometry, and with the
 * outward orientation of every cell (needed by pressure and volume).
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>

#include <string>

namespace pneuma
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * "Geometry" subsection: which surface to build.
     *
     * | type            | placement                         | ids |
     * |-----------------|-----------------------------------|-----|
     * | disc            | radius a, centre 0, plane z = 0    | material 0, rim
     * boundary 0 | | square          | side L, centre 0, plane z = 0      |
     * material 0, edges x-,x+,y-,y+ = 0..3 | | sphere          | radius R,
     * centre 0                 | material 0 | | closed cylinder | radius R,
     * axis x from 0 to L, flat end caps | hull material 0, cap at x=0 material
     * 1, cap at x=L material 2 | | gmsh            | a 2D-in-3D .msh file |
     * physical surfaces = material ids, physical curves = boundary ids |
     *
     * Normals point out of closed surfaces (for the built-ins); a Gmsh mesh
     * is taken as meshed, flipped, or oriented away from an interior point.
     */
    class SceneGenerator
    {
    public:
      /// "Geometry/Type" alone (it decides whether there is a membrane).
      static void
      declare_type(ParameterHandler &prm);
      /// The other entries of "Geometry".
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Build the coarse mesh, attach manifolds and refine globally.
      void
      create_triangulation(
        parallel::distributed::Triangulation<2, 3> &tria) const;

      /**
       * Orientation of a cell: +1 if the deal.II normal at the cell centre
       * @p x (reference configuration) points outward, -1 otherwise.
       */
      double
      orientation(const Point<3> &x, const Tensor<1, 3> &normal) const;

      /// True for surfaces that enclose a volume (sphere, closed cylinder).
      bool
      is_closed() const;

      /// The geometry type as named in the parameter file.
      const std::string &
      type() const
      {
        return geometry_type;
      }

      /// Characteristic radius (or half side), for scaling.
      double
      characteristic_length() const
      {
        return radius;
      }

    private:
      std::string  geometry_type;
      double       radius = 1., length = 1.;
      unsigned int refinements = 0, cells_along_length = 0;
      std::string  mesh_file, orientation_mode;
      Point<3>     interior_point;
    };
  } // namespace geometry
} // namespace pneuma
