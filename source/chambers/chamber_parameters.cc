#include <deal.II/base/utilities.h>

#include <pneuma/chambers/chamber_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
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
    ChamberParameters::declare_parameters(ParameterHandler &prm,
                          const InputLayout &layout)
    {
      prm.enter_subsection("Chambers");
      prm.declare_entry("Ambient pressure",
                        "101325",
                        Patterns::Double(0.),
                        "Absolute ambient pressure [Pa]; pressures of "
                        "chambers are gauge pressures above it.");
      prm.declare_entry("Gravity",
                        "0, 0, -9.81",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Gravitational acceleration acting on liquid "
                        "fillings [m/s^2]; the free-surface level is "
                        "measured against it.");
      for (const auto &instance :
           layout.numbered("Chambers", "Chamber", "Chambers/Number of chambers"))
        {
          prm.enter_subsection(instance);
          prm.declare_entry(
            "Regions",
            "",
            Patterns::Anything(),
            "Material ids of the walls, comma separated. A minus sign "
            "(e.g. -3) flips a wall: use it for a wall whose outward normal "
            "(Geometry/Orientation) points into this chamber, such as a "
            "divider listed by two chambers.");
          prm.declare_entry("Interior point",
                            "",
                            Patterns::Anything(),
                            "x, y, z of a point inside a convex chamber: "
                            "orients every wall away from it (then the "
                            "signs in Regions are ignored). Empty: use the "
                            "signs.");
          prm.declare_entry("Open",
                            "false",
                            Patterns::Bool(),
                            "A tank: the listed walls are closed by rigid "
                            "walls parallel to gravity that are not meshed "
                            "(liquid fillings only).");
          prm.declare_entry("Filling",
                            "gas",
                            Patterns::Selection(
                              "gas|liquid|liquid and gas|connected"),
                            "What fills the chamber. connected: it shares "
                            "the filling (pressure, level) of the chamber "
                            "named in Connected to.");
          prm.declare_entry("Connected to",
                            "0",
                            Patterns::Integer(0, max_chambers),
                            "For Filling = connected: the number of an "
                            "earlier chamber whose filling this one shares.");
          prm.enter_subsection("Gas");
          prm.declare_entry("Law",
                            "adiabatic",
                            Patterns::Selection("adiabatic|isothermal"),
                            "p V^kappa = const with kappa = Adiabatic "
                            "exponent, or p V = const.");
          prm.declare_entry("Adiabatic exponent",
                            "1.4",
                            Patterns::Double(1.),
                            "kappa of the adiabatic law (1.4 for air).");
          prm.declare_entry("Update",
                            "exact",
                            Patterns::Selection("exact|incremental"),
                            "exact: the law itself; incremental: the "
                            "source paper's first-order update about the "
                            "last converged step (its equation 2).");
          prm.declare_entry("Control",
                            "pressure",
                            Patterns::Selection("pressure|gas amount|volume"),
                            "pressure: the gauge pressure follows the "
                            "Pressure curve; gas amount: the amount follows "
                            "the Gas amount curve and the pressure the gas "
                            "law; volume: the volume follows the Volume "
                            "curve and the pressure is its Lagrange "
                            "multiplier.");
          prm.declare_entry("Seal time",
                            "-1",
                            Patterns::Double(),
                            "With Control = pressure: after the step that "
                            "reaches this pseudo time (use a stage end) the "
                            "chamber is sealed; its gas amount stays fixed "
                            "and the pressure follows the gas law. "
                            "Negative: never.");
          loads::declare_function(prm, "Pressure", 1, "0");
          loads::declare_function(prm, "Gas amount", 1, "1");
          loads::declare_function(prm, "Volume", 1, "1");
          prm.leave_subsection();
          prm.enter_subsection("Liquid");
          prm.declare_entry("Density",
                            "1000",
                            Patterns::Double(0.),
                            "Density of the liquid [kg/m^3].");
          loads::declare_function(prm, "Volume", 1, "0");
          prm.leave_subsection();
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    ChamberParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Chambers");
      const unsigned int n = prm.get_integer("Number of chambers");
      ambient_pressure     = prm.get_double("Ambient pressure");
      {
        const auto g = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Gravity")));
        for (unsigned int d = 0; d < 3; ++d)
          gravity[d] = g[d];
      }
      chambers.clear();
      chambers.resize(n);
      for (unsigned int c = 0; c < n; ++c)
        {
          ChamberDefinition &def = chambers[c];
          def.path = "Chambers/Chamber " + std::to_string(c + 1);
          prm.enter_subsection("Chamber " + std::to_string(c + 1));

          for (auto entry :
               Utilities::split_string_list(prm.get("Regions"), ','))
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
          const std::string interior = prm.get("Interior point");
          def.use_interior_point     = !Utilities::trim(interior).empty();
          if (def.use_interior_point)
            def.interior_point =
              loads::parse_point(interior, def.path + "/Interior point");
          def.open = prm.get_bool("Open");

          const std::string filling = prm.get("Filling");
          def.filling               = filling == "gas"    ? Filling::gas :
                                      filling == "liquid" ? Filling::liquid :
                                      filling == "connected" ?
                                                            Filling::connected :
                                                            Filling::liquid_and_gas;
          const unsigned int to     = prm.get_integer("Connected to");
          if (def.filling == Filling::connected)
            {
              check_input(to >= 1 && to <= c,
                          def.path + "/Connected to",
                          "must name an earlier chamber (1.." +
                            std::to_string(c) + ")");
              def.connected_to = to - 1;
              check_input(chambers[to - 1].filling != Filling::connected,
                          def.path + "/Connected to",
                          "names a chamber that is itself connected; name "
                          "the first chamber of the group");
            }
          else
            def.connected_to = c;

          prm.enter_subsection("Gas");
          const bool   isothermal = prm.get("Law") == "isothermal";
          const double kappa =
            isothermal ? 1. : prm.get_double("Adiabatic exponent");
          def.gas_law = GasLaw(kappa, prm.get("Update") == "incremental");
          const std::string control = prm.get("Control");
          def.control = control == "pressure"   ? GasControl::pressure :
                        control == "gas amount" ? GasControl::amount :
                                                  GasControl::volume;
          def.seal_time = prm.get_double("Seal time");
          def.pressure  = std::make_unique<Functions::ParsedFunction<3>>(1);
          def.amount    = std::make_unique<Functions::ParsedFunction<3>>(1);
          def.volume    = std::make_unique<Functions::ParsedFunction<3>>(1);
          loads::parse_function(prm,
                                *def.pressure,
                                "Pressure",
                                def.path + "/Gas/Pressure");
          loads::parse_function(prm,
                                *def.amount,
                                "Gas amount",
                                def.path + "/Gas/Gas amount");
          loads::parse_function(prm,
                                *def.volume,
                                "Volume",
                                def.path + "/Gas/Volume");
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
          def.density       = prm.get_double("Density");
          def.liquid_volume = std::make_unique<Functions::ParsedFunction<3>>(1);
          loads::parse_function(prm,
                                *def.liquid_volume,
                                "Volume",
                                def.path + "/Liquid/Volume");
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
