#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/selection_parameter.h>
#include <pneuma/loads/loads.h>
#include <pneuma/ties/tie_parameters.h>

namespace pneuma
{
  namespace ties
  {
    void
    TieParameters::declare_count(ParameterHandler &prm)
    {
      prm.enter_subsection("Ties");
      prm.declare_entry("Number of ties",
                        "0",
                        Patterns::Integer(0),
                        "Ties 1..N below are used (0: no ties).");
      prm.leave_subsection();
    }

    void
    TieParameters::declare_parameters(ParameterHandler  &prm,
                                      const InputLayout &layout)
    {
      const auto instances =
        layout.numbered("Ties", "Tie", "Ties/Number of ties");
      // Sized once: the entries are bound to these members.
      ties.clear();
      ties.resize(instances.size());
      text.clear();
      text.resize(instances.size());
      prm.enter_subsection("Ties");
      for (unsigned int k = 0; k < instances.size(); ++k)
        {
          TieDefinition &d = ties[k];
          Text          &t = text[k];
          d.path           = "Ties/" + instances[k];
          prm.enter_subsection(instances[k]);
          prm.add_parameter("Cable",
                            t.cable,
                            "The cable or beam (its number in Cables) whose "
                            "nodes are tied.",
                            Patterns::Integer(1));
          add_selection(prm,
                        "Nodes",
                        d.nodes,
                        {{"both ends", TiedNodes::both_ends},
                         {"start", TiedNodes::start},
                         {"end", TiedNodes::end},
                         {"all", TiedNodes::all}},
                        "The nodes tied: the ends of an open cable (an end "
                        "anchored to an end plate or to a point of the "
                        "membrane), or every node (a beam glued along a "
                        "membrane line). Each node follows the membrane "
                        "point nearest to it in the reference state, "
                        "u = sum_i N_i(xi) u_i (exact constraints).");
          prm.add_parameter("Membrane regions",
                            t.regions,
                            "Material ids of the cells the nodes may be tied "
                            "to, comma separated (empty: all).",
                            Patterns::Anything());
          prm.add_parameter("Maximum distance",
                            d.max_distance,
                            "How far a tied node may lie from the membrane "
                            "in the reference state [m] (0: the larger "
                            "semi-axis of the cable's section). The offset "
                            "is carried along without turning.",
                            Patterns::Double(0.));
          add_selection(prm,
                        "Section",
                        d.follow_section,
                        {{"follow membrane", true}, {"free", false}},
                        "Solid beams: follow membrane = a section semi-axis "
                        "vector A that lies in the membrane's tangent plane "
                        "at the node moves with the membrane, a = F A "
                        "(F the surface deformation gradient; a glued "
                        "strip turns and stretches with the wall); free = "
                        "only the position is tied. Ignored by the cable "
                        "element.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    TieParameters::parse_parameters(ParameterHandler  &prm,
                                    const unsigned int n_cables)
    {
      prm.enter_subsection("Ties");
      AssertThrow(static_cast<long>(ties.size())
                    == prm.get_integer("Number of ties"),
                  ExcMessage("the ties declared are not those of the input"));
      prm.leave_subsection();
      for (unsigned int k = 0; k < ties.size(); ++k)
        {
          TieDefinition &d = ties[k];
          check_input(text[k].cable >= 1 && text[k].cable <= n_cables,
                      d.path + "/Cable",
                      "there is no cable " + std::to_string(text[k].cable)
                        + " (Cables/Number of cables = "
                        + std::to_string(n_cables) + ")");
          d.cable = text[k].cable - 1;
          d.regions.clear();
          for (const auto id :
               loads::parse_id_list(text[k].regions,
                                    d.path + "/Membrane regions"))
            d.regions.insert(id);
        }
    }
  } // namespace ties
} // namespace pneuma
