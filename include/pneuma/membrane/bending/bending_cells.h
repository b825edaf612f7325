#pragma once

/**
 * @file
 * The bending energy inside the shell regions' cells (a membrane
 * CellTerms): w = 1/2 kappa : D_b : kappa per reference area at the
 * cell's Gauss points (degree + 1 per direction), kappa the change of
 * curvature of bending/kirchhoff_love.h, residual and tangent its exact
 * derivatives.
 */

#include <pneuma/membrane/bending/shell_bending.h>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      /// The cells' bending energy.
      class BendingCells : public CellTerms
      {
      public:
        explicit BendingCells(const ShellContext &context);

        void
        begin(const Assembly &a) override;
        std::unique_ptr<CellTerms::Scratch>
        new_scratch() const override;
        std::unique_ptr<CellTerms::Record>
        new_record() const override;
        void
        cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
             const ReferenceGeometry                      &reference,
             const unsigned int                            cell_index,
             const std::vector<double>                    &local_u,
             FullMatrix<double>                           *cell_matrix,
             Vector<double>                               *cell_residual,
             CellTerms::Scratch                           &scratch,
             CellTerms::Record &record) const override;
        void
        commit(
          const CellTerms::Record                    &record,
          const std::vector<types::global_dof_index> &dof_indices) override;
        void
        end() override
        {
        }
        /// No loads: nothing for the reactions.
        void
        add_loads(const LA::Vector &,
                  const AffineConstraints<double> &,
                  const double,
                  LA::Vector &,
                  LA::Vector &) const override
        {
        }
        /// The bending energy of this rank's cells at the last assembly.
        double
        energy() const
        {
          return sum;
        }

      private:
        const ShellContext &context;
        double              sum = 0.;
      };
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
