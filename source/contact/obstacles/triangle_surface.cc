#include <pneuma/contact/obstacles/triangle_surface.h>
#include <pneuma/core/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      namespace bgi = boost::geometry::index;

      /// Where on a triangle its nearest point to x lies.
      enum class Feature
      {
        face,
        edge,
        vertex
      };

      struct Nearest
      {
        Point<3> point;
        Feature  feature = Feature::face;
        /// The edge (0: v0 v1, 1: v1 v2, 2: v2 v0) or the vertex (0..2).
        unsigned int local = 0;
      };

      /// The nearest point of triangle (a, b, c) to p, by the Voronoi
      /// regions of its vertices, edges and face (Ericson 2005, §5.1.5).
      Nearest
      nearest_on_triangle(const Point<3> &p,
                          const Point<3> &a,
                          const Point<3> &b,
                          const Point<3> &c)
      {
        const Tensor<1, 3> ab = b - a, ac = c - a, ap = p - a;
        const double       d1 = ab * ap, d2 = ac * ap;
        if (d1 <= 0. && d2 <= 0.)
          return {a, Feature::vertex, 0};
        const Tensor<1, 3> bp = p - b;
        const double       d3 = ab * bp, d4 = ac * bp;
        if (d3 >= 0. && d4 <= d3)
          return {b, Feature::vertex, 1};
        const double vc = d1 * d4 - d3 * d2;
        if (vc <= 0. && d1 >= 0. && d3 <= 0.)
          return {a + d1 / (d1 - d3) * ab, Feature::edge, 0};
        const Tensor<1, 3> cp = p - c;
        const double       d5 = ab * cp, d6 = ac * cp;
        if (d6 >= 0. && d5 <= d6)
          return {c, Feature::vertex, 2};
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0. && d2 >= 0. && d6 <= 0.)
          return {a + d2 / (d2 - d6) * ac, Feature::edge, 2};
        const double va = d3 * d6 - d5 * d4;
        if (va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)
          return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b),
                  Feature::edge,
                  1};
        const double denominator = 1. / (va + vb + vc);
        return {a + vb * denominator * ab + vc * denominator * ac,
                Feature::face,
                0};
      }

      /// Does triangle @p t run from vertex @p a to vertex @p b?
      bool
      runs(const std::array<unsigned int, 3> &t,
           const unsigned int                 a,
           const unsigned int                 b)
      {
        for (unsigned int k = 0; k < 3; ++k)
          if (t[k] == a && t[(k + 1) % 3] == b)
            return true;
        return false;
      }

      std::pair<unsigned int, unsigned int>
      edge_key(const unsigned int a, const unsigned int b)
      {
        return {std::min(a, b), std::max(a, b)};
      }
    } // namespace

    TriangleSurface::TriangleSurface(
      std::vector<Point<3>>                    vertices_in,
      std::vector<std::array<unsigned int, 3>> triangles_in,
      const std::string                       &parameter)
      : vertices(std::move(vertices_in))
      , triangles(std::move(triangles_in))
    {
      check_input(!triangles.empty(), parameter, "holds no surface cells");
      BoundingBox<3> all(
        std::make_pair(vertices[triangles[0][0]], vertices[triangles[0][0]]));
      for (const auto &t : triangles)
        for (const auto v : t)
          all.merge_with(
            BoundingBox<3>(std::make_pair(vertices[v], vertices[v])));
      scale = all.get_boundary_points().first.distance(
        all.get_boundary_points().second);
      orient(parameter);
      compute_normals(parameter);
      std::vector<std::pair<BoundingBox<3>, unsigned int>> boxes;
      for (unsigned int t = 0; t < triangles.size(); ++t)
        {
          BoundingBox<3> box(std::make_pair(vertices[triangles[t][0]],
                                            vertices[triangles[t][0]]));
          for (const auto v : triangles[t])
            box.merge_with(
              BoundingBox<3>(std::make_pair(vertices[v], vertices[v])));
          boxes.emplace_back(box, t);
        }
      tree = pack_rtree(boxes);
    }

    void
    TriangleSurface::orient(const std::string &parameter)
    {
      const unsigned int n = triangles.size();
      std::map<std::pair<unsigned int, unsigned int>, std::vector<unsigned int>>
        at_edge;
      for (unsigned int t = 0; t < n; ++t)
        for (unsigned int k = 0; k < 3; ++k)
          at_edge[edge_key(triangles[t][k], triangles[t][(k + 1) % 3])]
            .push_back(t);
      for (const auto &[e, ts] : at_edge)
        check_input(ts.size() <= 2,
                    parameter,
                    "the edge between nodes " + std::to_string(e.first + 1)
                      + " and " + std::to_string(e.second + 1) + " joins "
                      + std::to_string(ts.size())
                      + " triangles; a rigid surface must be a manifold");
      // Breadth-first over each connected part, from its first triangle
      // in the file, which keeps its orientation.
      std::vector<int> flip(n, -1), part(n, -1);
      unsigned int     parts = 0;
      for (unsigned int start = 0; start < n; ++start)
        if (flip[start] < 0)
          {
            flip[start] = 0;
            part[start] = parts;
            std::queue<unsigned int> next;
            next.push(start);
            while (!next.empty())
              {
                const unsigned int t = next.front();
                next.pop();
                for (unsigned int k = 0; k < 3; ++k)
                  {
                    const unsigned int a = triangles[t][k],
                                       b = triangles[t][(k + 1) % 3];
                    // t runs a -> b once turned; its neighbour must run b -> a.
                    for (const unsigned int u : at_edge[edge_key(a, b)])
                      if (u != t)
                        {
                          const int want = runs(triangles[u], a, b) ? 1 : 0;
                          if (flip[u] < 0)
                            {
                              flip[u] = (want + flip[t]) % 2;
                              part[u] = parts;
                              next.push(u);
                            }
                          else
                            check_input(flip[u] == (want + flip[t]) % 2,
                                        parameter,
                                        "the triangles cannot be oriented "
                                        "consistently (a Moebius strip)");
                        }
                  }
              }
            ++parts;
          }
      for (unsigned int t = 0; t < n; ++t)
        if (flip[t] == 1)
          std::swap(triangles[t][1], triangles[t][2]);
      // A closed part encloses a positive volume.
      std::vector<double> part_volume(parts, 0.);
      std::vector<bool>   part_closed(parts, true);
      for (const auto &[e, ts] : at_edge)
        if (ts.size() == 1)
          part_closed[part[ts[0]]] = false;
      for (unsigned int t = 0; t < n; ++t)
        {
          const auto &v = triangles[t];
          part_volume[part[t]] +=
            (vertices[v[0]] * cross_product_3d(vertices[v[1]], vertices[v[2]]))
            / 6.;
        }
      for (unsigned int t = 0; t < n; ++t)
        if (part_closed[part[t]] && part_volume[part[t]] < 0.)
          std::swap(triangles[t][1], triangles[t][2]);
      all_closed = std::all_of(part_closed.begin(),
                               part_closed.end(),
                               [](const bool c) { return c; });
      // The edges of every (turned) triangle.
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> index;
      triangle_edges.resize(n);
      for (unsigned int t = 0; t < n; ++t)
        for (unsigned int k = 0; k < 3; ++k)
          {
            const auto key =
              edge_key(triangles[t][k], triangles[t][(k + 1) % 3]);
            const auto it        = index.emplace(key, index.size()).first;
            triangle_edges[t][k] = it->second;
          }
      edge_normals.assign(index.size(), Tensor<1, 3>());
    }

    void
    TriangleSurface::compute_normals(const std::string &parameter)
    {
      face_normals.resize(triangles.size());
      vertex_normals.assign(vertices.size(), Tensor<1, 3>());
      for (unsigned int t = 0; t < triangles.size(); ++t)
        {
          const auto        &v = triangles[t];
          const Tensor<1, 3> n =
            cross_product_3d(vertices[v[1]] - vertices[v[0]],
                             vertices[v[2]] - vertices[v[0]]);
          double longest = 0.;
          for (unsigned int k = 0; k < 3; ++k)
            longest =
              std::max(longest,
                       vertices[v[k]].distance(vertices[v[(k + 1) % 3]]));
          check_input(n.norm() > 1e-12 * longest * longest,
                      parameter,
                      "triangle " + std::to_string(t + 1)
                        + " is degenerate (zero area)");
          face_normals[t] = n / n.norm();
          for (unsigned int k = 0; k < 3; ++k)
            {
              edge_normals[triangle_edges[t][k]] += face_normals[t];
              // The angle at vertex k.
              const Tensor<1, 3> e1 = vertices[v[(k + 1) % 3]] - vertices[v[k]],
                                 e2 = vertices[v[(k + 2) % 3]] - vertices[v[k]];
              const double angle    = std::acos(
                std::clamp(e1 * e2 / (e1.norm() * e2.norm()), -1., 1.));
              vertex_normals[v[k]] += angle * face_normals[t];
            }
        }
      for (auto &n : edge_normals)
        if (n.norm() > 0.)
          n /= n.norm();
      for (auto &n : vertex_normals)
        if (n.norm() > 0.)
          n /= n.norm();
    }

    double
    TriangleSurface::volume() const
    {
      double v = 0.;
      for (const auto &t : triangles)
        v += vertices[t[0]] * cross_product_3d(vertices[t[1]], vertices[t[2]])
             / 6.;
      return v;
    }

    SignedDistance
    TriangleSurface::distance(const Point<3> &x) const
    {
      // The nearest box bounds the distance; every triangle nearer than
      // that bound has its box in the cube around x.
      std::vector<std::pair<BoundingBox<3>, unsigned int>> hits;
      tree.query(bgi::nearest(x, 1), std::back_inserter(hits));
      const auto  &t0    = triangles[hits[0].second];
      const double bound = x.distance(nearest_on_triangle(x,
                                                          vertices[t0[0]],
                                                          vertices[t0[1]],
                                                          vertices[t0[2]])
                                        .point)
                             * (1. + 1e-12)
                           + 1e-15 * scale;
      Point<3> lo = x, hi = x;
      for (unsigned int d = 0; d < 3; ++d)
        {
          lo[d] -= bound;
          hi[d] += bound;
        }
      hits.clear();
      tree.query(bgi::intersects(BoundingBox<3>(std::make_pair(lo, hi))),
                 std::back_inserter(hits));
      std::sort(hits.begin(), hits.end(), [](const auto &a, const auto &b) {
        return a.second < b.second;
      });
      // The nearest triangle (the first in the file among equals).
      unsigned int best = hits[0].second;
      Nearest      near;
      double       nearest_distance = std::numeric_limits<double>::max();
      for (const auto &[box, t] : hits)
        {
          const auto   &v = triangles[t];
          const Nearest n = nearest_on_triangle(x,
                                                vertices[v[0]],
                                                vertices[v[1]],
                                                vertices[v[2]]);
          const double  r = x.distance(n.point);
          if (r < nearest_distance)
            {
              nearest_distance = r;
              near             = n;
              best             = t;
            }
        }
      const auto        &v = triangles[best];
      const Tensor<1, 3> e = x - near.point;
      SignedDistance     s;
      if (near.feature == Feature::face)
        {
          s.normal = face_normals[best];
          s.phi    = (x - vertices[v[0]]) * s.normal;
          return s;
        }
      const Tensor<1, 3> pseudonormal =
        near.feature == Feature::edge
          ? edge_normals[triangle_edges[best][near.local]]
          : vertex_normals[v[near.local]];
      if (nearest_distance <= 1e-12 * scale)
        {
          s.normal = pseudonormal;
          return s;
        }
      Tensor<1, 3> axis;
      if (near.feature == Feature::edge)
        {
          axis = vertices[v[(near.local + 1) % 3]] - vertices[v[near.local]];
          axis /= axis.norm();
        }
      return round_distance(e - (e * axis) * axis,
                            axis,
                            0.,
                            e * pseudonormal >= 0.);
    }
  } // namespace contact
} // namespace pneuma
