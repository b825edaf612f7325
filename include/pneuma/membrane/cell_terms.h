#pragma once

/**
 * @file
 * Terms of another subsystem (the chambers' wall loads) on the membrane's
 * cells, added to the membrane's cell matrix and residual in its cell loop
 * so that each cell matrix is distributed once.
 *
 * The cell loop runs on the threads of the rank (deal.II's WorkStream,
 * MembraneAssembler::assemble): cell() may run on several threads at once,
 * each with its own Scratch, and leaves what it adds up across cells
 * (volumes, dV/du) in a Record; commit() then takes the records one at a
 * time, in the order of the cells, so every sum is formed in the same
 * order whatever the number of threads (results are bitwise those of one
 * thread).
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/membrane/reference_geometry.h>

#include <memory>
#include <vector>

namespace pneuma
{
  struct Assembly;

  namespace membrane
  {
    using namespace dealii;

    /// Terms of another subsystem on the membrane's cells.
    class CellTerms
    {
    public:
      /// Working memory of one thread (its FEValues, quadrature
      /// generators).
      struct Scratch
      {
        virtual ~Scratch() = default;
      };
      /// What cell() leaves of one cell for commit().
      struct Record
      {
        virtual ~Record() = default;
      };

      virtual ~CellTerms() = default;
      /// Before the cell loop of a Newton assembly @p a.
      virtual void
      begin(const Assembly &a) = 0;
      /// A new thread's working memory.
      virtual std::unique_ptr<Scratch>
      new_scratch() const = 0;
      /// A new (empty) record.
      virtual std::unique_ptr<Record>
      new_record() const = 0;
      /**
       * Add to the cell matrix and residual (either may be nullptr) and
       * fill @p record, at the displacement @p local_u of the cell with
       * @p cell_index in the membrane's @p reference data (its points,
       * frames and shape derivatives). Runs concurrently on other cells:
       * it may only write to its arguments.
       */
      virtual void
      cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
           const ReferenceGeometry                      &reference,
           const unsigned int                            cell_index,
           const std::vector<double>                    &local_u,
           FullMatrix<double>                           *cell_matrix,
           Vector<double>                               *cell_residual,
           Scratch                                      &scratch,
           Record                                       &record) const = 0;
      /// Add up the @p record of the cell with @p dof_indices (one call at
      /// a time, in the order of the cells).
      virtual void
      commit(const Record                               &record,
             const std::vector<types::global_dof_index> &dof_indices) = 0;
      /// After the cell loop.
      virtual void
      end() = 0;
      /// For the reactions at the converged state @p u (ghosted) at pseudo
      /// time @p t: add the loads to @p residual (as -f) and to
      /// @p external (as +f).
      virtual void
      add_loads(const LA::Vector                &u,
                const AffineConstraints<double> &constraints,
                const double                     t,
                LA::Vector                      &residual,
                LA::Vector                      &external) const = 0;
    };
  } // namespace membrane
} // namespace pneuma
