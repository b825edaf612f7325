#pragma once

/**
 * @file
 * The chambers as a subsystem of the coupled model (core/subsystem.h): one
 * or two border unknowns per chamber group (gas pressure, free-surface
 * level) with their constraints, and the filling loads on the membrane's
 * walls, added to the membrane's cell loop (chambers/chamber_system.h,
 * doc/theory.md "Chambers"). Present only when "Chambers/Number of
 * chambers" is positive.
 */

#include <pneuma/chambers/chamber_assembler.h>
#include <pneuma/chambers/chamber_parameters.h>
#include <pneuma/chambers/chamber_system.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include <memory>

namespace pneuma
{
  namespace chambers
  {
    /// The chamber subsystem.
    class ChamberSubsystem : public Subsystem,
                             public NewtonAids,
                             public Checkpointed,
                             public OutputFiles,
                             public BorderFromField,
                             public membrane::CellTerms
    {
    public:
      explicit ChamberSubsystem(Model &model);

      /// "Chambers/Number of chambers".
      static void
      declare_switches(ParameterHandler &prm);
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "chambers";
      }
      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;

      types::global_dof_index
      setup_unknowns(const types::global_dof_index first,
                     const MPI_Comm                comm) override;
      unsigned int
      n_border_unknowns() const override
      {
        return system.n_unknowns();
      }
      void
      finish_setup() override;

      void
      initialize(const LA::Vector &field, const double t) override;
      std::string
      begin_step(const double t, const LA::Vector &field, bool &grown) override;
      Vector<double>
      border() const override
      {
        return system.pack();
      }
      void
      assemble(const Assembly &a) override;
      void
      commit_step(const double          t,
                  const LA::Vector     &field,
                  const Vector<double> &border) override;
      void
      save_checkpoint(
        Checkpoint                            &checkpoint,
        const std::vector<const LA::Vector *> &fields) const override;
      void
      load_checkpoint(const Checkpoint                &checkpoint,
                      const std::vector<LA::Vector *> &fields) override;
      /// The reports of a state restored from a checkpoint.
      void
      refresh(const LA::Vector &field) override;
      double
      force_scale(const LA::Vector &field) const override;
      /// The virial of the gas pressures at the state last assembled,
      /// 3 p V per chamber (divergence theorem), over twice the walls'
      /// area: pR/2 for a sphere, 3pR/4 for a tube between plates (the
      /// mean of its hoop and axial forces). The liquid's share is left
      /// out.
      double
      start_prestress(const LA::Vector &external) const override;
      /// The border for a given field (ChamberSystem::border_for()).
      Vector<double>
      border_for(const LA::Vector              &field,
                 const double                   t,
                 const Vector<double>          &border,
                 std::vector<BorderConstraint> &constraints) const override;
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field,
                     const double      t) const override;
      void
      add_output_fields(const LA::Vector &field, const double t) override;

      // ---- membrane::CellTerms: the filling loads on the walls
      void
      begin(const Assembly &a) override;
      std::unique_ptr<membrane::CellTerms::Scratch>
      new_scratch() const override;
      std::unique_ptr<membrane::CellTerms::Record>
      new_record() const override;
      void
      cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
           const membrane::ReferenceGeometry            &reference,
           const unsigned int                            cell_index,
           const std::vector<double>                    &local_u,
           FullMatrix<double>                           *cell_matrix,
           Vector<double>                               *cell_residual,
           membrane::CellTerms::Scratch                 &scratch,
           membrane::CellTerms::Record                  &record) const override;
      void
      commit(const membrane::CellTerms::Record          &record,
             const std::vector<types::global_dof_index> &dof_indices) override;
      void
      end() override;
      void
      add_loads(const LA::Vector                &u,
                const AffineConstraints<double> &constraints,
                const double                     t,
                LA::Vector                      &residual,
                LA::Vector                      &external) const override;

    private:
      /// A checkpoint was loaded: record the reports at the next refresh.
      bool restored = false;
      /// This subsystem's part of the border vector @p border.
      Vector<double>
      own_part(const Vector<double> &border) const;

      Model                                  &model;
      membrane::MembraneSubsystem            &membrane;
      ChamberParameters                       parameters;
      ChamberAssembler                        assembler;
      ChamberSystem                           system;
      std::vector<ChamberLoad>                pass_loads;
      std::vector<ChamberMeasures>            measures;
      std::unique_ptr<ChamberAssembler::Pass> pass;
      ChamberCellData                         output_cells;
    };
  } // namespace chambers
} // namespace pneuma
