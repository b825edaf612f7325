/**
 * @file
 * The helix about Axis through Centre (circular_curve.h): Turns turns of
 * Radius, the axial advance per turn h = Pitch, or h = 2 pi R / tan(alpha)
 * from the Angle to axis alpha; "Number of elements" equal chords from
 * Start angle, right- or left-handed about the axis. A solid beam's
 * section axis a points outward, radially.
 */

#include <deal.II/base/numbers.h>

#include <pneuma/cables/cable_shape.h>
#include <pneuma/cables/circular_curve.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/selection_parameter.h>

#include <cmath>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      class Helix : public CableShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          circle.declare_parameters(prm);
          prm.add_parameter("Pitch",
                            pitch,
                            "Axial advance per turn [m]; 0: from Angle to "
                            "axis.",
                            Patterns::Double(0.));
          prm.add_parameter("Angle to axis",
                            angle_to_axis_degrees,
                            "Angle between the cable and the axis [degrees] "
                            "(used when Pitch = 0).",
                            Patterns::Double(0., 90.));
          prm.add_parameter("Turns",
                            turns,
                            "Number of turns; > 0.",
                            Patterns::Double(0.));
          add_selection(prm,
                        "Handedness",
                        right_handed,
                        {{"right", true}, {"left", false}},
                        "Right- or left-handed about Axis.");
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          circle.parse_parameters(path);
          check_input(turns > 0., path + "/Turns", "must be > 0");
          check_input(pitch > 0. || angle_to_axis_degrees > 0.,
                      path + "/Pitch",
                      "a helix needs a Pitch > 0 or an Angle to axis > 0");
          const double angle_to_axis =
            angle_to_axis_degrees * numbers::PI / 180.;
          advance = pitch > 0. ? pitch
                               : 2. * numbers::PI * circle.radius()
                                   / std::tan(angle_to_axis);
        }

        void
        create_mesh(const unsigned int   n_elements,
                    Triangulation<1, 3> &tria) const override
        {
          std::vector<Point<3>> vertices;
          const double          phi_end = 2. * numbers::PI * turns;
          for (unsigned int i = 0; i <= n_elements; ++i)
            vertices.push_back(
              circle.point(phi_end * i / n_elements, advance, right_handed));
          create_chain_mesh(vertices, false, tria);
        }

        Tensor<1, 3>
        section_direction(const Point<3> &X) const override
        {
          return circle.radial_direction(X);
        }

      private:
        CircularCurve circle;
        double        pitch = 0., angle_to_axis_degrees = 0., turns = 1.;
        bool          right_handed = true;
        /// The axial advance per turn h [m].
        double advance = 0.;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(CableShape,
                            Helix,
                            "helix",
                            "Turns turns about Axis through Centre, of "
                            "Radius and Pitch (or Angle to axis)")
  } // namespace cables
} // namespace pneuma
