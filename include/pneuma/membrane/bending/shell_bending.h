#pragma once

/**
 * @file
 * Shells with bending on the membrane's surface: a Kirchhoff-Love bending
 * energy, displacement only, made conforming in the weak sense across the
 * cells' edges by a C0 interior penalty (deal.II step-47 on a curved
 * surface, geometrically exact for large rotations; doc/theory.md §21).
 * Regions with `Materials/Region k/Bending = shell` get, on top of their
 * membrane law,
 * - in each cell the energy 1/2 kappa : D_b : kappa of the change of
 *   curvature (BendingCells, a membrane::CellTerms),
 * - on each edge between two such cells the consistency and penalty terms
 *   of the jump of the normal's rotation, and on clamped edges those of
 *   its rotation from the reference normal (BendingEdges, a
 *   membrane::FaceTerms),
 * with D_b = (t^3/12) dS/dE of the region's law at zero strain (any
 * membrane law: isotropic or orthotropic in its material frame) times the
 * region's Bending stiffness factor. Residual and tangent are the exact
 * derivatives of the energy (Sacado, bending/sacado_energy.h).
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <pneuma/membrane/cell_terms.h>
#include <pneuma/membrane/face_terms.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace dealii
{
  namespace Functions
  {
    template <int dim>
    class ParsedFunction;
  }
} // namespace dealii

namespace pneuma
{
  namespace membrane
  {
    class MembraneSubsystem;
    class MaterialRegions;

    namespace bending
    {
      using namespace dealii;

      /// The "Bending" subsection.
      struct Parameters
      {
        /// eta of the penalty gamma D / h (see gamma()).
        double penalty_factor = 2.;
        /// Edges whose normal keeps its reference direction about the
        /// edge (clamped edges and symmetry planes).
        std::set<types::boundary_id> clamped;
        /// Edges carrying the applied edge moment.
        std::set<types::boundary_id> moment_edges;
        /// The edge moment m(x, y, z, t) [N m/m] (shared by the copies).
        std::shared_ptr<Functions::ParsedFunction<3>> moment;

        /**
         * gamma for cells of degree @p p: 3 eta on Q2 (the default eta = 2
         * gives step-47's p (p + 1) = 6) and eta/2 on Q1 (1 by default:
         * the kink energy gamma D/(2h) delta^2 of a cylindrical bend
         * across the edges, delta = kappa h, is then its bending energy
         * D kappa^2/2 per area).
         */
        double
        gamma(const unsigned int p) const
        {
          return penalty_factor * (p == 1 ? 0.5 : 3.);
        }
        static void
        declare(ParameterHandler &prm);
        void
        parse(ParameterHandler &prm);
      };

      /// The bending stiffness of a region (material frame components)
      /// and its largest diagonal entry (the penalty's scale).
      struct RegionStiffness
      {
        double D[2][2][2][2];
        double largest = 0.;
      };

      /// What the cell and edge terms share.
      struct ShellContext
      {
        const MembraneSubsystem                      *membrane = nullptr;
        Parameters                                    parameters;
        std::map<types::material_id, RegionStiffness> stiffness;
        /// The region's stiffness, or null where it has no bending.
        const RegionStiffness *
        of(const types::material_id id) const
        {
          const auto it = stiffness.find(id);
          return it == stiffness.end() ? nullptr : &it->second;
        }
      };

      /// The stiffness of every region with bending.
      std::map<types::material_id, RegionStiffness>
      region_stiffness(const MaterialRegions &materials);

      /**
       * Input errors of the Bending edges: clamped or moment edges
       * without a shell region (@p has_shell), ids that are not among the
       * mesh's boundary ids @p ids, an edge moment that is not finite at
       * t = 0 at one of this rank's moment edge centres @p centres (every
       * rank throws alike).
       */
      void
      check_edges(const Parameters                      &parameters,
                  const bool                             has_shell,
                  const std::vector<types::boundary_id> &ids,
                  const std::vector<Point<3>>           &centres,
                  const MPI_Comm                         comm);

      class BendingCells;
      class BendingEdges;

      /// The bending of the membrane's shell regions: owns both terms.
      class ShellBending
      {
      public:
        ShellBending(const MembraneSubsystem &membrane,
                     const Parameters        &parameters);
        ~ShellBending();

        CellTerms &
        cell_terms();
        FaceTerms &
        face_terms();
        /// The bending energy of this rank's cells and edges at the last
        /// assembly with a residual or tangent.
        double
        energy() const;
        /**
         * The VTU cell fields at the ghosted @p field: per active cell
         * (zero off the owned shell cells) the principal changes of
         * curvature kappa_1 >= kappa_2 [1/m] and the principal bending
         * moments m_1 >= m_2 [N m/m] of the cell's mean curvature change.
         */
        void
        cell_fields(const LA::Vector                    &field,
                    std::vector<std::string>            &names,
                    std::vector<dealii::Vector<double>> &values) const;
        /// The unit tangents of this rank's clamped shell edges: a rigid
        /// rotation with a component along one of them turns a clamped
        /// normal, so the clamping holds it.
        std::vector<std::array<double, 3>>
        clamped_axes() const;
        /// Per clamped boundary, the moment its clamps exert on the
        /// structure at the last assembly, on this rank
        /// (BendingEdges::clamp_moments).
        const std::map<types::boundary_id, Tensor<1, 3>> &
        clamp_moments() const;
        /// One line: the regions with bending, their stiffness, the
        /// penalty chosen and the clamped edges.
        std::string
        description(const unsigned int degree) const;

      private:
        ShellContext                  context;
        std::unique_ptr<BendingCells> cells;
        std::unique_ptr<BendingEdges> edges;
      };
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
