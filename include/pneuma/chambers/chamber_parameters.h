#pragma once

/**
 * @file
 * The "Chambers" subsection: which surface regions close each chamber and
 * with which orientation, and what fills it (doc/user-guide.md
 * "Chambers", doc/theory.md "Chambers").
 *
 * A chamber is a closed surface made of membrane and rigid regions. A wall
 * shared by two chambers (a divider) is listed by both, with opposite
 * orientation, and carries the pressure difference. An open chamber is a
 * tank: its listed regions are closed by rigid walls parallel to gravity,
 * which need no mesh. Chambers may be connected: a chamber with filling
 * "connected" shares the gas and/or liquid (one pressure, one level) of the
 * chamber it names.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>

#include <pneuma/chambers/gas_update.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pneuma
{
  class InputLayout;

  namespace chambers
  {
    using namespace dealii;

    /// What fills a chamber.
    enum class Filling
    {
      gas,
      liquid,
      liquid_and_gas,
      connected
    };

    /// How the gas of a chamber is controlled.
    enum class GasControl
    {
      /// Prescribed gauge pressure curve (optionally sealed at a time).
      pressure,
      /// Prescribed gas amount V_n/V_0 (volume at ambient pressure over the
      /// initial chamber volume); pressure from the gas law.
      amount,
      /// Prescribed volume V/V_0; the pressure is the Lagrange multiplier.
      volume
    };

    /// What prescribes a liquid filling ("Liquid/Control").
    enum class LiquidControl
    {
      /// The liquid volume follows "Liquid/Volume"; the level is its
      /// Lagrange multiplier.
      volume,
      /// The level (height of the free surface against gravity) follows
      /// "Liquid/Level"; the volume follows from it.
      level
    };

    /**
     * One chamber, "Chambers/Chamber k". The members bound to an entry
     * (marked "entry") hold its default; the others are derived from the
     * entries by ChamberParameters::parse_parameters().
     */
    struct ChamberDefinition
    {
      /// "Chambers/Chamber k", for messages.
      std::string path;
      /// Material ids of the walls with their orientation (+1: the cell's
      /// outward normal points out of the chamber, -1: into it); from
      /// "Regions".
      std::vector<std::pair<unsigned int, int>> regions;
      /// If set, walls are oriented by this interior point instead
      /// (convex chambers); from "Interior point".
      bool     use_interior_point;
      Point<3> interior_point;
      /// Entry "Open": a tank.
      bool open = false;

      /// Entry "Filling".
      Filling filling = Filling::gas;
      /// The chamber whose filling this one shares (0-based; itself unless
      /// connected); from "Connected to".
      unsigned int connected_to;
      /// Entries "Gas/Law", "Gas/Update" and the law's constants.
      GasUpdate gas_law;
      /// Entry "Gas/Control".
      GasControl control = GasControl::pressure;
      /// Entry "Gas/Seal time".
      double seal_time = -1.;
      /// Entry "Liquid/Density".
      double density = 1000.;
      /// Entry "Liquid/Control".
      LiquidControl liquid_control = LiquidControl::volume;
      std::unique_ptr<Functions::ParsedFunction<3>> pressure, amount, volume,
        liquid_volume, liquid_level;

      bool
      has_gas() const
      {
        return filling == Filling::gas || filling == Filling::liquid_and_gas;
      }
      bool
      has_liquid() const
      {
        return filling == Filling::liquid || filling == Filling::liquid_and_gas;
      }
    };

    /// The "Chambers" subsection.
    class ChamberParameters
    {
    public:
      static constexpr unsigned int max_chambers = 8;

      /// "Chambers/Number of chambers" alone (it decides whether the
      /// subsystem exists).
      static void
      declare_count(ParameterHandler &prm);
      /// Every other entry, for the chambers 1..N the layout names, bound
      /// to this object (which must outlive the parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      void
      parse_parameters(ParameterHandler &prm);

      /// Entry "Ambient pressure": absolute [Pa].
      double ambient_pressure = 101325.;
      /// Entry "Gravity": the acceleration acting on liquids [m/s^2].
      Tensor<1, 3> gravity = Tensor<1, 3>({0., 0., -9.81});
      /// Chambers 1..N (declared by declare_parameters()).
      std::vector<ChamberDefinition> chambers;

      bool
      empty() const
      {
        return chambers.empty();
      }

    private:
      /// The entries of a chamber kept as text until they are checked.
      struct Text
      {
        std::string  regions, interior_point;
        unsigned int connected_to = 0;
      };
      std::vector<Text> text;
    };
  } // namespace chambers
} // namespace pneuma
