#pragma once

/**
 * @file
 * Integrals over chamber walls: the energetically equivalent loads of the
 * fillings with their consistent stiffness, and the measures of each
 * chamber (doc/theory.md "Chambers"; source paper section 2, eqs. 1-6).
 *
 * With the current wall position x, area vector \f$a = a_1\times a_2\f$
 * per reference area and orientation s = +-1 (out of the chamber):
 * - volume \f$V = \frac13\int s\,x\cdot a\,dA\f$, its gradient
 *   \f$q_i = \int s\,a\cdot N_i\,dA\f$;
 * - with a liquid of density \f$\rho\f$ under gravity \f$g\f$
 *   (\f$\hat g = g/|g|\f$, height \f$z = -\hat g\cdot x\f$) and free-surface
 *   level h, the wetted part \f$z < h\f$ carries
 *   \f$p_\ell = \rho |g| (h - z)\f$; liquid volume
 *   \f$V_\ell = \int_{wet} s\,(h - z)\,\hat g\cdot a\,dA\f$,
 *   \f$\partial V_\ell/\partial u = q_\ell = \int_{wet} s\,a\, N\,dA\f$,
 *   \f$\partial V_\ell/\partial h = A_{fs} = \int_{wet} s\,\hat g\cdot a\,dA\f$
 *   (the free-surface area);
 * - a gas (gauge) pressure \f$p_g\f$ acts on all walls.
 * The load \f$f_i = \int s\,(p_g + p_\ell)\,a\cdot N_i\,dA\f$ has the
 * stiffness \f$\partial f/\partial u\f$: the follower term
 * \f$s\,p\,N_i\,\partial a/\partial u_j\f$ and the hydrostatic gradient
 * term \f$s\,N_i\,a\,(\rho g\cdot N_j)\f$. There are no line terms at the
 * free surface because \f$p_\ell\f$ vanishes there.
 */

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/chambers/chamber_parameters.h>
#include <pneuma/chambers/free_surface_quadrature.h>
#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/local_access.h>
#include <pneuma/geometry/scene_generator.h>

#include <Epetra_BlockMap.h>

#include <array>
#include <cstdint>
#include <memory>
#include <pneuma/membrane/cell_terms.h>
#include <pneuma/membrane/reference_geometry.h>

#include <functional>
#include <map>
#include <vector>

namespace pneuma
{
  namespace chambers
  {
    using namespace dealii;

    /// What acts on the walls of one chamber.
    struct ChamberLoad
    {
      bool gas = true;          ///< a gas acts (else the gas pass is
                                ///< skipped when only loads are needed)
      double gas_pressure = 0.; ///< gauge [Pa], on all walls
      bool   liquid       = false;
      double level        = 0.; ///< free-surface height h [m]
      double density      = 0.;
    };

    /// Measures of one chamber at the current state.
    struct ChamberMeasures
    {
      double volume = 0., liquid_volume = 0., free_surface_area = 0.,
             wetted_area = 0., wall_area = 0.;
      /// dV/du and dV_l/du (condensed by the constraints), if requested.
      LA::Vector q, q_liquid;
    };

    /// Per-cell values for output.
    struct ChamberCellData
    {
      Vector<float> chamber, wetted, pressure;
    };

    class ChamberAssembler
    {
    public:
      ChamberAssembler(const geometry::SceneGenerator &geometry,
                       const ChamberParameters        &parameters);

      /// Set the discretisation; walls are looked up by material id and
      /// integrated on the membrane kernel's reference data (@p reference
      /// gives those of the current mesh).
      void
      reinit(const Mapping<2, 3>                                 &mapping,
             const DoFHandler<2, 3>                              &dof_handler,
             const unsigned int                                   degree,
             std::function<const membrane::ReferenceGeometry &()> reference);

      /**
       * Check every chamber before any work: its regions exist, and its
       * oriented walls close (the area vectors sum to zero; for an open
       * tank, their part normal to gravity, and the rest points down
       * along gravity or vanishes). Throws InputError naming the chamber
       * and the gap. Records which chambers are closed along gravity.
       */
      void
      check_chambers();

      /**
       * Whether the walls of chamber @p c close it along gravity (set by
       * check_chambers()): every closed chamber, and an open one that
       * lacks only walls parallel to gravity on all sides, such as a slice
       * of a long tube between two vertical cuts (plane strain) or a body
       * cut by vertical symmetry planes. Such a chamber holds a finite
       * volume; a level above its top fills it and presses it by the
       * head. False for a tank open at its top.
       */
      bool
      closed_along_gravity(const unsigned int c) const
      {
        return c < closed_vertically.size() && closed_vertically[c];
      }

      /**
       * At the ghosted displacement @p u: subtract the loads @p loads from
       * @p residual and their stiffness from @p tangent (either may be
       * nullptr), and fill @p measures (vectors only if @p with_vectors).
       */
      void
      assemble(const LA::Vector                &u,
               const AffineConstraints<double> &constraints,
               const std::vector<ChamberLoad>  &loads,
               LA::Vector                      *residual,
               LA::SparseMatrix                *tangent,
               std::vector<ChamberMeasures>    &measures,
               const bool                       with_vectors) const;

    private:
      struct SurfaceHeights;

    public:
      /**
       * One pass over the cells, for callers that loop themselves (the
       * membrane assembler adds these terms to its cell matrices, so that
       * each cell is distributed once): construct, call cell() for every
       * locally owned cell, then finish(). A loop on several threads calls
       * compute() (concurrently, one Scratch per thread) and then commit()
       * for each cell in cell order instead of cell().
       */
      class Pass
      {
      public:
        /// One thread's working memory.
        struct Scratch : membrane::CellTerms::Scratch
        {
          explicit Scratch(const ChamberAssembler &assembler);
          /// The free-surface data of a liquid's walls.
          struct Liquid
          {
            explicit Liquid(const ChamberAssembler &assembler);
            FreeSurfaceQuadrature free_surface;
            std::vector<double>   psi;
          };
          /// The free-surface data, made on first use (a gas alone needs
          /// none: building it was 4 % of an explicit step).
          Liquid &
          liquid();

        private:
          const ChamberAssembler &assembler;
          std::unique_ptr<Liquid> liquid_data;
        };
        /// One wall of one cell: its chamber, its part of the measures and
        /// of dV/du (and dV_l/du).
        struct Wall
        {
          unsigned int chamber = 0;
          double volume = 0., area = 0., liquid_volume = 0., free_surface = 0.,
                 wetted = 0.;
          Vector<double> q, q_liquid;
          bool           has_q_liquid = false;
        };
        /// What compute() leaves of one cell for commit().
        struct Record : membrane::CellTerms::Record
        {
          unsigned int      n_walls = 0;
          std::vector<Wall> walls;
        };

        Pass(const ChamberAssembler          &assembler,
             const LA::Vector                &u,
             const AffineConstraints<double> &constraints,
             const std::vector<ChamberLoad>  &loads,
             std::vector<ChamberMeasures>    &measures,
             const bool                       with_vectors);
        /// Add -f to @p cell_residual and -df/du to @p cell_matrix (either
        /// may be nullptr) and accumulate the measures: compute() and
        /// commit() on this pass's own scratch.
        void
        cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
             const unsigned int                            cell_index,
             const std::vector<double>                    &local_u,
             FullMatrix<double>                           *cell_matrix,
             Vector<double>                               *cell_residual,
             const std::vector<types::global_dof_index>   &dof_indices);
        /// The terms of the cell with @p cell_index in @p reference into
        /// @p cell_matrix and @p cell_residual and its measures into
        /// @p record. May run on several threads at once.
        void
        compute(const DoFHandler<2, 3>::active_cell_iterator &cell,
                const membrane::ReferenceGeometry            &reference,
                const unsigned int                            cell_index,
                const std::vector<double>                    &local_u,
                FullMatrix<double>                           *cell_matrix,
                Vector<double>                               *cell_residual,
                Scratch                                      &scratch,
                Record                                       &record) const;
        /// Add the @p record of the cell with @p dof_indices to the
        /// measures.
        void
        commit(const Record                               &record,
               const std::vector<types::global_dof_index> &dof_indices);
        /// Sum the measures over the ranks, compress the vectors.
        void
        finish();

      private:
        const ChamberAssembler          &assembler;
        const LA::Vector                &u;
        const AffineConstraints<double> &constraints;
        const std::vector<ChamberLoad>  &loads;
        std::vector<ChamberMeasures>    &measures;
        const bool                       with_vectors;
        Scratch                          own_scratch;
        Record                           own_record;
        /// The walls' heights at u (with a liquid).
        const SurfaceHeights *heights = nullptr;
        /// The owned values of each chamber's q and q_liquid.
        std::vector<LA::OwnedValues> q_owned, q_liquid_owned;

        /// Add a wall's cell vector @p q to @p target (owned values
        /// @p owned) through the constraints, or by local index if none
        /// of its dofs is constrained and all are owned here.
        void
        add(const Vector<double>                       &q,
            const std::vector<types::global_dof_index> &dof_indices,
            const LA::OwnedValues                      &owned,
            LA::Vector                                 &target) const;
      };

      /// Liquid volume below @p level in chamber @p c and its derivative
      /// (the free-surface area) at the ghosted displacement @p u.
      std::pair<double, double>
      liquid_volume(const LA::Vector  &u,
                    const unsigned int c,
                    const double       level) const;

      /// A number that identifies the state @p u among those the wall
      /// heights were found for (the same number for the same values on
      /// this rank; a new one for other values).
      std::uint64_t
      state(const LA::Vector &u) const
      {
        return heights(u).serial;
      }

      /// The mesh's communicator.
      MPI_Comm
      communicator() const
      {
        return dof_handler->get_communicator();
      }

      /// Lowest and highest wall height z = -g.x / |g| of chamber @p c.
      std::pair<double, double>
      height_range(const LA::Vector &u, const unsigned int c) const;

      /// Cell data for output (chamber number, wetted fraction, net
      /// pressure at the centre) at the ghosted displacement @p u.
      ChamberCellData
      cell_data(const LA::Vector               &u,
                const std::vector<ChamberLoad> &loads) const;

      /// Height of a current position above the level origin.
      double
      height(const Point<3> &x) const
      {
        return -(unit_gravity * x);
      }

    private:
      /// Per chamber: closed_along_gravity().
      std::vector<bool> closed_vertically;
      struct WallSums;
      /// The walls' sums over this rank's cells (check_chambers()).
      WallSums
      wall_sums() const;
      /// The message for chamber @p c whose walls leave @p gap open.
      std::string
      closure_error(const unsigned int  c,
                    const Tensor<1, 3> &gap,
                    const double        total,
                    const WallSums     &sums) const;
      /// Chambers (and orientation) a cell of material @p id belongs to.
      const std::vector<std::pair<unsigned int, int>> &
      walls_of(const types::material_id id) const;

      const geometry::SceneGenerator &geometry;
      const ChamberParameters        &parameters;
      const Mapping<2, 3>            *mapping     = nullptr;
      const DoFHandler<2, 3>         *dof_handler = nullptr;
      unsigned int                    degree      = 1;
      std::function<const membrane::ReferenceGeometry &()> reference;
      Tensor<1, 3>                                         unit_gravity;
      double gravity_magnitude = 0.;
      std::map<types::material_id, std::vector<std::pair<unsigned int, int>>>
        membership;

      /**
       * The measures of the last pass that asked for measures alone, and
       * the state and free-surface levels it was made at: an explicit step
       * asks for them twice at one state (the border of the step, the
       * record at its end), each a pass over all walls.
       */
      struct MeasureCache
      {
        LA::VectorSnapshot                   u;
        std::vector<std::pair<bool, double>> levels;
        std::vector<std::array<double, 5>>   measures;
      };
      mutable MeasureCache measure_cache;
      /// The local index of every wall dof in the ghosted field (a pass
      /// of its own reads u by it, as the membrane kernel does).
      mutable LA::GhostedIndices ghosted_indices;

      /**
       * The heights of the walls of liquid chambers at one state, per
       * owned cell (in the reference data's order): at the free surface's
       * support points (to classify a cell) and at the nodes (the height
       * range). The level search evaluates the liquid volume at several
       * levels for one state, and each evaluation mapped every wall's
       * support points anew (most of an explicit step with a liquid).
       */
      struct SurfaceHeights
      {
        LA::VectorSnapshot u;
        /// Per owned cell: its first entry, or -1 (not a liquid's wall).
        std::vector<int>    first;
        std::vector<double> support, nodes;
        unsigned int        n_support = 0, n_nodes = 0;
        /// The reference positions of the nodes (as nodes).
        std::vector<Point<3>> positions;
        /// Which of the states found since the start this is.
        std::uint64_t serial = 0;

        /// The reference node positions of owned cell @p k (a liquid's
        /// wall).
        const Point<3> *
        cell_nodes(const unsigned int k) const
        {
          return &positions[std::size_t(first[k]) * n_nodes];
        }
      };
      mutable SurfaceHeights surface_heights;
      /// The number of states the heights were found for.
      mutable std::uint64_t n_height_states = 0;

      /// The heights at @p u (found anew if @p u is not the last state).
      const SurfaceHeights &
      heights(const LA::Vector &u) const;

      /// The measures of a pass for measures alone from the cache, if it
      /// holds those of @p u and @p loads (see cached()).
      bool
      from_cache(const LA::Vector               &u,
                 const std::vector<ChamberLoad> &loads,
                 std::vector<ChamberMeasures>   &measures) const;

      /// Are @p u and the levels of @p loads those of the cache (on every
      /// rank)?
      bool
      cached(const LA::Vector &u, const std::vector<ChamberLoad> &loads) const;

      /// Keep @p measures made at @p u and @p loads.
      void
      store(const LA::Vector                   &u,
            const std::vector<ChamberLoad>     &loads,
            const std::vector<ChamberMeasures> &measures) const;
    };
  } // namespace chambers
} // namespace pneuma
