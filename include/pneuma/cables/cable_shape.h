#pragma once

/**
 * @file
 * The reference mid-line of a cable (doc/theory.md §8): one variant per
 * shape, each one .cc file in source/cables/shapes/ with one registration
 * line (core/registry.h). The input chooses it with
 * "Cables/Cable <k>/Shape"; its constants live in the subsection of its
 * name, e.g. "Cables/Cable 1/helix/Pitch".
 *
 * The registered shapes: "polyline" (elements spread over the segments by
 * length), "ring" (a closed circle), "helix" (circular_curve.h:
 * \f$X(\varphi) = C + \frac{h\varphi}{2\pi}e_3 + R(\cos\phi\,e_1 +
 * \sin\phi\,e_2)\f$, \f$\phi = \phi_0 \pm \varphi\f$), "gmsh" (one open
 * chain of the lines of a 1D-in-3D Gmsh mesh).
 *
 * A shape builds the mesh of straight linear cells between nodes on the
 * curve; every rank holds the whole cable mesh (p4est does not distribute
 * 1D meshes).
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <pneuma/core/registry.h>

#include <string>
#include <vector>

namespace pneuma
{
  namespace cables
  {
    using namespace dealii;

    /// One kind of reference mid-line.
    class CableShape
    {
    public:
      virtual ~CableShape() = default;

      /// Declare (and bind) the shape's constants in the current
      /// subsection.
      virtual void
      declare_parameters(ParameterHandler &prm) = 0;
      /// Check the constants; messages name @p path.
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &path) = 0;

      /**
       * Build the mesh into the empty @p tria, with @p n_elements cells if
       * the shape takes a number ("Cables/Cable <k>/Number of elements").
       * An open cable is ordered: the first vertex of the first cell is
       * the start, the second vertex of the last cell the end. Throws
       * InputError naming the parameter or file.
       */
      virtual void
      create_mesh(const unsigned int   n_elements,
                  Triangulation<1, 3> &tria) const = 0;

      /// True for a closed curve, which has no ends to support.
      virtual bool
      is_closed() const
      {
        return false;
      }

      /// The fewest elements the shape can be meshed with.
      virtual unsigned int
      minimum_elements() const
      {
        return 1;
      }

      /// The shape's preferred direction of a section axis at the
      /// reference point @p X (a solid beam's semi-axis a lies along it,
      /// projected normal to the mid-line), or zero if it has none (then
      /// the element's own Section axis is used).
      virtual Tensor<1, 3>
      section_direction(const Point<3> &X) const
      {
        (void)X;
        return Tensor<1, 3>();
      }
    };

    /// The registry of cable shapes.
    using CableShapeRegistry = Registry<CableShape>;

    /// The mesh of the ordered @p vertices: cells i -> i+1, and the last
    /// back to the first when @p closed (for the shapes).
    void
    create_chain_mesh(const std::vector<Point<3>> &vertices,
                      const bool                   closed,
                      Triangulation<1, 3>         &tria);
  } // namespace cables
} // namespace pneuma
