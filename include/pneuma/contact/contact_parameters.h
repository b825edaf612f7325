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

    /// One contact pair as given in the input.
    struct ContactPair
    {
      /// "Contact/Pair k", for messages.
      std::string path;
      /// Cable index (0-based) and the membrane regions of the master.
      unsigned int                 cable = 0;
      std::set<types::material_id> regions;
      /// True: the cable is on the side the outward normal points to.
      bool outside = true;
      /// Cable radius R in the gap [m] (0: the cable's larger semi-axis).
      double radius = 0.;
      /// Penalty eps_N [N/m^2]: line load per penetration.
      double penalty = 1e6;
      /// Integration along each cable element.
      bool         lobatto          = false;
      unsigned int points_per_element = 2;
      /// Extra distance for the candidate search [m] (0: R + one cable
      /// element length).
      double search_distance = 0.;
      /// Coulomb friction coefficient mu and tangential penalty eps_T
      /// [N/m^2] (0: eps_N).
      double friction = 0., tangential_penalty = 0.;
    };

    /// The "Contact" subsection.
    class ContactParameters
    {
    public:
      /// "Contact/Number of pairs" alone (it decides whether the subsystem exists).
      static void
      declare_count(ParameterHandler &prm);
      static void
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
    };
  } // namespace contact
} // namespace pneuma
