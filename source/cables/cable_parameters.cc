#include <deal.II/base/utilities.h>

#include <pneuma/cables/cable_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/loads/loads.h>

#include <cmath>
#include <map>
#include <tuple>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
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
      : prestress_factor(std::make_unique<Functions::ParsedFunction<3>>(1))
      , start_displacement(std::make_unique<Functions::ParsedFunction<3>>(3))
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

    /// One declared cable: the bound entries (their defaults are the
    /// declared ones), one instance of every element and shape, and the
    /// definition that parse_parameters() builds.
    struct CableParameters::Slot
    {
      std::string         name;
      std::string         element = "cable", shape = "polyline";
      unsigned int        n_elements = 16;
      std::vector<double> semi_axes{0.005, 0.005};
      double youngs_modulus = 2e11, density = 0., prestress_force = 0.,
             unstressed_length  = 0.;
      std::string start_support = "free", end_support = "free",
                  start_components = "xyz", end_components = "xyz";
      bool end_forces = false;

      std::map<std::string, std::unique_ptr<CableElement>> elements;
      std::map<std::string, std::unique_ptr<CableShape>>   shapes;
      CableDefinition                                      definition;
    };

    CableParameters::CableParameters()  = default;
    CableParameters::~CableParameters() = default;

    const CableDefinition &
    CableParameters::operator[](const unsigned int k) const
    {
      return slots[k]->definition;
    }

    void
    CableParameters::declare_parameters(ParameterHandler  &prm,
                                        const InputLayout &layout)
    {
      slots.clear();
      const auto &elements = CableElementRegistry::instance();
      const auto &shapes   = CableShapeRegistry::instance();
      prm.enter_subsection("Cables");
      for (const auto &instance :
           layout.numbered("Cables", "Cable", "Cables/Number of cables"))
        {
          auto  slot = std::make_unique<Slot>();
          Slot &s    = *slot;
          s.name     = instance;
          prm.enter_subsection(instance);
          prm.add_parameter("Element",
                            s.element,
                            "The cable element; its constants are in the "
                            "subsection of its name. "
                              + elements.descriptions() + ".",
                            Patterns::Selection(elements.names()));
          prm.add_parameter("Shape",
                            s.shape,
                            "The reference mid-line; its constants are in "
                            "the subsection of its name. "
                              + shapes.descriptions() + ".",
                            Patterns::Selection(shapes.names()));
          prm.add_parameter("Number of elements",
                            s.n_elements,
                            "Elements along the cable (polyline: spread over "
                            "the segments by length; ring; helix; a gmsh "
                            "mesh brings its own).",
                            Patterns::Integer(1, 100000));
          prm.add_parameter("Section semi-axes",
                            s.semi_axes,
                            "Semi-axes a, b of the elliptic section, or one "
                            "radius [m]; area pi a b.",
                            Patterns::List(Patterns::Double(0.), 1, 2));
          prm.add_parameter("Young's modulus",
                            s.youngs_modulus,
                            "E [Pa].",
                            Patterns::Double(0.));
          prm.add_parameter("Density",
                            s.density,
                            "Mass density [kg/m^3]; gravity (Loads/Gravity) "
                            "acts on density * area per unstressed length, "
                            "and a modal analysis' mass is the same.",
                            Patterns::Double(0.));
          prm.add_parameter("Prestress force",
                            s.prestress_force,
                            "Axial force [N] in the reference shape: the "
                            "unstressed length is L/(1 + F/EA). Staged by "
                            "the Prestress factor f(t): L/(1 + f F/EA), a "
                            "cable shortened (a turnbuckle) as t goes on.",
                            Patterns::Double(0.));
          prm.add_parameter("Unstressed length",
                            s.unstressed_length,
                            "Length [m] of the unstressed cable (0: the "
                            "reference length). A length above the reference "
                            "length makes a slack cable (e.g. a catenary).",
                            Patterns::Double(0.));
          prm.add_parameter("Start support",
                            s.start_support,
                            "First end: fixed holds every unknown of the end "
                            "node (the position, and the section of a solid "
                            "beam), pinned the position only.",
                            Patterns::Selection("free|fixed|pinned"));
          prm.add_parameter("End support",
                            s.end_support,
                            "Last end, as Start support.",
                            Patterns::Selection("free|fixed|pinned"));
          prm.add_parameter("Start components",
                            s.start_components,
                            "Position components held by the Start support "
                            "(any of x, y, z; e.g. xy leaves the end free "
                            "along z).",
                            Patterns::Anything());
          prm.add_parameter("End components",
                            s.end_components,
                            "Position components held by the End support.",
                            Patterns::Anything());
          loads::declare_function(prm, "Start displacement", 3, "0; 0; 0");
          loads::declare_function(prm, "End displacement", 3, "0; 0; 0");
          prm.add_parameter("End forces",
                            s.end_forces,
                            "Apply the Start force and End force functions "
                            "(dead forces [N]).",
                            Patterns::Bool());
          loads::declare_function(prm, "Start force", 3, "0; 0; 0");
          loads::declare_function(prm, "End force", 3, "0; 0; 0");
          // Dead load [N/m per unstressed length], function of the
          // reference position and t; active unless all zero.
          loads::declare_function(prm, "Distributed load", 3, "0; 0; 0");
          loads::declare_function(prm, "End moment", 3, "0; 0; 0");
          loads::declare_function(prm, "Prestress factor", 1, "1");
          s.elements = elements.declare_all(prm);
          s.shapes   = shapes.declare_all(prm);
          prm.leave_subsection();
          slots.push_back(std::move(slot));
        }
      prm.leave_subsection();
    }

    void
    CableParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cables");
      for (auto &slot : slots)
        {
          Slot             &s    = *slot;
          CableDefinition  &d    = s.definition;
          const std::string path = "Cables/" + s.name;
          prm.enter_subsection(s.name);
          d.path         = path;
          d.element_name = s.element;
          d.element      = CableElementRegistry::instance().take(
            s.elements, prm, s.element, path + "/Element", path);
          d.shape_name = s.shape;
          d.shape      = CableShapeRegistry::instance().take(
            s.shapes, prm, s.shape, path + "/Shape", path);

          d.n_elements              = s.n_elements;
          const unsigned int fewest = d.shape->minimum_elements();
          check_input(d.n_elements >= fewest,
                      path + "/Number of elements",
                      "a " + s.shape + " needs at least "
                        + std::to_string(fewest) + " elements");
          d.section_a = s.semi_axes[0];
          d.section_b =
            s.semi_axes.size() > 1 ? s.semi_axes[1] : s.semi_axes[0];
          check_input(d.section_a > 0. && d.section_b > 0.,
                      path + "/Section semi-axes",
                      "the semi-axes must be > 0");
          d.youngs_modulus = s.youngs_modulus;
          // Above 1e14 Pa (100 times diamond's) a modulus is a typing
          // error, and E A times a strain would overflow.
          check_input(d.youngs_modulus > 0. && d.youngs_modulus <= 1e14,
                      path + "/Young's modulus",
                      "must be > 0 and at most 1e14 Pa");
          d.density           = s.density;
          d.prestress_force   = s.prestress_force;
          d.unstressed_length = s.unstressed_length;
          check_input(d.prestress_force == 0. || d.unstressed_length == 0.,
                      path + "/Unstressed length",
                      "give either a Prestress force or an Unstressed "
                      "length, not both");

          d.start_support = parse_support(s.start_support);
          d.end_support   = parse_support(s.end_support);
          for (const auto &[name, text, flags] :
               {std::make_tuple(std::string("Start components"),
                                &s.start_components,
                                &d.start_components),
                std::make_tuple(std::string("End components"),
                                &s.end_components,
                                &d.end_components)})
            {
              check_input(!text->empty()
                            && text->find_first_not_of("xyz")
                                 == std::string::npos,
                          path + "/" + name,
                          "'" + *text + "' is not a set of x, y, z");
              for (unsigned int c = 0; c < 3; ++c)
                (*flags)[c] = text->find("xyz"[c]) != std::string::npos;
            }
          if (d.closed())
            check_input(d.start_support == EndSupport::free
                          && d.end_support == EndSupport::free,
                        path + "/Start support",
                        "a " + s.shape + " has no ends to support");
          loads::parse_function(prm,
                                *d.start_displacement,
                                "Start displacement",
                                path + "/Start displacement",
                                true);
          loads::parse_function(prm,
                                *d.end_displacement,
                                "End displacement",
                                path + "/End displacement",
                                true);
          d.has_end_forces = s.end_forces;
          loads::parse_function(
            prm, *d.start_force, "Start force", path + "/Start force", true);
          loads::parse_function(
            prm, *d.end_force, "End force", path + "/End force", true);
          loads::parse_function(prm,
                                *d.distributed_load,
                                "Distributed load",
                                path + "/Distributed load");
          prm.enter_subsection("Distributed load");
          d.has_distributed_load =
            !is_zero_expression(prm.get("Function expression"));
          prm.leave_subsection();
          loads::parse_function(
            prm, *d.end_moment, "End moment", path + "/End moment", true);
          loads::parse_function(prm,
                                *d.prestress_factor,
                                "Prestress factor",
                                path + "/Prestress factor",
                                true);
          prm.enter_subsection("Prestress factor");
          d.staged_prestress =
            Utilities::trim(prm.get("Function expression")) != "1";
          prm.leave_subsection();
          check_input(!d.staged_prestress || d.prestress_force > 0.,
                      path + "/Prestress factor",
                      "stages a Prestress force, which is not given");
          prm.enter_subsection("End moment");
          d.has_end_moment =
            !is_zero_expression(prm.get("Function expression"));
          prm.leave_subsection();
          if (d.has_end_moment)
            check_input(d.element->carries_moments(),
                        path + "/End moment",
                        "Element = " + s.element
                          + " carries no moment; choose an element that does "
                            "(e.g. solid beam)");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }
  } // namespace cables
} // namespace pneuma
