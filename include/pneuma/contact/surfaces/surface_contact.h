#pragma once

/**
 * @file
 * Membrane-to-membrane penalty contact at the membrane's quadrature points
 * (doc/theory.md "Membrane-to-membrane contact").
 *
 * Every quadrature point x of a slave cell (the lattice patch of its
 * current node positions, contact/contact_point.h) is projected onto the
 * cells of the other side (two-pass: each side is slave once; for
 * self-contact a region's points against its own cells that share no
 * vertex with the point's cell). The nearest projection inside a cell
 * wins; with the normal n of that cell turned to the side the point was on
 * at the start of the load step, the gap is
 * \f[ g = (x - \rho(\xi^*))\cdot n - (t_s + t_m)/2 \f]
 * (the half thicknesses of both membranes as the offset), and for g < 0
 * the penalty energy \f$\tfrac12\epsilon g^2 w\f$ (w the point's reference
 * area weight) adds its exact gradient and Hessian (penalty_terms of the
 * cable contact's point kernel, the slave chained to its cell's nodes by
 * the patch's shape functions). The default penalty is that of the
 * obstacles (contact/derived_penalty.h) of the slave's cell.
 *
 * Parallel: the cells of every pair's regions, with their dofs and
 * reference nodes, are known on every rank (ordered by their reference
 * centroids, so the order does not depend on the partition), and their
 * dofs are ghosts of every rank; each rank takes the points of its owned
 * cells, so a pair across a partition boundary is found like any other.
 * Candidates are the cells whose current boxes come within the offset
 * plus the search distance of the slave cell's box at the start of a step
 * (by default four times the largest motion of the pair's nodes in the
 * step before, at least twice the thickness, at most a cell's size);
 * the sparsity pattern grows when new couplings appear. A converged state
 * in which a point penetrates a cell that was not its candidate is not
 * accepted (the step is cut back).
 */

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <pneuma/contact/contact_point.h>
#include <pneuma/contact/surfaces/surface_parameters.h>
#include <pneuma/core/linear_algebra.h>
#include <pneuma/membrane/constitutive_law.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace pneuma
{
  namespace contact
  {
    /// What a pair reports at a state (the same on every rank).
    struct SurfaceReport
    {
      /// Points in contact (both sides), points tested.
      unsigned int active_points = 0, points = 0;
      /// Sum of the normal contact forces of the points [N].
      double total_force = 0.;
      /// Force on the first side [N] (self-contact: the forces on the
      /// points, about zero).
      Tensor<1, 3> force;
      /// Contact area: half the current area of the points in contact
      /// (each side's points count the interface once) [m^2].
      double area = 0.;
      /// Largest penetration -g [m] and the penalty energy [J].
      double penetration = 0., energy = 0.;
    };

    /// What an assembly finds besides the terms.
    struct SurfaceRecord
    {
      std::vector<SurfaceReport> reports;
      /// Per surface cell: the normal contact force on it (as slave and as
      /// master) [N], its current area [m^2] and the smallest gap of its
      /// points (all summed or reduced over the ranks).
      std::vector<double> cell_force, cell_area, cell_gap;
    };

    /// The membrane-to-membrane contact of a scene.
    class SurfaceContact
    {
    public:
      SurfaceContact(const std::vector<SurfacePair>  &pairs,
                     const membrane::MaterialRegions &materials);

      /// Gather the pairs' cells (every rank) and the points of the owned
      /// ones.
      void
      setup(const Mapping<2, 3>    &mapping,
            const DoFHandler<2, 3> &dof_handler,
            const MPI_Comm          comm);

      /// The dofs of every cell of the pairs' regions (ghosts everywhere).
      IndexSet
      relevant_dofs(const types::global_dof_index size) const;

      /// Regions of a pair that have no cell (for the message).
      std::vector<types::material_id>
      missing_regions(const unsigned int k) const;

      /// Accept the state @p u (ghosted; nullptr: the reference
      /// configuration): the sides of the next candidates are those of
      /// its points.
      void
      commit(const LA::Vector *u);

      /**
       * Renew the candidates at @p u (ghosted; nullptr: the reference
       * configuration), a prediction of the step's end or an accepted
       * state, and the side of every point to each of them in the state
       * last committed. Returns true on every rank if couplings outside
       * the current sparsity pattern appeared.
       */
      bool
      update_candidates(const LA::Vector *u);

      /// Couplings of all candidates seen so far.
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const;

      /// Add the penalty forces (to r = f_int - f_ext) and their tangent
      /// at @p u (ghosted), either may be nullptr; fill @p record if given.
      void
      assemble(const LA::Vector                &u,
               const AffineConstraints<double> &constraints,
               LA::SparseMatrix                *tangent,
               LA::Vector                      *residual,
               SurfaceRecord                   *record) const;

      /**
       * Why the converged state @p u is not admissible: a point penetrates
       * a cell that was not its candidate in the step (@p start: at the
       * start of the run, any penetration beyond 1 % of the offset; the
       * membranes overlap). Empty if none; the same on every rank.
       */
      std::string
      check(const LA::Vector &u, const bool start) const;

      /// The smallest and largest penalty of pair @p k (over the ranks).
      std::pair<double, double>
      penalty_range(const unsigned int k) const;
      /// The search distance of pair @p k (the current one: by default
      /// it follows the motion of the steps, commit()).
      double
      search_distance(const unsigned int k) const
      {
        return pairs[k].search;
      }
      /// Number of pairs.
      unsigned int
      size() const
      {
        return pairs.size();
      }
      /// The surface cell of each active cell by active cell index (-1:
      /// not owned, or in no pair).
      const std::vector<int> &
      surface_cell_of_active() const
      {
        return cell_of_active;
      }
      /// The cell pairs of pair @p k left out as part of a seam
      /// (find_seams()).
      unsigned int
      seam_pairs(const unsigned int k) const
      {
        return seam_counts[k];
      }

    private:
      /// A cell of a pair's regions, known on every rank.
      struct Cell
      {
        std::vector<types::global_dof_index> dofs;
        std::vector<Tensor<1, 3>>            reference;
        types::material_id                   material = 0;
        /// Reference area weight of each Gauss point, their sum, and half
        /// the region's thickness.
        std::vector<double> weights;
        double              area = 0., half_thickness = 0.;
        int                 owner = 0;
      };
      /// One side's slaves of a pair: owned cells, their candidate cells
      /// and per point and candidate the side (+-1) it was on.
      struct Side
      {
        std::vector<unsigned int>              slaves;
        std::vector<char>                      opposite;
        std::vector<std::vector<unsigned int>> candidates;
        /// Per point and candidate (q * candidates + j): +-1, or 0 until
        /// first needed (side_of()).
        mutable std::vector<std::vector<signed char>> orientation;
      };
      struct PairData
      {
        std::vector<Side> sides;
        /// The search distance of the next candidates, and the largest
        /// cell size (box diagonal) of the pair's regions.
        double search = 0., largest = 0.;
      };
      /// A point in contact at an assembly, and its terms.
      struct Active
      {
        unsigned int       pair, side, slave, q, master;
        Point<2>           xi;
        double             gap, offset, penalty, weight;
        signed char        orientation;
        Vector<double>     gradient;
        FullMatrix<double> hessian;
      };

      /// The cells of all pairs' regions from every rank (cells,
      /// cell_of_active, thickest).
      void
      gather_cells(const Mapping<2, 3>    &mapping,
                   const DoFHandler<2, 3> &dof_handler);
      /// The sides, slaves and search distance of every pair.
      void
      make_sides();
      /**
       * Where two regions meet at a seam at a small angle (a tube sewn
       * onto another, meeting it tangentially), the cells next to the seam
       * are closer than their half thicknesses in the reference state,
       * and the finer the mesh, the more rows of them. A cell pair that
       * starts that close is left out of each other's contact, like the
       * cells that share a seam vertex, if it is chained to the seam: the
       * pair's cells are next to (share a corner with, or are) the cells
       * of a pair that touches or was left out so. Overlapping cells
       * elsewhere (two membranes meshed into each other) stay overlapping
       * and check() refuses them. Sets seam and seam_counts.
       */
      void
      find_seams();
      /// Is (a, b) a cell pair left out by find_seams()?
      bool
      at_seam(const unsigned int a, const unsigned int b) const
      {
        return seam.count({std::min(a, b), std::max(a, b)}) > 0;
      }
      std::vector<MasterPatch>
      current_patches(const LA::Vector *u) const;
      bool
      touching(const unsigned int a, const unsigned int b) const;
      double
      offset(const unsigned int a, const unsigned int b) const;
      double
      cell_penalty(const unsigned int k, const unsigned int cell) const;
      /// The cells at a state: patches, boxes, and how far each cell's
      /// nodes moved since the last accepted state.
      struct State
      {
        std::vector<MasterPatch>                           patches;
        std::vector<std::pair<Tensor<1, 3>, Tensor<1, 3>>> boxes;
        std::vector<double>                                motion;
      };
      State
      current_state(const LA::Vector &u) const;
      /// The side (+-1) point @p q of slave @p i was on, in the last
      /// accepted state, of its candidate @p j.
      signed char
      side_of(const Side        &side,
              const unsigned int i,
              const unsigned int q,
              const unsigned int j) const;
      /// The nearest projection of the point @p x of slave @p i onto the
      /// candidates it may touch; returns the candidate's position in the
      /// list, or -1.
      int
      nearest(const Side         &side,
              const unsigned int  i,
              const Tensor<1, 3> &x,
              const State        &state,
              Projection         &projection) const;
      /// check() of point @p q of slave @p i of pair @p k.
      template <class Tree>
      std::string
      check_point(const unsigned int k,
                  const Side        &side,
                  const unsigned int i,
                  const unsigned int q,
                  const State       &state,
                  const Tree        &tree,
                  const bool         start) const;
      std::vector<Active>
      active_points(const State &state, SurfaceRecord *record) const;
      /// The points of slave @p i of side @p s of pair @p k in contact at
      /// @p state (with a record: their cell's smallest gap).
      std::vector<Active>
      slave_points(const unsigned int k,
                   const unsigned int s,
                   const unsigned int i,
                   const State       &state,
                   SurfaceRecord     *record) const;
      /// The reports and per-cell values of the points @p active (summed
      /// over the ranks).
      void
      add_record(const std::vector<Active>      &active,
                 const std::vector<MasterPatch> &patches,
                 SurfaceRecord                  &record) const;
      void
      add_terms(const Active                    &a,
                const AffineConstraints<double> &constraints,
                LA::SparseMatrix                *tangent,
                LA::Vector                      *residual) const;

      const std::vector<SurfacePair>  &parameters;
      const membrane::MaterialRegions &materials;
      MPI_Comm                         comm;
      unsigned int                     degree = 1;
      std::vector<Cell>                cells;
      /// The largest thickness of the pairs' regions (offsets are below).
      double           thickest = 0.;
      std::vector<int> cell_of_active;
      /// The points of a slave cell: unit coordinates, shape values and
      /// the unit weights.
      std::vector<Point<2>>            points;
      std::vector<std::vector<double>> shape;
      std::vector<double>              unit_weights;
      std::vector<PairData>            pairs;
      /// The cells' patches in the state last committed.
      std::vector<MasterPatch> converged;
      /// (slave cell, master cell) couplings in the sparsity pattern.
      std::set<std::pair<unsigned int, unsigned int>> coupled;
      /// Cell pairs (smaller index first) next to a seam, left out of the
      /// contact, and their number per pair.
      std::set<std::pair<unsigned int, unsigned int>> seam;
      std::vector<unsigned int>                       seam_counts;
    };
  } // namespace contact
} // namespace pneuma
