#pragma once

/**
 * @file
 * Ties as a subsystem of the coupled model (core/subsystem.h): cable and
 * beam nodes that follow a material point of the membrane, as kinematic
 * constraints u_node = sum_i N_i(xi) u_i (AffineConstraints), exact for
 * any motion of the point (doc/theory.md §15). A node on a rigid end plate
 * follows the plate's master nodes through the plate's own constraints
 * (the chain is resolved by AffineConstraints::close()). Present only when
 * "Ties/Number of ties" is positive; it has no unknowns and no terms of
 * its own: the cable's forces at a tied node are condensed into the
 * membrane rows.
 */

#include <deal.II/base/index_set.h>

#include <pneuma/cables/cable_subsystem.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/ties/membrane_point.h>
#include <pneuma/ties/tie_parameters.h>

namespace pneuma
{
  namespace ties
  {
    /// The tie subsystem.
    class TieSubsystem : public Subsystem, public Holds
    {
    public:
      explicit TieSubsystem(Model &model);

      /// "Ties/Number of ties".
      static void
      declare_switches(ParameterHandler &prm);
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "ties";
      }
      /// The membrane may be held by the supported cables tied to it.
      bool
      holds(const Subsystem &other) const override;
      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;

      /// Find the membrane point of every tied node (its owner), share the
      /// constraint lines with every rank, and make their dofs relevant.
      void
      add_locally_relevant(IndexSet &relevant) override;
      void
      add_kinematic_constraints(AffineConstraints<double> &c) const override;
      void
      add_update_constraints(AffineConstraints<double> &c) const override;

      /// No terms of its own: the constraints carry the coupling.
      void
      assemble(const Assembly &) override
      {
      }

      /// Per tie: the force it exerts on the cable (sum over its nodes) and
      /// the largest distance of a node from its membrane point.
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field) const override;

    private:
      /// One constrained cable dof: value = sum of weight x membrane dof.
      struct Line
      {
        types::global_dof_index dof;
        Combination             entries;
      };

      Model                       &model;
      membrane::MembraneSubsystem &membrane;
      cables::CableSubsystem      &cables;
      TieParameters                parameters;
      /// The constraint lines of every tied dof (the same on every rank).
      std::vector<Line> lines;
      /// The membrane dofs the lines refer to.
      IndexSet membrane_dofs;
      /// Per tie: the tied translation dofs, and the largest distance of a
      /// node from the membrane.
      std::vector<std::vector<types::global_dof_index>> tied_translations;
      std::vector<double>                               offsets;
    };
  } // namespace ties
} // namespace pneuma
