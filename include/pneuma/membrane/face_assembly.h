#pragma once

/**
 * @file
 * The membrane's face loop (membrane/face_terms.h): the edges of the owned
 * cells that the FaceTerms use, each visited once over all ranks, their
 * terms distributed into the residual and tangent, and the couplings of
 * the two cells of an interior edge in the sparsity pattern.
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/membrane/face_terms.h>

#include <vector>

namespace pneuma
{
  namespace membrane
  {
    /**
     * One edge of the face loop: face @p face of the owned @p cell,
     * interior or on the boundary. The loop visits an interior edge from
     * the finer cell, or between cells of one level from the cell with the
     * lower subdomain id (the lower cell id on one rank), so each edge
     * once over all ranks.
     */
    struct MeshEdge
    {
      DoFHandler<2, 3>::active_cell_iterator cell;
      unsigned int                           face     = 0;
      bool                                   interior = true;
    };

    /// The edges of the owned cells of @p dofs that the loop visits, in a
    /// fixed order (cells in their order, faces in theirs).
    std::vector<MeshEdge>
    mesh_edges(const DoFHandler<2, 3> &dofs,
               const bool              interior,
               const bool              boundary);

    /// Add the couplings of the two cells of every interior edge of the
    /// owned cells to @p dsp (through @p constraints).
    void
    add_face_sparsity(const DoFHandler<2, 3>          &dofs,
                      const AffineConstraints<double> &constraints,
                      DynamicSparsityPattern          &dsp);

    /**
     * The terms of @p terms on their edges at the ghosted displacement
     * @p u (with @p mapping), distributed with @p constraints into
     * @p tangent and @p residual (either may be nullptr; both are
     * compressed by the caller's pass). The edges run on the rank's
     * threads; records are committed in the edges' order.
     */
    void
    assemble_faces(const Mapping<2, 3>             &mapping,
                   const DoFHandler<2, 3>          &dofs,
                   const std::vector<FaceTerms *>  &terms,
                   const LA::Vector                &u,
                   const AffineConstraints<double> &constraints,
                   LA::SparseMatrix                *tangent,
                   LA::Vector                      *residual);
  } // namespace membrane
} // namespace pneuma
