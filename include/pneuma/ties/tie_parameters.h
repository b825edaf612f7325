#pragma once

/**
 * @file
 * The "Ties" subsection: cable or beam nodes tied to the membrane (to a
 * point of its surface, to a rigid end plate, or node by node along a
 * membrane line), doc/user-guide.md "Ties", doc/theory.md §15. A scene
 * without ties builds none of this.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <set>
#include <string>
#include <vector>

namespace pneuma
{
  class InputLayout;

  namespace ties
  {
    using namespace dealii;

    /// Which nodes of the cable a tie holds.
    enum class TiedNodes
    {
      start,
      end,
      both_ends,
      all
    };

    /**
     * One tie, "Ties/Tie k". The members bound to an entry hold its
     * default; the others are derived by TieParameters::parse_parameters().
     */
    struct TieDefinition
    {
      /// "Ties/Tie k", for messages.
      std::string path;
      /// Cable index (0-based), from "Cable".
      unsigned int cable = 0;
      /// Entry "Nodes".
      TiedNodes nodes = TiedNodes::both_ends;
      /// The membrane regions the nodes are tied to (empty: all), from
      /// "Membrane regions".
      std::set<types::material_id> regions;
      /// Entry "Maximum distance": how far a node may lie from the
      /// membrane in the reference state [m] (0: the larger semi-axis of
      /// the cable's section).
      double max_distance = 0.;
      /// Entry "Section": a solid beam's section semi-axis vectors that lie
      /// in the membrane's tangent plane follow the membrane's deformation
      /// gradient (true), or the section is free (false).
      bool follow_section = true;
    };

    /// The "Ties" subsection: "Number of ties" and Tie 1..N.
    class TieParameters
    {
    public:
      /// "Ties/Number of ties" alone (it decides whether the subsystem
      /// exists).
      static void
      declare_count(ParameterHandler &prm);
      void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      /// Check the entries against the @p n_cables cables of the scene.
      void
      parse_parameters(ParameterHandler &prm, const unsigned int n_cables);

      const std::vector<TieDefinition> &
      all() const
      {
        return ties;
      }

    private:
      struct Text
      {
        unsigned int cable = 1;
        std::string  regions;
      };
      std::vector<TieDefinition> ties;
      std::vector<Text>          text;
    };
  } // namespace ties
} // namespace pneuma
