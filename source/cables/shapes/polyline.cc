/**
 * @file
 * The polyline through Points (doc/theory.md §8): "Number of elements"
 * cells spread over the segments by length, at least one each.
 */

#include <deal.II/base/utilities.h>

#include <pneuma/cables/cable_shape.h>
#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>

#include <algorithm>
#include <cmath>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      class Polyline : public CableShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Points",
                            points_text,
                            "Vertices 'x, y, z; x, y, z; ...' [m], at least "
                            "two; the elements are spread over the segments "
                            "by length.",
                            Patterns::Anything());
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          points.clear();
          for (const auto &p : Utilities::split_string_list(points_text, ';'))
            points.push_back(loads::parse_point(p, path + "/Points"));
          check_input(points.size() >= 2,
                      path + "/Points",
                      "a polyline needs at least two points");
          for (unsigned int i = 1; i < points.size(); ++i)
            check_input(points[i].distance(points[i - 1]) > 0.,
                        path + "/Points",
                        "points " + std::to_string(i) + " and "
                          + std::to_string(i + 1) + " coincide");
        }

        void
        create_mesh(const unsigned int   n_elements,
                    Triangulation<1, 3> &tria) const override
        {
          const auto &p     = points;
          double      total = 0.;
          for (unsigned int i = 1; i < p.size(); ++i)
            total += p[i].distance(p[i - 1]);
          std::vector<Point<3>> vertices{p[0]};
          for (unsigned int i = 1; i < p.size(); ++i)
            {
              const double       l = p[i].distance(p[i - 1]);
              const unsigned int n =
                std::max<unsigned int>(1, std::lround(n_elements * l / total));
              for (unsigned int k = 1; k <= n; ++k)
                vertices.push_back(p[i - 1]
                                   + (double(k) / n) * (p[i] - p[i - 1]));
            }
          create_chain_mesh(vertices, false, tria);
        }

      private:
        std::string           points_text = "0, 0, 0; 1, 0, 0";
        std::vector<Point<3>> points;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(CableShape,
                            Polyline,
                            "polyline",
                            "straight segments through Points")
  } // namespace cables
} // namespace pneuma
