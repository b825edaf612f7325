/**
 * @file
 * A rigid body given as a Gmsh surface mesh (a loading saddle, a roller, a
 * shaped indenter): its triangles, and its quadrilaterals split into two
 * triangles along the shorter diagonal, are the obstacle's surface
 * (contact/obstacles/triangle_surface.h). The membrane stays on the side
 * the normals point to (Side = outside: outside a closed body, in front of
 * an open surface) or on the other.
 */

#include <pneuma/contact/obstacles/obstacle_shape.h>
#include <pneuma/contact/obstacles/triangle_surface.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/geometry/gmsh_surface_reader.h>

#include <memory>
#include <sstream>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      class GmshSurface : public ObstacleShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Mesh file",
                            mesh_file,
                            "An ASCII Gmsh surface mesh (MSH 2.2 or 4.1) of "
                            "first-order triangles and/or quadrilaterals, "
                            "relative to the working directory: the "
                            "obstacle's surface in its reference position.",
                            Patterns::Anything());
          add_selection(prm,
                        "Side",
                        outside,
                        {{"outside", true}, {"inside", false}},
                        "Where the membrane stays: outside a closed "
                        "surface (its normals are turned outwards) or "
                        "inside it; for an open surface, in front of it "
                        "(the side its first triangle's normal points to, "
                        "by Gmsh's node order) or behind it.");
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          const std::string parameter = path + "/Mesh file";
          check_input(!mesh_file.empty(), parameter, "is empty");
          auto data = geometry::read_gmsh_surface(mesh_file, parameter, true);
          auto triangles = std::move(data.triangles);
          for (const auto &c : data.cells)
            {
              // Gmsh's counter-clockwise order of the quadrilateral.
              const std::array<unsigned int, 4> q = {
                {c.vertices[0], c.vertices[1], c.vertices[3], c.vertices[2]}};
              const double d02 =
                             data.vertices[q[0]].distance(data.vertices[q[2]]),
                           d13 =
                             data.vertices[q[1]].distance(data.vertices[q[3]]);
              if (d02 <= d13)
                {
                  triangles.push_back({{q[0], q[1], q[2]}});
                  triangles.push_back({{q[0], q[2], q[3]}});
                }
              else
                {
                  triangles.push_back({{q[0], q[1], q[3]}});
                  triangles.push_back({{q[1], q[2], q[3]}});
                }
            }
          check_input(!triangles.empty(),
                      parameter,
                      "'" + mesh_file
                        + "' holds no triangles or quadrilaterals");
          surface = std::make_unique<TriangleSurface>(std::move(data.vertices),
                                                      std::move(triangles),
                                                      parameter);
        }

        SignedDistance
        distance(const Point<3> &x) const override
        {
          SignedDistance d = surface->distance(x);
          if (!outside)
            {
              d.phi     = -d.phi;
              d.normal  = -d.normal;
              d.hessian = -d.hessian;
            }
          return d;
        }

        std::string
        describe() const override
        {
          std::ostringstream s;
          s << "Gmsh surface '" << mesh_file << "' of "
            << surface->n_triangles() << " triangles, ";
          if (surface->closed())
            s << "closed (enclosing " << surface->volume() << " m^3)";
          else
            s << "open";
          s << ", membrane "
            << (outside ? (surface->closed() ? "outside" : "in front")
                        : (surface->closed() ? "inside" : "behind"));
          return s.str();
        }

      private:
        std::string                      mesh_file;
        bool                             outside = true;
        std::unique_ptr<TriangleSurface> surface;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(ObstacleShape,
                            GmshSurface,
                            "gmsh",
                            "the triangles and quadrilaterals of a Gmsh "
                            "surface Mesh file (a rigid body of any shape)")
  } // namespace contact
} // namespace pneuma
