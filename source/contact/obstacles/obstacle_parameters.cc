#include <pneuma/contact/obstacles/obstacle_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/loads/loads.h>

#include <cmath>

namespace pneuma
{
  namespace contact
  {
    void
    ObstacleParameters::declare_count(ParameterHandler &prm)
    {
      prm.enter_subsection("Obstacles");
      prm.declare_entry("Number of obstacles",
                        "0",
                        Patterns::Integer(0, max_obstacles),
                        "Obstacles 1..N below are used (0: none).");
      prm.leave_subsection();
    }

    void
    ObstacleParameters::declare_parameters(ParameterHandler  &prm,
                                           const InputLayout &layout)
    {
      const auto &shapes    = ObstacleShapeRegistry::instance();
      const auto  instances = layout.numbered("Obstacles",
                                             "Obstacle",
                                             "Obstacles/Number of obstacles");
      obstacles.clear();
      obstacles.resize(instances.size());
      text.clear();
      text.resize(instances.size());
      prm.enter_subsection("Obstacles");
      for (unsigned int k = 0; k < instances.size(); ++k)
        {
          ObstacleDefinition &def = obstacles[k];
          Text               &t   = text[k];
          def.path                = "Obstacles/" + instances[k];
          prm.enter_subsection(instances[k]);
          prm.add_parameter("Shape",
                            t.shape,
                            "The obstacle's surface: " + shapes.descriptions()
                              + ".",
                            Patterns::Selection(shapes.names()));
          prm.add_parameter("Regions",
                            t.regions,
                            "Material ids of the membrane regions the "
                            "obstacle touches, comma separated (empty: "
                            "all).",
                            Patterns::Anything());
          prm.add_parameter(
            "Penalty",
            def.penalty,
            "Contact pressure per penetration [Pa/m]. 0: derived per cell "
            "as Penalty factor x E t / h^2 (E t = 3 x the initial shear "
            "modulus x thickness of the cell's region, h the node spacing); "
            "the run prints the range it chose.",
            Patterns::Double(0.));
          prm.add_parameter("Penalty factor",
                            def.penalty_factor,
                            "f of the derived penalty (Penalty = 0).",
                            Patterns::Double(0.));
          prm.add_parameter(
            "Friction coefficient",
            def.friction,
            "Coulomb's mu between the membrane and the obstacle (0: "
            "frictionless). A point sticks while its tangential traction, "
            "elastic with the Tangential penalty, stays below mu times its "
            "contact pressure, and slips beyond.",
            Patterns::Double(0.));
          prm.add_parameter("Tangential penalty",
                            def.tangential_penalty,
                            "Tangential traction per elastic slip [Pa/m] "
                            "while a point sticks. 0: the cell's normal "
                            "penalty.",
                            Patterns::Double(0.));
          loads::declare_function(prm, "Displacement", 3, "0; 0; 0");
          prm.add_parameter(
            "Control",
            t.control,
            "displacement: the obstacle moves by its Displacement alone. "
            "force: it also moves along Force direction by as much as "
            "makes the membrane's contact force on it balance Force (its "
            "position along that direction is an unknown; a weight, a "
            "plate pressed by a jack). Needs a static strategy.",
            Patterns::Selection("displacement|force"));
          loads::declare_function(prm, "Force", 1, "0");
          prm.add_parameter("Force direction",
                            t.direction,
                            "x, y, z of the direction in which Force pushes "
                            "the obstacle (any length; Control = force).",
                            Patterns::Anything());
          t.shapes = shapes.declare_all(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    ObstacleParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Obstacles");
      for (unsigned int k = 0; k < obstacles.size(); ++k)
        {
          ObstacleDefinition &def = obstacles[k];
          Text               &t   = text[k];
          prm.enter_subsection("Obstacle " + std::to_string(k + 1));
          def.regions.clear();
          for (const auto id :
               loads::parse_id_list(t.regions, def.path + "/Regions"))
            def.regions.insert(static_cast<types::material_id>(id));
          check_input(std::isfinite(def.penalty),
                      def.path + "/Penalty",
                      "must be finite");
          check_input(def.penalty > 0.
                        || (def.penalty_factor > 0.
                            && std::isfinite(def.penalty_factor)),
                      def.path + "/Penalty factor",
                      "must be positive and finite when Penalty is 0");
          check_input(std::isfinite(def.friction),
                      def.path + "/Friction coefficient",
                      "must be finite");
          check_input(std::isfinite(def.tangential_penalty),
                      def.path + "/Tangential penalty",
                      "must be finite");
          def.displacement = std::make_unique<Functions::ParsedFunction<3>>(3);
          loads::parse_function(prm,
                                *def.displacement,
                                "Displacement",
                                def.path + "/Displacement",
                                true);
          def.force_controlled = t.control == "force";
          def.force = std::make_unique<Functions::ParsedFunction<3>>(1);
          loads::parse_function(
            prm, *def.force, "Force", def.path + "/Force", true);
          def.force_direction =
            parse_direction(t.direction, def.path + "/Force direction");
          def.shape_name = t.shape;
          def.shape      = ObstacleShapeRegistry::instance().take(
            t.shapes, prm, t.shape, def.path + "/Shape", def.path);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }
  } // namespace contact
} // namespace pneuma
