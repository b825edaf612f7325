#include <deal.II/base/utilities.h>

#include <pneuma/chambers/chamber_parameters.h>

#include <cmath>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/loads/loads.h>

namespace pneuma
{
  namespace chambers
  {
    void
    ChamberParameters::declare_count(ParameterHandler &prm)
    {
      prm.enter_subsection("Chambers");
      prm.declare_entry("Number of chambers",
                        "0",
                        Patterns::Integer(0),
                        "Chambers 1..N below are used (0: no chambers).");
      prm.leave_subsection();
    }

    void
    ChamberParameters::declare_parameters(ParameterHandler  &prm,
                                          const InputLayout &layout)
    {
      prm.enter_subsection("Chambers");
      prm.add_parameter("Ambient pressure",
                        ambient_pressure,
                        "Absolute ambient pressure [Pa]; pressures of "
                        "chambers are gauge pressures above it.",
                        Patterns::Double(0.));
      prm.add_parameter("Gravity",
                        gravity,
                        "Gravitational acceleration acting on liquid "
                        "fillings [m/s^2]; the free-surface level is "
                        "measured against it.",
                        Patterns::List(Patterns::Double(), 3, 3));
      const auto instances =
        layout.numbered("Chambers", "Chamber", "Chambers/Number of chambers");
      // Sized once: the entries are bound to these members.
      chambers.clear();
      chambers.resize(instances.size());
      text.clear();
      text.resize(instances.size());
      for (unsigned int c = 0; c < instances.size(); ++c)
        {
          ChamberDefinition &def = chambers[c];
          Text              &t   = text[c];
          def.path               = "Chambers/" + instances[c];
          prm.enter_subsection(instances[c]);
          prm.add_parameter(
            "Regions",
            t.regions,
            "Material ids of the walls, comma separated. A minus sign "
            "(e.g. -3) flips a wall: use it for a wall whose outward normal "
            "(Geometry/Orientation) points into this chamber, such as a "
            "divider listed by two chambers.",
            Patterns::Anything());
          prm.add_parameter("Interior point",
                            t.interior_point,
                            "x, y, z of a point inside a convex chamber: "
                            "orients every wall away from it (then the "
                            "signs in Regions are ignored). Empty: use the "
                            "signs.",
                            Patterns::Anything());
          prm.add_parameter("Open",
                            def.open,
                            "The listed walls are closed by rigid walls "
                            "parallel to gravity that are not meshed "
                            "(liquid fillings only): a tank open at its top, "
                            "or a slice of a long tube between two vertical "
                            "cuts (plane strain) or a body cut by vertical "
                            "symmetry planes, whose own walls close it above "
                            "and below; a level above such a one's top "
                            "fills it and presses it by the head.");
          add_selection(prm,
                        "Filling",
                        def.filling,
                        {{"gas", Filling::gas},
                         {"liquid", Filling::liquid},
                         {"liquid and gas", Filling::liquid_and_gas},
                         {"connected", Filling::connected}},
                        "What fills the chamber. connected: it shares the "
                        "filling (pressure, level) of the chamber named in "
                        "Connected to.");
          prm.add_parameter("Connected to",
                            t.connected_to,
                            "For Filling = connected: the number of an "
                            "earlier chamber whose filling this one shares.",
                            Patterns::Integer(0, max_chambers));
          prm.enter_subsection("Gas");
          def.gas_law.declare_parameters(prm);
          add_selection(prm,
                        "Control",
                        def.control,
                        {{"pressure", GasControl::pressure},
                         {"gas amount", GasControl::amount},
                         {"volume", GasControl::volume}},
                        "pressure: the gauge pressure follows the Pressure "
                        "curve; gas amount: the amount follows the Gas "
                        "amount curve and the pressure the gas law; volume: "
                        "the volume follows the Volume curve and the "
                        "pressure is its Lagrange multiplier.");
          prm.add_parameter("Seal time",
                            def.seal_time,
                            "With Control = pressure: after the step that "
                            "reaches this pseudo time (use a stage end) the "
                            "chamber is sealed; its gas amount stays fixed "
                            "and the pressure follows the gas law. "
                            "Negative: never.",
                            Patterns::Double());
          loads::declare_function(prm, "Pressure", 1, "0");
          loads::declare_function(prm, "Gas amount", 1, "1");
          loads::declare_function(prm, "Volume", 1, "1");
          prm.leave_subsection();
          prm.enter_subsection("Liquid");
          prm.add_parameter("Density",
                            def.density,
                            "Density of the liquid [kg/m^3].",
                            Patterns::Double(0.));
          add_selection(prm,
                        "Control",
                        def.liquid_control,
                        {{"volume", LiquidControl::volume},
                         {"level", LiquidControl::level}},
                        "volume: the liquid volume follows the Volume curve "
                        "[m^3] and the level is found; level: the free "
                        "surface's height follows the Level curve [m] "
                        "(measured against gravity: with gravity along -z, "
                        "its z coordinate) and the volume is found.");
          loads::declare_function(prm, "Volume", 1, "0");
          loads::declare_function(prm, "Level", 1, "0");
          prm.leave_subsection();
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    ChamberParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Chambers");
      // The gas laws divide by it: a vacuum outside is not a chamber scene.
      check_input(ambient_pressure > 0. && std::isfinite(ambient_pressure),
                  "Chambers/Ambient pressure",
                  "must be positive (absolute pressure), got "
                    + std::to_string(ambient_pressure));
      const unsigned int n = chambers.size();
      AssertThrow(static_cast<long>(n) == prm.get_integer("Number of chambers"),
                  ExcMessage("the chambers declared are not those of the "
                             "input"));
      for (unsigned int c = 0; c < n; ++c)
        {
          ChamberDefinition &def = chambers[c];
          const Text        &t   = text[c];
          prm.enter_subsection("Chamber " + std::to_string(c + 1));

          def.regions.clear();
          for (auto entry : Utilities::split_string_list(t.regions, ','))
            {
              int sign = 1;
              if (!entry.empty() && (entry[0] == '-' || entry[0] == '+'))
                {
                  sign  = entry[0] == '-' ? -1 : 1;
                  entry = Utilities::trim(entry.substr(1));
                }
              int id = -1;
              try
                {
                  id = Utilities::string_to_int(entry);
                }
              catch (...)
                {
                }
              check_input(id >= 0 && id < 256,
                          def.path + "/Regions",
                          "'" + entry + "' is not a material id");
              def.regions.emplace_back(id, sign);
            }
          check_input(!def.regions.empty(),
                      def.path + "/Regions",
                      "is empty: a chamber needs walls");
          def.use_interior_point = !Utilities::trim(t.interior_point).empty();
          if (def.use_interior_point)
            def.interior_point =
              loads::parse_point(t.interior_point,
                                 def.path + "/Interior point");

          if (def.filling == Filling::connected)
            {
              check_input(t.connected_to >= 1 && t.connected_to <= c,
                          def.path + "/Connected to",
                          "must name an earlier chamber (1.."
                            + std::to_string(c) + ")");
              def.connected_to = t.connected_to - 1;
              check_input(chambers[def.connected_to].filling
                            != Filling::connected,
                          def.path + "/Connected to",
                          "names a chamber that is itself connected; name "
                          "the first chamber of the group");
            }
          else
            def.connected_to = c;

          prm.enter_subsection("Gas");
          def.gas_law.parse_parameters(prm, def.path + "/Gas");
          def.pressure = std::make_unique<Functions::ParsedFunction<3>>(1);
          def.amount   = std::make_unique<Functions::ParsedFunction<3>>(1);
          def.volume   = std::make_unique<Functions::ParsedFunction<3>>(1);
          loads::parse_function(
            prm, *def.pressure, "Pressure", def.path + "/Gas/Pressure", true);
          loads::parse_function(
            prm, *def.amount, "Gas amount", def.path + "/Gas/Gas amount", true);
          loads::parse_function(
            prm, *def.volume, "Volume", def.path + "/Gas/Volume", true);
          prm.leave_subsection();
          check_input(!(def.filling == Filling::liquid_and_gas
                        && def.control == GasControl::volume),
                      def.path + "/Gas/Control",
                      "volume control is not possible with liquid and gas "
                      "(the liquid volume is prescribed already); use "
                      "pressure or gas amount");
          check_input(!(def.open && def.has_gas()),
                      def.path + "/Open",
                      "an open chamber (tank) can only hold a liquid");

          prm.enter_subsection("Liquid");
          def.liquid_volume = std::make_unique<Functions::ParsedFunction<3>>(1);
          def.liquid_level  = std::make_unique<Functions::ParsedFunction<3>>(1);
          loads::parse_function(prm,
                                *def.liquid_volume,
                                "Volume",
                                def.path + "/Liquid/Volume",
                                true);
          loads::parse_function(
            prm, *def.liquid_level, "Level", def.path + "/Liquid/Level", true);
          prm.leave_subsection();
          prm.leave_subsection();
        }
      prm.leave_subsection();
      for (const auto &def : chambers)
        if (def.has_liquid())
          check_input(gravity.norm() > 0.,
                      "Chambers/Gravity",
                      "is zero but " + def.path + " holds a liquid");
    }
  } // namespace chambers
} // namespace pneuma
