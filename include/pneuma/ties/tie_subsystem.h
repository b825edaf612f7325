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

#include <map>
#include <set>
#include <utility>
#include <vector>

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

      /// Make the dofs of the constraint lines relevant: the tied cable
      /// dofs and the membrane dofs they follow (the lines are found
      /// first, by find_constraint_lines()).
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
                     const LA::Vector &field,
                     const double      t) const override;

    private:
      /// One constrained cable dof: value = sum of weight x membrane dof.
      struct Line
      {
        types::global_dof_index dof;
        Combination             entries;
      };

      /// A tied cable node: its tie, its dofs (the translations, then those
      /// of the section vectors), its reference position, the section
      /// vectors that follow the membrane and how far its membrane point
      /// may lie.
      struct TiedNode
      {
        unsigned int                         tie;
        std::vector<types::global_dof_index> dofs;
        Point<3>                             position;
        /// The reference section vectors a1, a2 (a solid beam that follows
        /// the membrane's surface; empty otherwise) and the node's
        /// components that carry them
        /// (CableElement::section_vector_components).
        std::vector<Tensor<1, 3>> sections;
        std::vector<unsigned int> section_slots;
        double                    reach;
      };

      /// Per tied node and slot: the number of cells that wrote the row,
      /// and the sum of their weights per membrane dof.
      using RowSums = std::vector<std::map<
        unsigned int,
        std::pair<unsigned int, std::map<types::global_dof_index, double>>>>;

      /// Search the membrane for the tied nodes, check what the ties ask
      /// for, and set #lines, #offsets and #tied_translations alike on
      /// every rank (collective).
      void
      find_constraint_lines();
      /// Throw an InputError if a tie names a membrane region that has no
      /// cells in the mesh.
      void
      check_regions() const;
      /// Every tied node, in the same order on every rank.
      std::vector<TiedNode>
      tied_nodes() const;
      /// The nearest membrane points of each node on this rank's cells
      /// into @p found; returns each node's distance from the nearest of
      /// them on any rank (collective).
      std::vector<double>
      search_membrane(const std::vector<TiedNode>             &nodes,
                      std::vector<std::vector<MembranePoint>> &found) const;
      /// Throw an InputError if a node lies farther than its reach from the
      /// membrane; record each tie's largest distance in #offsets.
      void
      check_distances(const std::vector<TiedNode> &nodes,
                      const std::vector<double>   &nearest);
      /// The interpolation rows of the nearest membrane points of every
      /// node, gathered from every rank and summed (collective).
      RowSums
      share_rows(const std::vector<TiedNode>                   &nodes,
                 const std::vector<std::vector<MembranePoint>> &found,
                 const std::vector<double>                     &nearest) const;
      /// Fill #lines with the mean of the summed rows; returns the tied
      /// dofs.
      std::set<types::global_dof_index>
      make_lines(const std::vector<TiedNode> &nodes, const RowSums &sums);
      /// Throw an InputError if a node is tied twice or a solid beam's
      /// section cannot follow the membrane (@p tied: the tied dofs); fill
      /// #tied_translations.
      void
      check_tied_nodes(const std::vector<TiedNode>             &nodes,
                       const std::set<types::global_dof_index> &tied);

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
