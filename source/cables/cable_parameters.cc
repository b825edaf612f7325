#include <deal.II/base/utilities.h>

#include <pneuma/cables/cable_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/loads/loads.h>

#include <cmath>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      Tensor<1, 3>
      parse_vector(const std::string &text, const std::string &path)
      {
        const Point<3> p = loads::parse_point(text, path);
        return Tensor<1, 3>(p);
      }

      EndSupport
      parse_support(const std::string &text)
      {
        if (text == "fixed")
          return EndSupport::fixed;
        if (text == "pinned")
          return EndSupport::pinned;
        return EndSupport::free;
      }

      bool
      is_zero_expression(const std::string &expression)
      {
        for (const auto &item : Utilities::split_string_list(expression, ';'))
          {
            try
              {
                if (Utilities::string_to_double(item) != 0.)
                  return false;
              }
            catch (...)
              {
                return false;
              }
          }
        return true;
      }
    } // namespace

    CableDefinition::CableDefinition()
      : start_displacement(std::make_unique<Functions::ParsedFunction<3>>(3))
      , end_displacement(std::make_unique<Functions::ParsedFunction<3>>(3))
      , start_force(std::make_unique<Functions::ParsedFunction<3>>(3))
      , end_force(std::make_unique<Functions::ParsedFunction<3>>(3))
      , distributed_load(std::make_unique<Functions::ParsedFunction<3>>(3))
      , end_moment(std::make_unique<Functions::ParsedFunction<3>>(3))
    {
    }

    double
    CableDefinition::area() const
    {
      return numbers::PI * section_a * section_b;
    }

    void
    CableParameters::declare_count(ParameterHandler &prm)
    {
      prm.enter_subsection("Cables");
      prm.declare_entry("Number of cables",
                        "0",
                        Patterns::Integer(0),
                        "Cables 1..N below are used (0: no cables, and no "
                        "cable work at all).");
      prm.leave_subsection();
    }

    void
    CableParameters::declare_parameters(ParameterHandler &prm,
                          const InputLayout &layout)
    {
      prm.enter_subsection("Cables");
      for (const auto &instance :
           layout.numbered("Cables", "Cable", "Cables/Number of cables"))
        {
          prm.enter_subsection(instance);
          prm.declare_entry(
            "Element",
            "cable",
            Patterns::Selection("cable|solid beam"),
            "cable: tension-only truss (displacements only); solid beam: "
            "the source paper's solid-beam element (mid-line and two "
            "section axes per node, 3D material over the elliptic section).");
          prm.declare_entry(
            "Shape",
            "polyline",
            Patterns::Selection("polyline|ring|helix|gmsh"),
            "Reference mid-line: a polyline through Points, a closed ring or "
            "a helix around Axis through Centre, or a 1D-in-3D Gmsh mesh.");
          prm.declare_entry("Points",
                            "0, 0, 0; 1, 0, 0",
                            Patterns::Anything(),
                            "Polyline vertices 'x, y, z; x, y, z; ...' [m]; "
                            "the elements are spread over it by length.");
          prm.declare_entry("Centre",
                            "0, 0, 0",
                            Patterns::Anything(),
                            "Ring/helix: a point on the axis; the ring lies "
                            "in the plane through it, the helix starts "
                            "there [m].");
          prm.declare_entry("Axis",
                            "1, 0, 0",
                            Patterns::Anything(),
                            "Ring/helix: axis direction.");
          prm.declare_entry("Reference direction",
                            "0, 0, 1",
                            Patterns::Anything(),
                            "Ring/helix: the direction (projected normal to "
                            "the axis) of angle 0.");
          prm.declare_entry("Radius",
                            "1",
                            Patterns::Double(0.),
                            "Ring/helix: radius of the mid-line [m].");
          prm.declare_entry("Start angle",
                            "0",
                            Patterns::Double(),
                            "Ring/helix: angle of the first node from the "
                            "reference direction [degrees].");
          prm.declare_entry("Pitch",
                            "0",
                            Patterns::Double(0.),
                            "Helix: axial advance per turn [m]; 0: use "
                            "Angle to axis.");
          prm.declare_entry("Angle to axis",
                            "0",
                            Patterns::Double(0., 90.),
                            "Helix: angle between the cable and the axis "
                            "[degrees] (used when Pitch = 0).");
          prm.declare_entry("Turns",
                            "1",
                            Patterns::Double(0.),
                            "Helix: number of turns.");
          prm.declare_entry("Handedness",
                            "right",
                            Patterns::Selection("right|left"),
                            "Helix: right- or left-handed about Axis.");
          prm.declare_entry("Mesh file",
                            "",
                            Patterns::Anything(),
                            "Gmsh: a 1D-in-3D .msh file (line elements).");
          prm.declare_entry("Physical group",
                            "-1",
                            Patterns::Integer(-1),
                            "Gmsh: the physical curve that is this cable "
                            "(-1: every line of the file).");
          prm.declare_entry("Number of elements",
                            "16",
                            Patterns::Integer(1),
                            "Elements along the cable (polyline, ring, "
                            "helix).");
          prm.declare_entry("Section semi-axes",
                            "0.005, 0.005",
                            Patterns::List(Patterns::Double(0.), 1, 2),
                            "Semi-axes a, b of the elliptic section, or one "
                            "radius [m]; area pi a b.");
          prm.declare_entry("Section axis",
                            "0, 0, 1",
                            Patterns::Anything(),
                            "Solid beam: direction of the semi-axis a, "
                            "projected normal to the mid-line; for ring and "
                            "helix the outward radial direction is used.");
          prm.declare_entry("Young's modulus",
                            "2e11",
                            Patterns::Double(0.),
                            "E [Pa].");
          prm.declare_entry("Poisson's ratio",
                            "0.3",
                            Patterns::Double(-1., 0.5),
                            "nu (solid beam).");
          prm.declare_entry("Density",
                            "0",
                            Patterns::Double(0.),
                            "Mass density [kg/m^3]; gravity (Loads/Gravity) "
                            "acts on density * area per unstressed length.");
          prm.declare_entry("Law",
                            "Saint Venant-Kirchhoff",
                            Patterns::Selection(
                              "Saint Venant-Kirchhoff|neo-Hookean"),
                            "Solid beam: 3D hyperelastic law (compressible "
                            "neo-Hookean).");
          prm.declare_entry("Prestress force",
                            "0",
                            Patterns::Double(0.),
                            "Axial force [N] in the reference shape: the "
                            "unstressed length is L/(1 + F/EA).");
          prm.declare_entry("Unstressed length",
                            "0",
                            Patterns::Double(0.),
                            "Length [m] of the unstressed cable (0: the "
                            "reference length). A length above the reference "
                            "length makes a slack cable (e.g. a catenary).");
          prm.declare_entry(
            "Slack stiffness ratio",
            "1e-6",
            Patterns::Double(0., 1.),
            "Cable: axial stiffness in compression relative to EA. A slack "
            "cable then carries (almost) nothing, yet the matrix stays "
            "regular; it has no effect on a taut cable.");
          prm.declare_entry("Start support",
                            "free",
                            Patterns::Selection("free|fixed|pinned"),
                            "First end: fixed holds the position (and the "
                            "section of a solid beam), pinned the position "
                            "only.");
          prm.declare_entry("End support",
                            "free",
                            Patterns::Selection("free|fixed|pinned"),
                            "Last end, as Start support.");
          prm.declare_entry("Start components",
                            "xyz",
                            Patterns::Anything(),
                            "Position components held by the Start support "
                            "(any of x, y, z; e.g. xy leaves the end free "
                            "along z).");
          prm.declare_entry("End components",
                            "xyz",
                            Patterns::Anything(),
                            "Position components held by the End support.");
          loads::declare_function(prm, "Start displacement", 3, "0; 0; 0");
          loads::declare_function(prm, "End displacement", 3, "0; 0; 0");
          prm.declare_entry("End forces",
                            "false",
                            Patterns::Bool(),
                            "Apply the Start force and End force functions "
                            "(dead forces [N]).");
          loads::declare_function(prm, "Start force", 3, "0; 0; 0");
          loads::declare_function(prm, "End force", 3, "0; 0; 0");
          prm.declare_entry("Distributed load",
                            "false",
                            Patterns::Bool(),
                            "Apply the Distributed load function [N/m per "
                            "unstressed length].");
          loads::declare_function(prm, "Distributed load", 3, "0; 0; 0");
          loads::declare_function(prm, "End moment", 3, "0; 0; 0");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    CableParameters::parse_parameters(ParameterHandler &prm)
    {
      cables.clear();
      prm.enter_subsection("Cables");
      const unsigned int n = prm.get_integer("Number of cables");
      for (unsigned int c = 1; c <= n; ++c)
        {
          const std::string path = "Cables/Cable " + std::to_string(c);
          prm.enter_subsection("Cable " + std::to_string(c));
          CableDefinition d;
          d.path    = path;
          d.element = prm.get("Element") == "solid beam" ?
                        CableElement::solid_beam :
                        CableElement::cable;
          const std::string shape = prm.get("Shape");
          d.shape = shape == "ring"  ? CableShape::ring :
                    shape == "helix" ? CableShape::helix :
                    shape == "gmsh"  ? CableShape::gmsh :
                                       CableShape::polyline;
          for (const auto &p :
               Utilities::split_string_list(prm.get("Points"), ';'))
            d.points.push_back(loads::parse_point(p, path + "/Points"));
          if (d.shape == CableShape::polyline)
            {
              check_input(d.points.size() >= 2,
                          path + "/Points",
                          "a polyline needs at least two points");
              for (unsigned int i = 1; i < d.points.size(); ++i)
                check_input(d.points[i].distance(d.points[i - 1]) > 0.,
                            path + "/Points",
                            "points " + std::to_string(i) + " and " +
                              std::to_string(i + 1) + " coincide");
            }
          d.centre = loads::parse_point(prm.get("Centre"), path + "/Centre");
          d.axis   = parse_vector(prm.get("Axis"), path + "/Axis");
          d.reference_direction = parse_vector(prm.get("Reference direction"),
                                               path + "/Reference direction");
          d.radius        = prm.get_double("Radius");
          d.start_angle   = prm.get_double("Start angle") * numbers::PI / 180.;
          d.pitch         = prm.get_double("Pitch");
          d.angle_to_axis = prm.get_double("Angle to axis") * numbers::PI / 180.;
          d.turns         = prm.get_double("Turns");
          d.right_handed  = prm.get("Handedness") == "right";
          if (d.shape == CableShape::ring || d.shape == CableShape::helix)
            {
              check_input(d.axis.norm() > 0.,
                          path + "/Axis",
                          "the axis must not be zero");
              const Tensor<1, 3> e = d.axis / d.axis.norm();
              check_input((d.reference_direction -
                           (d.reference_direction * e) * e)
                                .norm() > 1e-12 * d.reference_direction.norm(),
                          path + "/Reference direction",
                          "must not be parallel to the axis");
              check_input(d.radius > 0.,
                          path + "/Radius",
                          "a ring or helix needs a radius > 0");
            }
          if (d.shape == CableShape::helix)
            {
              check_input(d.turns > 0., path + "/Turns", "must be > 0");
              check_input(d.pitch > 0. || d.angle_to_axis > 0.,
                          path + "/Pitch",
                          "a helix needs a Pitch > 0 or an Angle to axis "
                          "> 0");
            }
          d.mesh_file      = prm.get("Mesh file");
          d.physical_group = prm.get_integer("Physical group");
          if (d.shape == CableShape::gmsh)
            check_input(!d.mesh_file.empty(),
                        path + "/Mesh file",
                        "is empty but Shape = gmsh");
          d.n_elements = prm.get_integer("Number of elements");
          if (d.shape == CableShape::ring)
            check_input(d.n_elements >= 3,
                        path + "/Number of elements",
                        "a ring needs at least 3 elements");

          const auto axes =
            Utilities::string_to_double(
              Utilities::split_string_list(prm.get("Section semi-axes")));
          d.section_a = axes[0];
          d.section_b = axes.size() > 1 ? axes[1] : axes[0];
          check_input(d.section_a > 0. && d.section_b > 0.,
                      path + "/Section semi-axes",
                      "the semi-axes must be > 0");
          d.section_axis =
            parse_vector(prm.get("Section axis"), path + "/Section axis");
          if (d.element == CableElement::solid_beam &&
              d.shape == CableShape::polyline)
            check_input(d.section_axis.norm() > 0.,
                        path + "/Section axis",
                        "must not be zero");
          d.youngs_modulus = prm.get_double("Young's modulus");
          check_input(d.youngs_modulus > 0.,
                      path + "/Young's modulus",
                      "must be > 0");
          d.poisson_ratio = prm.get_double("Poisson's ratio");
          check_input(d.poisson_ratio < 0.5,
                      path + "/Poisson's ratio",
                      "must be < 0.5 (the solid-beam law is compressible)");
          d.density     = prm.get_double("Density");
          d.neo_hookean = prm.get("Law") == "neo-Hookean";

          d.prestress_force   = prm.get_double("Prestress force");
          d.unstressed_length = prm.get_double("Unstressed length");
          check_input(d.prestress_force == 0. || d.unstressed_length == 0.,
                      path + "/Unstressed length",
                      "give either a Prestress force or an Unstressed "
                      "length, not both");
          d.slack_ratio = prm.get_double("Slack stiffness ratio");

          d.start_support = parse_support(prm.get("Start support"));
          d.end_support   = parse_support(prm.get("End support"));
          for (const auto &[name, flags] :
               {std::make_pair(std::string("Start components"),
                               &d.start_components),
                std::make_pair(std::string("End components"),
                               &d.end_components)})
            {
              const std::string text = prm.get(name);
              check_input(!text.empty() &&
                            text.find_first_not_of("xyz") == std::string::npos,
                          path + "/" + name,
                          "'" + text + "' is not a set of x, y, z");
              for (unsigned int c = 0; c < 3; ++c)
                (*flags)[c] = text.find("xyz"[c]) != std::string::npos;
            }
          if (d.closed())
            check_input(d.start_support == EndSupport::free &&
                          d.end_support == EndSupport::free,
                        path + "/Start support",
                        "a ring has no ends to support");
          loads::parse_function(prm,
                                *d.start_displacement,
                                "Start displacement",
                                path + "/Start displacement");
          loads::parse_function(prm,
                                *d.end_displacement,
                                "End displacement",
                                path + "/End displacement");
          d.has_end_forces = prm.get_bool("End forces");
          loads::parse_function(prm,
                                *d.start_force,
                                "Start force",
                                path + "/Start force");
          loads::parse_function(prm,
                                *d.end_force,
                                "End force",
                                path + "/End force");
          d.has_distributed_load = prm.get_bool("Distributed load");
          loads::parse_function(prm,
                                *d.distributed_load,
                                "Distributed load",
                                path + "/Distributed load");
          loads::parse_function(prm,
                                *d.end_moment,
                                "End moment",
                                path + "/End moment");
          prm.enter_subsection("End moment");
          d.has_end_moment =
            !is_zero_expression(prm.get("Function expression"));
          prm.leave_subsection();
          if (d.has_end_moment)
            check_input(d.element == CableElement::solid_beam,
                        path + "/End moment",
                        "a cable element carries no moment; use Element = "
                        "solid beam");
          prm.leave_subsection();
          cables.push_back(std::move(d));
        }
      prm.leave_subsection();
    }
  } // namespace cables
} // namespace pneuma
