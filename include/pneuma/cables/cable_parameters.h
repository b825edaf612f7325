#pragma once

/**
 * @file
 * The "Cables" subsection: the cables of a scene, each on its own
 * one-dimensional mesh with its own element, shape, section, material,
 * prestress, supports and loads (doc/user-guide.md "Cables", doc/theory.md
 * §8). The element and the shape are variants chosen by name
 * (core/registry.h); their constants live in the subsection of their name,
 * e.g. "Cables/Cable 1/helix/Pitch" and "Cables/Cable 1/solid beam/Law".
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>

#include <pneuma/cables/cable_element.h>
#include <pneuma/cables/cable_shape.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  class InputLayout;

  namespace cables
  {
    using namespace dealii;

    /// Support at one end of an open cable.
    enum class EndSupport
    {
      free,
      /// Every component of the end node held (the position, and the
      /// section of a solid beam).
      fixed,
      /// The position held, the element's further components free (the
      /// section of a solid beam may rotate).
      pinned
    };

    /**
     * One cable as given in the input, after CableParameters::parse_parameters
     * (which sets every member from the bound entries; the defaults are
     * those of the declarations).
     */
    struct CableDefinition
    {
      CableDefinition();

      /// "Cables/Cable k", for messages.
      std::string path;

      /// The element (its constants; CableSystem::setup prepares it for the
      /// mesh), and its name ("Element").
      std::unique_ptr<CableElement> element;
      std::string                   element_name;
      /// The reference mid-line, and its name ("Shape").
      std::unique_ptr<CableShape> shape;
      std::string                 shape_name;
      /// Elements along the cable (shapes that take a number).
      unsigned int n_elements = 0;

      /// Semi-axes a, b of the elliptic section [m].
      double section_a = 0., section_b = 0.;
      /// Young's modulus E [Pa] and mass density [kg/m^3].
      double youngs_modulus = 0., density = 0.;
      /// Prestress: the axial force in the reference shape [N], or the
      /// unstressed length [m] (0: not given).
      double prestress_force = 0., unstressed_length = 0.;
      /// Prestress as a load stage: the Prestress force times this factor
      /// f(t) (default 1), e.g. a cable tensioned after inflation.
      std::unique_ptr<Functions::ParsedFunction<3>> prestress_factor;
      bool                                          staged_prestress = false;

      /// Supports of the ends, and the position components they hold (x,
      /// y, z).
      EndSupport start_support = EndSupport::free,
                 end_support   = EndSupport::free;
      std::array<bool, 3> start_components{{true, true, true}},
        end_components{{true, true, true}};
      std::unique_ptr<Functions::ParsedFunction<3>> start_displacement,
        end_displacement, start_force, end_force, distributed_load;
      bool has_end_forces = false, has_distributed_load = false;
      /// Pure moment at the end [N m] (elements that carry moments): a
      /// conservative couple on the end section, whose potential is
      /// -M . theta with theta the rotation of the section.
      std::unique_ptr<Functions::ParsedFunction<3>> end_moment;
      bool                                          has_end_moment = false;

      /// Cross-section area (pi a b).
      double
      area() const;
      /// True for a closed curve (ring), which has no ends.
      bool
      closed() const
      {
        return shape->is_closed();
      }
    };

    /**
     * The "Cables" subsection: "Number of cables" and Cable 1..N, each with
     * the entries common to every cable (Element, Shape, Number of
     * elements, section, material, prestress, supports, loads) and, in the
     * subsection of each element's and each shape's name, their constants
     * (cable_element.h, cable_shape.h).
     */
    class CableParameters
    {
    public:
      CableParameters();
      ~CableParameters();

      /// "Cables/Number of cables" alone (it decides whether the subsystem
      /// exists).
      static void
      declare_count(ParameterHandler &prm);
      /// Declare (and bind) Cable 1..N of @p layout.
      void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      /// Check the entries and build the definitions.
      void
      parse_parameters(ParameterHandler &prm);

      bool
      empty() const
      {
        return slots.empty();
      }
      unsigned int
      size() const
      {
        return slots.size();
      }
      const CableDefinition &
      operator[](const unsigned int k) const;

    private:
      struct Slot;
      std::vector<std::unique_ptr<Slot>> slots;
    };
  } // namespace cables
} // namespace pneuma
