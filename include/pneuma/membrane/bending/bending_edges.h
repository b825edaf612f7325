#pragma once

/**
 * @file
 * The interior-penalty terms of the shell regions on the cells' edges (a
 * membrane FaceTerms): on an edge between two shell cells the consistency
 * and penalty terms of the change delta of the kink (the angle between the
 * two cells' normals about the edge, against the reference's),
 *   e = {m_nunu} delta + 1/2 (gamma D / h) delta^2,
 * and on a clamped edge the same of the normal's rotation from its
 * reference direction, e = -m_nunu delta + 1/2 (gamma D / h) delta^2
 * (bending/kirchhoff_love.h), at degree + 1 Gauss points along the edge,
 * with gamma = eta p (p + 1), D the larger region's largest stiffness and h
 * the smaller cell's area over its edge's length. Edges with a cell
 * without bending are hinges. On edges with an applied moment m [N m/m]
 * the potential -m theta of the normal's turn theta about the edge.
 */

#include <pneuma/membrane/bending/shell_bending.h>

#include <map>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      /// The edges' interior-penalty terms.
      class BendingEdges : public FaceTerms
      {
      public:
        explicit BendingEdges(const ShellContext &context);

        unsigned int
        n_quadrature_points() const override;
        bool
        on_boundary_faces() const override
        {
          return !context.parameters.clamped.empty()
                 || !context.parameters.moment_edges.empty();
        }
        UpdateFlags
        update_flags() const override
        {
          return update_quadrature_points;
        }
        void
        begin(const Assembly &a) override;
        std::unique_ptr<FaceTerms::Scratch>
        new_scratch() const override;
        std::unique_ptr<FaceTerms::Record>
        new_record() const override;
        void
        interior_face(const FEInterfaceValues<2, 3> &fiv,
                      const std::vector<double>     &local_u,
                      FullMatrix<double>            *matrix,
                      Vector<double>                *residual,
                      FaceTerms::Scratch            &scratch,
                      FaceTerms::Record             &record) const override;
        void
        boundary_face(const DoFHandler<2, 3>::active_cell_iterator &cell,
                      const unsigned int                            face,
                      const FEFaceValues<2, 3>                     &fv,
                      const std::vector<double>                    &local_u,
                      FullMatrix<double>                           *matrix,
                      Vector<double>                               *residual,
                      FaceTerms::Scratch                           &scratch,
                      FaceTerms::Record &record) const override;
        void
        commit(const FaceTerms::Record &record) override;
        /// The edges' energy on this rank at the last assembly.
        double
        energy() const
        {
          return sum;
        }

        /// Compress the external forces of edge moments (after the face
        /// loop, on every rank alike).
        void
        end() override;

        /**
         * Per clamped boundary, the moment about the origin that its
         * clamps exert on the structure at the last assembly, -sum_a x_a x
         * g_a over the nodes of the cells along it (g the clamp energy's
         * gradient, x the current positions), on this rank. A weak clamp
         * holds the rotation through the nodes next to the edge, which are
         * not supports, so the prescribed dofs' reactions miss it; their
         * forces add up to zero (the clamp's energy does not change under
         * a translation), so only the moment is missing.
         */
        const std::map<types::boundary_id, Tensor<1, 3>> &
        clamp_moments() const
        {
          return clamp_moment;
        }

      private:
        const ShellContext &context;
        double              sum = 0.;
        /// The assembly's external force vector while edge moments load it.
        LA::Vector                                *external    = nullptr;
        const dealii::AffineConstraints<double>   *constraints = nullptr;
        std::map<types::boundary_id, Tensor<1, 3>> clamp_moment;
      };
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
