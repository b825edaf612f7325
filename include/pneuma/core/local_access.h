#pragma once

/**
 * @file
 * Reading and adding the entries of distributed vectors by local index
 * (issue 49: the cost of an explicit step). Every element access of a
 * Trilinos vector by global index goes through Epetra's global-to-local
 * map (a hash lookup for a ghosted vector) and, for an addition, through
 * deal.II's checks; an explicit step reads and adds each cell's dofs
 * several times, which on the waterbeam was a fifth of the step.
 *
 * - OwnedValues: the owned values of a vector whose owned entries are one
 *   contiguous range of global indices (as deal.II's DoFHandler numbers
 *   them on each rank): entry i is values[i - first]. Additions made here
 *   are summed like those of Vector::add() (compress(add) as usual);
 *   entries owned elsewhere must take the usual path.
 * - GhostedIndices: for the cells of a ReferenceGeometry-like list of dof
 *   indices, the local index of each dof in a ghosted vector's values,
 *   found once per vector layout (its Epetra map) and reused while the
 *   layout and the list stay the same.
 *
 * Both give the same values and the same sums in the same order as the
 * global-index access, so results are bit-identical.
 */

#include <pneuma/core/linear_algebra.h>

#include <Epetra_BlockMap.h>
#include <Epetra_Import.h>

#include <memory>
#include <vector>

namespace pneuma
{
  namespace LA
  {
    class OwnedValues
    {
    public:
      /// No direct access.
      OwnedValues() = default;

      /// Direct access to @p v's owned values (none if its owned range is
      /// not contiguous or it has ghosts).
      explicit OwnedValues(Vector &v);

      /// May entry @p i be added here?
      bool
      owns(const dealii::types::global_dof_index i) const
      {
        return values != nullptr && i - first < n;
      }

      /// Entry @p i (owns(i) must hold).
      double &
      operator[](const dealii::types::global_dof_index i) const
      {
        return values[i - first];
      }

      /// Is direct access available at all?
      explicit operator bool() const
      {
        return values != nullptr;
      }

    private:
      double                         *values = nullptr;
      dealii::types::global_dof_index first  = 0;
      dealii::types::global_dof_index n      = 0;
    };

    /**
     * ghosted = owned (the owned values and the ghosts) by one Epetra
     * import whose plan is built once per pair of layouts. deal.II's
     * operator= from an owned into a ghosted vector of another map builds
     * a new plan at every call (a dozen collective operations, most of an
     * explicit step's on 2 ranks); the plan is kept while the two vectors
     * have the maps it was built for (the same Epetra map data, a test on
     * this rank alone: every rank makes its vectors the same way).
     */
    class GhostImport
    {
    public:
      /// @p ghosted (with ghosts) takes the values of @p owned.
      void
      operator()(const Vector &owned, Vector &ghosted);

    private:
      std::unique_ptr<Epetra_Import> import;
    };

    /**
     * A copy of a vector's local values (owned and ghosts) and its layout,
     * to tell whether a later vector holds the same state on this rank
     * (for results computed from it alone: the chambers' measures and
     * wall heights).
     */
    class VectorSnapshot
    {
    public:
      /// Does @p u have the layout and the local values taken last?
      bool
      matches(const Vector &u) const;

      /// Keep @p u's layout and local values.
      void
      take(const Vector &u);

    private:
      std::unique_ptr<Epetra_BlockMap> map;
      std::vector<double>              values;
    };

    class GhostedIndices
    {
    public:
      /**
       * The values of the ghosted vector @p u by local index, with the
       * local index of each of the @p n_cells x @p n_dofs indices in
       * @p dofs (recomputed only when @p u's layout or @p dofs changed).
       * nullptr if some index is not in @p u's ghosted range.
       */
      const double *
      values(const Vector                          &u,
             const dealii::types::global_dof_index *dofs,
             unsigned int                           n_cells,
             unsigned int                           n_dofs);

      /// The local indices of cell @p k's dofs (after values()).
      const int *
      cell(const unsigned int k) const
      {
        return &local[std::size_t(k) * n_dofs_per_cell];
      }

    private:
      std::unique_ptr<Epetra_BlockMap>       map;
      const dealii::types::global_dof_index *dofs_address    = nullptr;
      unsigned int                           n_cells         = 0;
      unsigned int                           n_dofs_per_cell = 0;
      bool                                   complete        = false;
      std::vector<int>                       local;
    };
  } // namespace LA
} // namespace pneuma
