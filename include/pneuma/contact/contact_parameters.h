#pragma once

/**
 * @file
 * The "Contact" subsection: curve-to-surface contact pairs between a cable
 * mid-line (slave) and membrane regions (master), doc/user-guide.md
 * "Contact". A scene without pairs does no contact search at all.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <set>
#include <string>
#include <vector>

namespace pneuma
{
  class InputLayout;

  namespace contact
  {
    using namespace dealii;

    /// Largest number of contact pairs a parameter file can declare.
    constexpr unsigned int max_pairs = 16;

    /**
     * One contact pair, "Contact/Pair k". The members bound to an entry
     * (marked "entry") hold its default; the others are derived from the
     * entries by ContactParameters::parse_parameters().
     */
    struct ContactPair
    {
      /// "Contact/Pair k", for messages.
      std::string path;
      /// Cable index (0-based), from "Cable".
      unsigned int cable;
      /// The membrane regions of the master (empty: all), from "Membrane
      /// regions".
      std::set<types::material_id> regions;
      /// Entry "Side": true if the cable is on the side the outward normal
      /// points to.
      bool outside = true;
      /// Entry "Radius": cable radius R in the gap [m] (0: the cable's
      /// larger semi-axis).
      double radius = 0.;
      /// Entry "Penalty": eps_N [N/m^2], line load per penetration.
      double penalty = 1e6;
      /// Entries "Integration" (Gauss or Lobatto points) and "Points per
      /// element", along each cable element.
      bool         lobatto            = false;
      unsigned int points_per_element = 2;
      /// Entry "Search distance": extra distance for the candidate search
      /// [m] (0: R + one cable element length).
      double search_distance = 0.;
      /// Entry "Maximum motion per step": a converged step in which a point
      /// near the master moved relative to it by more than this fraction
      /// of the search distance is cut back (0: no limit).
      double max_motion = 0.5;
      /// Entries "Friction coefficient" mu and "Tangential penalty" eps_T
      /// [N/m^2]; a tangential penalty of 0 in the input is eps_N.
      double friction = 0., tangential_penalty = 0.;
      /// Entry "Master normal": true (smoothed) for the normal field
      /// interpolated from nodal-averaged normals, continuous across cell
      /// edges; false (facet) for each cell's own normal.
      bool smoothed_normal = false;
      /// Entry "Smoothed normal from": with a smoothed master normal, the
      /// pseudo time after which it is used; the steps up to it use the
      /// facet normal (0: smoothed from the start).
      double smoothed_from = 0.;
    };

    /// The "Contact" subsection.
    class ContactParameters
    {
    public:
      /// "Contact/Number of pairs" alone (it decides whether the subsystem
      /// exists).
      static void
      declare_count(ParameterHandler &prm);
      /// The pairs 1..N the layout names, bound to this object (which must
      /// outlive the parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      /// @p n_cables: cables declared, to check the pair's cable.
      void
      parse_parameters(ParameterHandler &prm, const unsigned int n_cables);

      bool
      empty() const
      {
        return pairs.empty();
      }
      const std::vector<ContactPair> &
      all() const
      {
        return pairs;
      }

    private:
      std::vector<ContactPair> pairs;
      /// The entries of a pair kept as given until they are checked.
      struct Text
      {
        unsigned int cable = 1;
        std::string  regions;
      };
      std::vector<Text> text;
    };
  } // namespace contact
} // namespace pneuma
