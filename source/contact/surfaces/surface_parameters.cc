#include <pneuma/contact/surfaces/surface_parameters.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/loads/loads.h>

#include <algorithm>
#include <cmath>

namespace pneuma
{
  namespace contact
  {
    void
    SurfaceParameters::declare_count(ParameterHandler &prm)
    {
      prm.enter_subsection("Surface contact");
      prm.declare_entry("Number of pairs",
                        "0",
                        Patterns::Integer(0, max_surface_pairs),
                        "Pairs 1..N below are used (0: none).");
      prm.leave_subsection();
    }

    void
    SurfaceParameters::declare_parameters(ParameterHandler  &prm,
                                          const InputLayout &layout)
    {
      const auto instances = layout.numbered("Surface contact",
                                             "Pair",
                                             "Surface contact/Number of pairs");
      pairs.assign(instances.size(), SurfacePair());
      first_text.assign(instances.size(), "");
      second_text.assign(instances.size(), "");
      prm.enter_subsection("Surface contact");
      for (unsigned int k = 0; k < instances.size(); ++k)
        {
          SurfacePair &p = pairs[k];
          p.path         = "Surface contact/" + instances[k];
          prm.enter_subsection(instances[k]);
          prm.add_parameter("Regions",
                            first_text[k],
                            "Material ids of the membrane regions of the "
                            "first side, comma separated (empty: all).",
                            Patterns::Anything());
          prm.add_parameter(
            "Opposite regions",
            second_text[k],
            "Material ids of the regions the first side bears on, comma "
            "separated. Empty: self-contact of the first side (each cell "
            "against every cell of it that shares no vertex with it).",
            Patterns::Anything());
          prm.add_parameter(
            "Penalty",
            p.penalty,
            "Contact pressure per penetration [Pa/m]. 0: derived per cell "
            "as Penalty factor x E t / h^2 (E t = 3 x the initial shear "
            "modulus x thickness of the cell's region, h the node spacing); "
            "the run prints the range it chose.",
            Patterns::Double(0.));
          prm.add_parameter("Penalty factor",
                            p.penalty_factor,
                            "f of the derived penalty (Penalty = 0).",
                            Patterns::Double(0.));
          prm.add_parameter(
            "Search distance",
            p.search_distance,
            "How far apart [m] a point and a cell of the other side may be "
            "at the start of a load step to be tested in it; a step that "
            "brings a point into a cell not tested is cut back. 0: four "
            "times the largest motion of the pair's nodes in the step "
            "before (at least twice the thickness, at most the largest "
            "cell size; a quarter of it in the first step).",
            Patterns::Double(0.));
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    SurfaceParameters::parse_parameters(ParameterHandler &)
    {
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          SurfacePair &p = pairs[k];
          p.first.clear();
          p.second.clear();
          for (const auto id :
               loads::parse_id_list(first_text[k], p.path + "/Regions"))
            p.first.insert(static_cast<types::material_id>(id));
          for (const auto id :
               loads::parse_id_list(second_text[k],
                                    p.path + "/Opposite regions"))
            p.second.insert(static_cast<types::material_id>(id));
          for (const auto id : p.second)
            check_input(p.first.empty() ? false : p.first.count(id) == 0,
                        p.path + "/Opposite regions",
                        "region " + std::to_string(id)
                          + " is on both sides (leave Opposite regions "
                            "empty for the self-contact of Regions)");
          check_input(std::isfinite(p.penalty),
                      p.path + "/Penalty",
                      "must be finite");
          check_input(p.penalty > 0.
                        || (p.penalty_factor > 0.
                            && std::isfinite(p.penalty_factor)),
                      p.path + "/Penalty factor",
                      "must be positive and finite when Penalty is 0");
          check_input(std::isfinite(p.search_distance),
                      p.path + "/Search distance",
                      "must be finite");
        }
    }
  } // namespace contact
} // namespace pneuma
