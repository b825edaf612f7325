#pragma once

/**
 * @file
 * Terms on the edges of the membrane's cells (the faces of its
 * codimension-one mesh), added in the membrane's assembly: interior edges
 * through deal.II's FEInterfaceValues<2,3> (both cells' dofs at once, as
 * the interior-penalty and discontinuous Galerkin terms of step-47 and
 * step-74), boundary edges through FEFaceValues<2,3>. The bending of a
 * Kirchhoff-Love shell made conforming by interior penalty and contact
 * terms along edges plug in here (doc/architecture.md "Add a face term to
 * the membrane").
 *
 * The face loop runs on the rank's threads (deal.II's MeshWorker::
 * mesh_loop on WorkStream), like the cell loop of CellTerms: interior_face()
 * and boundary_face() may run concurrently on other faces, each with its
 * own Scratch, and may only write to their arguments; what spans faces
 * (an energy, a count) is added up in commit(), called one face at a time
 * in the loop's fixed order, so every sum is formed in the same order
 * whatever the number of threads.
 *
 * Each interior edge is visited once (on the rank that owns the cell with
 * the lower subdomain id, or both cells); boundary edges of owned cells
 * once. A term that couples the dofs of the two cells of an edge makes the
 * membrane add the edge couplings to the sparsity pattern (flux sparsity).
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace pneuma
{
  struct Assembly;

  namespace membrane
  {
    using namespace dealii;

    /// Terms on the membrane's cell edges.
    class FaceTerms
    {
    public:
      /// Working memory of one thread.
      struct Scratch
      {
        virtual ~Scratch() = default;
      };
      /// What a face leaves for commit() (sums over faces).
      struct Record
      {
        virtual ~Record() = default;
      };

      virtual ~FaceTerms() = default;

      /// The quadrature on an edge (its order).
      virtual unsigned int
      n_quadrature_points() const = 0;
      /// Does the term use interior edges, boundary edges?
      virtual bool
      on_interior_faces() const
      {
        return true;
      }
      virtual bool
      on_boundary_faces() const
      {
        return false;
      }
      /// What the FEInterfaceValues / FEFaceValues must compute.
      virtual UpdateFlags
      update_flags() const = 0;

      /// Before the face loop of an assembly @p a.
      virtual void
      begin(const Assembly &a)
      {
        (void)a;
      }
      virtual std::unique_ptr<Scratch>
      new_scratch() const = 0;
      virtual std::unique_ptr<Record>
      new_record() const = 0;
      /**
       * An interior edge: @p fiv is reinitialized on it; @p local_u holds
       * the displacement of its joint dofs (fiv.get_interface_dof_indices()
       * order). Add to @p matrix and @p residual (joint dofs; either may be
       * nullptr) and fill @p record.
       */
      virtual void
      interior_face(const FEInterfaceValues<2, 3> &fiv,
                    const std::vector<double>     &local_u,
                    FullMatrix<double>            *matrix,
                    Vector<double>                *residual,
                    Scratch                       &scratch,
                    Record                        &record) const = 0;
      /// A boundary edge: @p fv is reinitialized on face @p face of
      /// @p cell; @p local_u holds the cell's displacement (cell dof
      /// order).
      virtual void
      boundary_face(const DoFHandler<2, 3>::active_cell_iterator &cell,
                    const unsigned int                            face,
                    const FEFaceValues<2, 3>                     &fv,
                    const std::vector<double>                    &local_u,
                    FullMatrix<double>                           *matrix,
                    Vector<double>                               *residual,
                    Scratch                                      &scratch,
                    Record                                       &record) const
      {
        (void)cell;
        (void)face;
        (void)fv;
        (void)local_u;
        (void)matrix;
        (void)residual;
        (void)scratch;
        (void)record;
      }
      /// Add up the @p record of a face (one call at a time, in the loop's
      /// order).
      virtual void
      commit(const Record &record)
      {
        (void)record;
      }
      /// After the face loop.
      virtual void
      end()
      {
      }
    };
  } // namespace membrane
} // namespace pneuma
