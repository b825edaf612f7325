#pragma once

/**
 * @file
 * The "Obstacles" subsection: rigid obstacles the membrane touches (the
 * ground, loading plates, indenters, rollers), doc/user-guide.md
 * "Obstacles". A scene without obstacles builds nothing of them.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/types.h>

#include <pneuma/contact/obstacles/obstacle_shape.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace pneuma
{
  class InputLayout;

  namespace contact
  {
    using namespace dealii;

    /// Largest number of obstacles a parameter file can declare.
    constexpr unsigned int max_obstacles = 16;

    /// One obstacle, "Obstacles/Obstacle k".
    struct ObstacleDefinition
    {
      /// "Obstacles/Obstacle k", for messages.
      std::string path;
      /// The surface, from "Shape" and its subsection.
      std::string                    shape_name;
      std::unique_ptr<ObstacleShape> shape;
      /// The membrane regions it touches (empty: all), from "Regions".
      std::set<types::material_id> regions;
      /// Entry "Penalty" [Pa/m]: contact pressure per penetration; 0
      /// derives it per cell from the membrane (Penalty factor).
      double penalty = 0.;
      /// Entry "Penalty factor" f of the derived penalty f E t / h^2.
      double penalty_factor = 10.;
      /// Entry "Friction coefficient" mu (0: frictionless).
      double friction = 0.;
      /// Entry "Tangential penalty" [Pa/m] (0: the normal penalty).
      double tangential_penalty = 0.;
      /// "Displacement": the obstacle's rigid translation d(t) [m].
      std::unique_ptr<Functions::ParsedFunction<3>> displacement;
      /// "Control = force": the obstacle also moves by an unknown s along
      /// "Force direction" e (unit), such that the membrane's contact
      /// force on it balances "Force" F(t) along e.
      bool force_controlled = false;
      /// "Force": F(t) [N], pushing the obstacle along e.
      std::unique_ptr<Functions::ParsedFunction<3>> force;
      /// "Force direction" e.
      Tensor<1, 3> force_direction;

      /// Does the obstacle touch the region @p id?
      bool
      touches(const types::material_id id) const
      {
        return regions.empty() || regions.count(id) > 0;
      }
    };

    /// The "Obstacles" subsection.
    class ObstacleParameters
    {
    public:
      /// "Obstacles/Number of obstacles" alone (it decides whether the
      /// subsystem exists).
      static void
      declare_count(ParameterHandler &prm);
      /// The obstacles @p layout names, with every shape's constants.
      void
      declare_parameters(ParameterHandler &prm, const InputLayout &layout);
      /// Check the entries, naming them; select each obstacle's shape.
      void
      parse_parameters(ParameterHandler &prm);

      std::vector<ObstacleDefinition> obstacles;

    private:
      /// Entries read as text, and one instance of every shape, per
      /// obstacle (bound members: sized once in declare_parameters).
      struct Text
      {
        std::string regions;
        std::string shape   = "plane";
        std::string control = "displacement", direction = "0, 0, -1";
        std::map<std::string, std::unique_ptr<ObstacleShape>> shapes;
      };
      std::vector<Text> text;
    };
  } // namespace contact
} // namespace pneuma
