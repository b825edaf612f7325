#pragma once

/**
 * @file
 * What the membrane kernel needs of the reference surface, computed once
 * per mesh instead of by FEValues::reinit at every assembly (issue 17,
 * doc/theory.md §3 "Assembly kernel"): per locally owned cell its dof
 * indices and orientation, and per quadrature point the orthonormal
 * material frame (E_1, E_2) of the tangent plane, the derivatives
 * dN_a/dS_alpha of each node's scalar shape function along it, the
 * weight JxW and the point X. Shape values N_a(q) are the same on every
 * cell and are stored once.
 *
 * Memory for degree 1 (4 nodes, 4 points): 96 B of dof indices and
 * 4 x (10 + 8) doubles = 576 B per cell.
 */

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <pneuma/geometry/scene_generator.h>
#include <pneuma/membrane/assumed_strains.h>
#include <pneuma/membrane/constitutive_law.h>

#include <array>
#include <memory>
#include <vector>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    /// Most nodes per cell of a membrane element (Q2).
    constexpr unsigned int max_cell_nodes = 9;

    /// The dofs of a membrane element FE_Q^3 (degree 1 or 2) by node:
    /// result[a][c] is the cell dof of component c at node a, the node's
    /// scalar shape function being the base element's function a.
    std::array<std::array<unsigned int, 3>, max_cell_nodes>
    node_dofs(const FiniteElement<2, 3> &fe);

    /// Outward orientation (+1 or -1) of the cell of @p fe_values (reinit'ed
    /// with quadrature points and normal vectors).
    double
    cell_orientation(const geometry::SceneGenerator &geometry,
                     const FEValues<2, 3>           &fe_values);

    /// Whether the cells of @p material take assumed membrane strains
    /// with elements of @p degree (InputError: assumed asked of Q1).
    bool
    uses_assumed_strains(const RegionMaterial    &material,
                         const types::material_id id,
                         const unsigned int       degree);

    /// Reference data of the locally owned cells, in the order of
    /// DoFHandler::active_cell_iterators().
    class ReferenceGeometry
    {
    public:
      /// Quadrature data of one point.
      struct Point
      {
        /// The material frame E_1, E_2 (orthonormal, E_1 x E_2 the outward
        /// normal, E_1 along the region's warp where it has one).
        double E[2][3];
        double JxW;
        double X[3];
      };

      /// Compute it for the locally owned cells of @p dof_handler with the
      /// Gauss rule of degree + 1 points per direction.
      ReferenceGeometry(const geometry::SceneGenerator &geometry,
                        const MaterialRegions          &materials,
                        const Mapping<2, 3>            &mapping,
                        const DoFHandler<2, 3>         &dof_handler,
                        const unsigned int              degree);

      unsigned int
      n_cells() const
      {
        return n_owned;
      }
      unsigned int
      n_q_points() const
      {
        return n_q;
      }
      unsigned int
      n_nodes() const
      {
        return n_node;
      }
      /// The cell's dof indices.
      const types::global_dof_index *
      dof_indices(const unsigned int cell) const
      {
        return dofs.data() + std::size_t(cell) * 3 * n_node;
      }
      const Point &
      point(const unsigned int cell, const unsigned int q) const
      {
        return points[std::size_t(cell) * n_q + q];
      }
      /// dN_a/dS_alpha at point q of the cell: [a][alpha].
      const std::array<double, 2> *
      shape_derivatives(const unsigned int cell, const unsigned int q) const
      {
        return derivatives.data() + (std::size_t(cell) * n_q + q) * n_node;
      }
      /// N_a at point q (the same on every cell).
      const double *
      shape_values(const unsigned int q) const
      {
        return &values[q * n_node];
      }
      /// The tying geometry of a cell with assumed membrane strains, else
      /// nullptr.
      const TyingGeometry *
      tying(const unsigned int cell) const
      {
        return tying_of.empty() || tying_of[cell] < 0
                 ? nullptr
                 : &tying_cells[tying_of[cell]];
      }
      /// The assumed strains' rule (only where a cell has tying()).
      const AssumedStrains &
      assumed_strains() const
      {
        return *assumed;
      }
      /// Node a and component c of cell dof i (FESystem order).
      unsigned int
      node(const unsigned int i) const
      {
        return node_of[i];
      }
      unsigned int
      component(const unsigned int i) const
      {
        return component_of[i];
      }

    private:
      /// The assumed strains' rule if a region takes them, and an
      /// FEValues with the jacobians at its tying points (else nullptr).
      std::unique_ptr<FEValues<2, 3>>
      start_assumed_strains(const MaterialRegions     &materials,
                            const Mapping<2, 3>       &mapping,
                            const FiniteElement<2, 3> &fe,
                            const unsigned int         degree);
      /// The tying geometry of owned cell @p k from the FEValues at its
      /// Gauss and tying points (its frames already stored).
      void
      add_tying_cell(const unsigned int    k,
                     const FEValues<2, 3> &at_gauss,
                     const FEValues<2, 3> &at_tying);

      unsigned int                         n_owned = 0, n_q = 0, n_node = 0;
      std::vector<types::global_dof_index> dofs;
      std::vector<Point>                   points;
      std::vector<std::array<double, 2>>   derivatives;
      std::vector<double>                  values;
      std::vector<unsigned int>            node_of, component_of;
      std::unique_ptr<AssumedStrains>      assumed;
      std::vector<int>                     tying_of;
      std::vector<TyingGeometry>           tying_cells;
    };
  } // namespace membrane
} // namespace pneuma
