#pragma once

/**
 * @file
 * The "Surface contact" subsection: membrane regions that bear on each
 * other (the hulls of two chambers, a wall and a divider) or on themselves
 * (a crushed chamber folding onto itself), doc/user-guide.md "Surface
 * contact". A scene without pairs builds nothing of it.
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

    /// Largest number of pairs a parameter file can declare.
    constexpr unsigned int max_surface_pairs = 16;

    /// One pair, "Surface contact/Pair k".
    struct SurfacePair
    {
      /// "Surface contact/Pair k", for messages.
      std::string path;
      /// "Regions": the first side (empty: every membrane region).
      std::set<types::material_id> first;
      /// "Opposite regions": the second side; empty: self-contact, every
      /// cell of the first side against every other cell of it.
      std::set<types::material_id> second;
      /// "Penalty" [Pa/m]; 0: derived per slave cell (Penalty factor).
      double penalty = 0.;
      /// "Penalty factor" f of the derived penalty f E t / h^2.
      double penalty_factor = 10.;
      /// "Search distance" [m]; 0: the largest cell size of the pair.
      double search_distance = 0.;

      bool
      self() const
      {
        return second.empty();
      }
      /// Is region @p id on the first (second) side?
      bool
      on_first(const types::material_id id) const
      {
        return first.empty() || first.count(id) > 0;
      }
      bool
      on_second(const types::material_id id) const
      {
        return second.count(id) > 0;
      }
    };

    /// The "Surface contact" subsection.
    class SurfaceParameters
    {
    public:
      /// "Surface contact/Number of pairs" alone (it decides whether the
      /// subsystem exists).
      static void
      declare_count(ParameterHandler &prm);
      /// The pairs @p layout names.
      void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      /// Check the entries, naming them.
      void
      parse_parameters(ParameterHandler &prm);

      std::vector<SurfacePair> pairs;

    private:
      /// Region lists read as text (bound members: sized once in
      /// declare_parameters).
      std::vector<std::string> first_text, second_text;
    };
  } // namespace contact
} // namespace pneuma
