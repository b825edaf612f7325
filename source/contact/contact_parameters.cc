#include <pneuma/contact/contact_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/loads/loads.h>

namespace pneuma
{
  namespace contact
  {
    void
    ContactParameters::declare_count(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry("Number of pairs",
                        "0",
                        Patterns::Integer(0),
                        "Contact pairs 1..N below are used (0: no contact "
                        "and no search).");
      prm.leave_subsection();
    }

    void
    ContactParameters::declare_parameters(ParameterHandler &prm,
                          const InputLayout &layout)
    {
      prm.enter_subsection("Contact");
      for (const auto &instance :
           layout.numbered("Contact", "Pair", "Contact/Number of pairs"))
        {
          prm.enter_subsection(instance);
          prm.declare_entry("Cable",
                            "1",
                            Patterns::Integer(1),
                            "The cable (its number in Cables) whose mid-line "
                            "is the slave.");
          prm.declare_entry("Membrane regions",
                            "",
                            Patterns::Anything(),
                            "Material ids of the master surface, comma "
                            "separated (empty: all).");
          prm.declare_entry("Side",
                            "outside",
                            Patterns::Selection("outside|inside"),
                            "The side of the membrane the cable is on: "
                            "outside = where the outward normal "
                            "(Geometry/Orientation) points.");
          prm.declare_entry("Radius",
                            "0",
                            Patterns::Double(0.),
                            "Cable radius R in the gap [m] (0: the larger "
                            "semi-axis of the cable's section).");
          prm.declare_entry("Penalty",
                            "1e6",
                            Patterns::Double(0.),
                            "eps_N [N/m^2]: contact line load per unit "
                            "penetration (paper eq. 9).");
          prm.declare_entry("Integration",
                            "gauss",
                            Patterns::Selection("gauss|lobatto"),
                            "Points along each cable element.");
          prm.declare_entry("Points per element",
                            "2",
                            Patterns::Integer(1, 10),
                            "Integration points per cable element (Lobatto: "
                            "at least 2).");
          prm.declare_entry("Search distance",
                            "0",
                            Patterns::Double(0.),
                            "Membrane cells closer than R + this to a cable "
                            "element (current configuration, updated every "
                            "load step) are contact candidates [m] (0: R "
                            "plus one cable element length).");
          prm.declare_entry("Friction coefficient",
                            "0",
                            Patterns::Double(0.),
                            "Coulomb friction mu (0: frictionless). The "
                            "cable sticks elastically (Tangential penalty) "
                            "until the tangential force reaches mu N, then "
                            "slips.");
          prm.declare_entry("Tangential penalty",
                            "0",
                            Patterns::Double(0.),
                            "eps_T [N/m^2]: tangential line load per unit "
                            "elastic slip while sticking (0: the Penalty).");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    ContactParameters::parse_parameters(ParameterHandler  &prm,
                                        const unsigned int n_cables)
    {
      pairs.clear();
      prm.enter_subsection("Contact");
      const unsigned int n = prm.get_integer("Number of pairs");
      for (unsigned int k = 1; k <= n; ++k)
        {
          prm.enter_subsection("Pair " + std::to_string(k));
          ContactPair p;
          p.path = "Contact/Pair " + std::to_string(k);
          const unsigned int cable = prm.get_integer("Cable");
          check_input(cable >= 1 && cable <= n_cables,
                      p.path + "/Cable",
                      "there is no cable " + std::to_string(cable) +
                        " (Cables/Number of cables = " +
                        std::to_string(n_cables) + ")");
          p.cable = cable - 1;
          for (const auto id : loads::parse_id_list(prm.get("Membrane regions"),
                                                    p.path + "/Membrane regions"))
            p.regions.insert(id);
          p.outside            = prm.get("Side") == "outside";
          p.radius             = prm.get_double("Radius");
          p.penalty            = prm.get_double("Penalty");
          check_input(p.penalty > 0., p.path + "/Penalty", "must be > 0");
          p.lobatto            = prm.get("Integration") == "lobatto";
          p.points_per_element = prm.get_integer("Points per element");
          check_input(!p.lobatto || p.points_per_element >= 2,
                      p.path + "/Points per element",
                      "Lobatto integration needs at least 2 points");
          p.search_distance = prm.get_double("Search distance");
          p.friction           = prm.get_double("Friction coefficient");
          p.tangential_penalty = prm.get_double("Tangential penalty");
          if (p.tangential_penalty == 0.)
            p.tangential_penalty = p.penalty;
          prm.leave_subsection();
          pairs.push_back(p);
        }
      prm.leave_subsection();
    }
  } // namespace contact
} // namespace pneuma
