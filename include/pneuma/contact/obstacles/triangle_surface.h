#pragma once

/**
 * @file
 * A rigid surface given as triangles (a Gmsh mesh of a loading saddle, a
 * roller, a rigid body's skin), with the signed distance of a point from
 * it (doc/theory.md "Rigid obstacles", "Obstacles from a mesh").
 *
 * The nearest point c of x on the surface lies on a face, on an edge or at
 * a vertex of one triangle (Ericson, Real-Time Collision Detection, 2005,
 * §5.1.5). Its side is the sign of (x - c) against the angle-weighted
 * pseudonormal of that feature (Baerentzen and Aanaes, IEEE TVCG 11, 2005):
 * the face's normal, the sum of the two faces' normals at an edge, the
 * faces' normals weighted by their angles at a vertex. Then
 * \f$\varphi = \pm|x - c|\f$; on a face its gradient is the face's normal
 * and its Hessian zero, at an edge or a vertex the surface is locally a
 * cylinder or a sphere of radius zero, and \f$\nabla\varphi\f$ and
 * \f$\nabla\nabla\varphi\f$ are those of round_distance() with radius 0
 * (so the membrane's offset surface rounds a sharp edge with its half
 * thickness). \f$\varphi\f$ is continuously differentiable off the medial
 * axis; its Hessian jumps between a face's and an edge's regions.
 *
 * Orientation: the triangles are turned consistently (neighbours run
 * their shared edge in opposite directions); a closed part is then turned
 * so that its normals point out of the volume it encloses; an open part
 * keeps the orientation of its first triangle in the file (Gmsh's node
 * order, right-handed). The nearest triangles are found with a boost
 * R-tree of the triangles' boxes (deal.II's pack_rtree).
 */

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/numerics/rtree.h>

#include <pneuma/contact/obstacles/obstacle_shape.h>

#include <array>
#include <string>
#include <vector>

namespace pneuma
{
  namespace contact
  {
    /// Triangles with the signed distance of a point from them.
    class TriangleSurface
    {
    public:
      /**
       * The surface of @p triangles over @p vertices. Throws InputError
       * naming @p parameter if a triangle is degenerate, an edge joins more
       * than two triangles or the triangles cannot be oriented (a Moebius
       * strip).
       */
      TriangleSurface(std::vector<Point<3>>                    vertices,
                      std::vector<std::array<unsigned int, 3>> triangles,
                      const std::string                       &parameter);

      /// Signed distance, positive on the normals' side.
      SignedDistance
      distance(const Point<3> &x) const;

      unsigned int
      n_triangles() const
      {
        return triangles.size();
      }
      /// Is every edge shared by two triangles?
      bool
      closed() const
      {
        return all_closed;
      }
      /// The volume the surface encloses (closed) [m^3].
      double
      volume() const;

    private:
      /// Turn the triangles consistently; closed parts outwards.
      void
      orient(const std::string &parameter);
      /// Face normals and the pseudonormals of edges and vertices; throws
      /// InputError naming @p parameter for a degenerate triangle.
      void
                            compute_normals(const std::string &parameter);
      std::vector<Point<3>> vertices;
      std::vector<std::array<unsigned int, 3>> triangles;
      std::vector<Tensor<1, 3>>                face_normals;
      /// Per triangle, its edges (v0 v1, v1 v2, v2 v0) as edge indices.
      std::vector<std::array<unsigned int, 3>> triangle_edges;
      std::vector<Tensor<1, 3>>                edge_normals;
      std::vector<Tensor<1, 3>>                vertex_normals;
      bool                                     all_closed = true;
      /// The size of the surface's box: the distance below which a point
      /// lies on the surface.
      double                                         scale = 0.;
      RTree<std::pair<BoundingBox<3>, unsigned int>> tree;
    };
  } // namespace contact
} // namespace pneuma
