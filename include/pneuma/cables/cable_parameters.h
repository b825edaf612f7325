#pragma once

/**
 * @file
 * The "Cables" subsection: the cables of a scene, each on its own
 * one-dimensional mesh with its own element, section, material, prestress,
 * supports and loads (doc/user-guide.md "Cables", doc/theory.md "Cables").
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>

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

    /// Largest number of cables a parameter file can declare.
    constexpr unsigned int max_cables = 16;

    /// Which element a cable uses.
    enum class CableElement
    {
      /// Displacement-only truss, tension only (doc/theory.md §8.1).
      cable,
      /// The source paper's solid-beam: mid-line and two section directors
      /// per node, 3D continuum over the elliptic section (§8.2).
      solid_beam
    };

    /// How the reference mid-line is built.
    enum class CableShape
    {
      polyline,
      ring,
      helix,
      gmsh
    };

    /// Support at one end of an open cable.
    enum class EndSupport
    {
      free,
      /// Position held (truss), or position and section (solid-beam).
      fixed,
      /// Position held, section free to rotate (solid-beam).
      pinned
    };

    /// One cable as given in the input.
    struct CableDefinition
    {
      CableDefinition();

      /// "Cables/Cable k", for messages.
      std::string path;

      CableElement element = CableElement::cable;
      CableShape   shape   = CableShape::polyline;

      // Geometry.
      std::vector<Point<3>> points;
      Point<3>              centre;
      Tensor<1, 3>          axis, reference_direction;
      double                radius = 1., start_angle = 0., pitch = 0.,
             angle_to_axis = 0., turns = 1.;
      bool         right_handed = true;
      std::string  mesh_file;
      int          physical_group = -1;
      unsigned int n_elements     = 16;

      // Section and material.
      double     section_a = 0.005, section_b = 0.005;
      Tensor<1, 3> section_axis;
      double       youngs_modulus = 2e11, poisson_ratio = 0.3, density = 0.;
      /// Solid-beam law: St. Venant-Kirchhoff, or compressible neo-Hookean.
      bool         neo_hookean = false;

      // Prestress: reference length / unstressed length.
      double prestress_force = 0., unstressed_length = 0.;
      double slack_ratio = 1e-6;

      // Supports and loads.
      EndSupport start_support = EndSupport::free,
                 end_support   = EndSupport::free;
      /// Position components held at a supported end (x, y, z).
      std::array<bool, 3> start_components{{true, true, true}},
        end_components{{true, true, true}};
      std::unique_ptr<Functions::ParsedFunction<3>> start_displacement,
        end_displacement, start_force, end_force, distributed_load;
      bool has_end_forces = false, has_distributed_load = false;
      /// Pure moment at the end (solid-beam) [N m]: a conservative couple
      /// on the end section, whose potential is -M . theta with theta the
      /// rotation of the section.
      std::unique_ptr<Functions::ParsedFunction<3>> end_moment;
      bool has_end_moment = false;

      /// Cross-section area (pi a b).
      double
      area() const;
      /// True for a closed curve (ring), which has no ends.
      bool
      closed() const
      {
        return shape == CableShape::ring;
      }
    };

    /// The "Cables" subsection.
    class CableParameters
    {
    public:
      /// "Cables/Number of cables" alone (it decides whether the subsystem exists).
      static void
      declare_count(ParameterHandler &prm);
      static void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      void
      parse_parameters(ParameterHandler &prm);

      bool
      empty() const
      {
        return cables.empty();
      }
      unsigned int
      size() const
      {
        return cables.size();
      }
      const CableDefinition &
      operator[](const unsigned int k) const
      {
        return cables[k];
      }

    private:
      std::vector<CableDefinition> cables;
    };
  } // namespace cables
} // namespace pneuma
