#include <pneuma/contact/contact_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/selection_parameter.h>
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
    ContactParameters::declare_parameters(ParameterHandler  &prm,
                                          const InputLayout &layout)
    {
      const auto instances =
        layout.numbered("Contact", "Pair", "Contact/Number of pairs");
      // Sized once: the entries are bound to these members.
      pairs.clear();
      pairs.resize(instances.size());
      text.clear();
      text.resize(instances.size());
      prm.enter_subsection("Contact");
      for (unsigned int k = 0; k < instances.size(); ++k)
        {
          ContactPair &p = pairs[k];
          Text        &t = text[k];
          p.path         = "Contact/" + instances[k];
          prm.enter_subsection(instances[k]);
          prm.add_parameter("Cable",
                            t.cable,
                            "The cable (its number in Cables) whose mid-line "
                            "is the slave.",
                            Patterns::Integer(1));
          prm.add_parameter("Membrane regions",
                            t.regions,
                            "Material ids of the master surface, comma "
                            "separated (empty: all).",
                            Patterns::Anything());
          add_selection(prm,
                        "Side",
                        p.outside,
                        {{"outside", true}, {"inside", false}},
                        "The side of the membrane the cable is on: "
                        "outside = where the outward normal "
                        "(Geometry/Orientation) points.");
          add_selection(
            prm,
            "Master normal",
            p.smoothed_normal,
            {{"smoothed", true}, {"facet", false}},
            "The normal along which the gap is measured. smoothed: "
            "interpolated from nodal normals (the average of the unit "
            "normals of the pair's cells at each node), continuous across "
            "cell edges, so that a cable lying on a mesh line or across "
            "the edges of flat Q1 facets is pushed along the averaged "
            "normal (its tangent includes the nodal normals' dependence "
            "on the neighbouring cells); facet: each cell's own normal "
            "and closest point (cheaper; the normal jumps at cell edges).");
          prm.add_parameter(
            "Smoothed normal from",
            p.smoothed_from,
            "With Master normal = smoothed: the pseudo time after which the "
            "smoothed normal is used; the load steps up to it use each "
            "cell's facet normal (0: smoothed from the start). For a cable "
            "pressed onto a flaccid wall through the inflation, where the "
            "nodal normals of the crumpling wall make the smoothed contact "
            "fail: facet normals until the wall is taut, smoothed after "
            "(a step back across it by a cut-back uses the facet normal "
            "again).",
            Patterns::Double(0.));
          prm.add_parameter("Radius",
                            p.radius,
                            "Cable radius R in the gap [m] (0: the larger "
                            "semi-axis of the cable's section).",
                            Patterns::Double(0.));
          prm.add_parameter("Penalty",
                            p.penalty,
                            "eps_N [N/m^2]: contact line load per unit "
                            "penetration (paper eq. 9).",
                            Patterns::Double(0.));
          add_selection(prm,
                        "Integration",
                        p.lobatto,
                        {{"gauss", false}, {"lobatto", true}},
                        "Points along each cable element.");
          prm.add_parameter("Points per element",
                            p.points_per_element,
                            "Integration points per cable element (Lobatto: "
                            "at least 2).",
                            Patterns::Integer(1, 10));
          prm.add_parameter("Search distance",
                            p.search_distance,
                            "Membrane cells closer than R + this to a cable "
                            "element (current configuration, updated every "
                            "load step) are contact candidates [m] (0: R "
                            "plus one cable element length).",
                            Patterns::Double(0.));
          prm.add_parameter(
            "Maximum motion per step",
            p.max_motion,
            "A converged load step is rejected and cut back if a cable "
            "point that was near the membrane at the step's start moved "
            "relative to the material point it faced by more than this "
            "fraction of the search distance (the step's candidate cells "
            "may no longer hold it), or if a point penetrates a cell that "
            "was not among its candidates (0: only the second test).",
            Patterns::Double(0., 1.));
          prm.add_parameter("Friction coefficient",
                            p.friction,
                            "Coulomb friction mu (0: frictionless). The "
                            "cable sticks elastically (Tangential penalty) "
                            "until the tangential force reaches mu N, then "
                            "slips.",
                            Patterns::Double(0.));
          prm.add_parameter("Tangential penalty",
                            p.tangential_penalty,
                            "eps_T [N/m^2]: tangential line load per unit "
                            "elastic slip while sticking (0: the Penalty).",
                            Patterns::Double(0.));
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    ContactParameters::parse_parameters(ParameterHandler  &prm,
                                        const unsigned int n_cables)
    {
      prm.enter_subsection("Contact");
      AssertThrow(static_cast<long>(pairs.size())
                    == prm.get_integer("Number of pairs"),
                  ExcMessage("the pairs declared are not those of the "
                             "input"));
      prm.leave_subsection();
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          ContactPair &p = pairs[k];
          const Text  &t = text[k];
          check_input(t.cable >= 1 && t.cable <= n_cables,
                      p.path + "/Cable",
                      "there is no cable " + std::to_string(t.cable)
                        + " (Cables/Number of cables = "
                        + std::to_string(n_cables) + ")");
          p.cable = t.cable - 1;
          p.regions.clear();
          for (const auto id :
               loads::parse_id_list(t.regions, p.path + "/Membrane regions"))
            p.regions.insert(id);
          check_input(p.penalty > 0., p.path + "/Penalty", "must be > 0");
          check_input(p.smoothed_from == 0. || p.smoothed_normal,
                      p.path + "/Smoothed normal from",
                      "needs Master normal = smoothed");
          check_input(!p.lobatto || p.points_per_element >= 2,
                      p.path + "/Points per element",
                      "Lobatto integration needs at least 2 points");
          if (p.tangential_penalty == 0.)
            p.tangential_penalty = p.penalty;
        }
    }
  } // namespace contact
} // namespace pneuma
