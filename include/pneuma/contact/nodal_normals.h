#pragma once

/**
 * @file
 * Nodal-averaged normals of a contact master surface (doc/theory.md
 * §10.4), the continuous normal field of the smoothed curve-to-surface
 * contact.
 *
 * At a node a shared by the cells e of a contact pair's regions, the unit
 * normals of the cells at the node are averaged:
 * \f[ \bar n_a = \frac{S_a}{|S_a|},\qquad
 *     S_a = \sum_{e \ni a} \frac{c_e}{|c_e|},\qquad
 *     c_e = \sigma_e\, \rho^e_{,1} \times \rho^e_{,2}\,\big|_{\xi_a^e}, \f]
 * sigma_e turning each cell's normal to the contact side. At a lattice
 * node the tangents of a Lagrange cell involve only the nodes on the two
 * lattice lines through it, so nbar_a depends on the positions of the
 * nodes of those lines in every incident cell (5 nodes for Q1, 9 for Q2 at
 * a regular vertex). The contact terms take nbar as variables; the chain
 * rule needs d nbar_a / dY (jacobian(), by Sacado numbers over the node's
 * dependencies).
 *
 * Nodes are keyed by the global dof of their x component, so a node on a
 * partition boundary gets the same normal on every rank that sees its
 * cells (owned and ghost cells are given).
 */

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>

#include <pneuma/core/linear_algebra.h>

#include <map>
#include <vector>

namespace pneuma
{
  namespace contact
  {
    using namespace dealii;

    /// A cell that contributes to the nodal normals.
    struct NormalCell
    {
      /// Global dofs in lattice order, 3 per node.
      std::vector<types::global_dof_index> dofs;
      /// Reference node positions, lattice order.
      std::vector<Tensor<1, 3>> reference;
      /// +1 or -1: turns rho_1 x rho_2 to the contact side.
      double sign = 1.;
    };

    /// The nodal normals of one contact pair's master surface.
    class NodalNormals
    {
    public:
      /// Cells of degree @p degree (1 or 2) that share nodes by dof.
      void
      reinit(const unsigned int degree, const std::vector<NormalCell> &cells);

      bool
      empty() const
      {
        return nodes.empty();
      }

      /// Forget the cached values (the configuration changed).
      void
      clear_cache();

      /// The dofs nbar of node @p key depends on (3 per node).
      const std::vector<types::global_dof_index> &
      dependencies(const types::global_dof_index key) const;

      /// nbar of node @p key at @p u (ghosted), cached.
      const Tensor<1, 3> &
      normal(const types::global_dof_index key, const LA::Vector &u);

      /// d nbar / d dependencies(key), 3 x dependencies(key).size(), cached.
      const FullMatrix<double> &
      jacobian(const types::global_dof_index key, const LA::Vector &u);

    private:
      struct Node
      {
        /// Per incident cell: the sign and, for the nodes on the two
        /// lattice lines through this node, their index into the
        /// dependency nodes and their weights in rho_1 and rho_2.
        struct Incidence
        {
          double                    sign;
          std::vector<unsigned int> line1, line2;
          std::vector<double>       weight1, weight2;
        };
        std::vector<Incidence>               cells;
        std::vector<types::global_dof_index> dofs;
        std::vector<Tensor<1, 3>>            reference;
        bool               have_normal = false, have_jacobian = false;
        Tensor<1, 3>       value;
        FullMatrix<double> jacobian;
      };

      Node &
      find(const types::global_dof_index key);
      const Node &
      find(const types::global_dof_index key) const;

      std::map<types::global_dof_index, Node> nodes;
    };
  } // namespace contact
} // namespace pneuma
