/**
 * @file
 * The closed ring of Radius about Axis through Centre (circular_curve.h
 * with pitch 0): "Number of elements" (at least 3) equal chords, the first
 * node at Start angle. A ring has no ends; a solid beam's section axis a
 * points outward, radially.
 */

#include <deal.II/base/numbers.h>

#include <pneuma/cables/cable_shape.h>
#include <pneuma/cables/circular_curve.h>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      class Ring : public CableShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          circle.declare_parameters(prm);
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          circle.parse_parameters(path);
        }

        void
        create_mesh(const unsigned int   n_elements,
                    Triangulation<1, 3> &tria) const override
        {
          std::vector<Point<3>> vertices;
          for (unsigned int i = 0; i < n_elements; ++i)
            vertices.push_back(
              circle.point(2. * numbers::PI * i / n_elements, 0.));
          create_chain_mesh(vertices, true, tria);
        }

        bool
        is_closed() const override
        {
          return true;
        }

        unsigned int
        minimum_elements() const override
        {
          return 3;
        }

        Tensor<1, 3>
        section_direction(const Point<3> &X) const override
        {
          return circle.radial_direction(X);
        }

      private:
        CircularCurve circle;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(CableShape,
                            Ring,
                            "ring",
                            "closed circle of Radius about Axis through "
                            "Centre")
  } // namespace cables
} // namespace pneuma
