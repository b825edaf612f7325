#pragma once

/**
 * @file
 * Membrane-to-membrane contact as a subsystem of the coupled model
 * (core/subsystem.h): membrane regions that bear on each other or fold
 * onto themselves (contact/surfaces/surface_contact.h, doc/theory.md
 * "Membrane-to-membrane contact"). Present only when "Surface
 * contact/Number of pairs" is positive. It has no unknowns; its forces are
 * internal to the membrane (they add up to zero), so they leave the
 * reactions alone. Each pair reports its contact force, area, penetration
 * and penalty energy; the VTU gets surface_contact_pressure and
 * surface_contact_gap per cell.
 */

#include <deal.II/lac/vector.h>

#include <pneuma/contact/surfaces/surface_contact.h>
#include <pneuma/contact/surfaces/surface_parameters.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include <memory>

namespace pneuma
{
  namespace contact
  {
    /// The membrane-to-membrane contact pairs.
    class SurfaceSubsystem : public Subsystem, public OutputFiles
    {
    public:
      explicit SurfaceSubsystem(Model &model);

      /// "Surface contact/Number of pairs".
      static void
      declare_switches(ParameterHandler &prm);
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "surface contact";
      }
      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;
      /// The pairs' cells on every rank, their dofs as ghosts, the first
      /// candidates.
      void
      add_locally_relevant(IndexSet &relevant) override;
      /// Print each pair's penalty and search distance.
      void
      finish_setup() override;
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const override;
      /// The membranes do not overlap at the start.
      void
      initialize(const LA::Vector &field, const double t) override;
      /// New candidates and sides at the step's start.
      std::string
      begin_step(const double t, const LA::Vector &field, bool &grown) override;
      void
      assemble(const Assembly &a) override;
      /// No point penetrates a cell the step did not test.
      std::string
      check_state(const LA::Vector &field) const override;
      /// Accept @p field (the sides of the next step) and record it.
      void
      refresh(const LA::Vector &field) override;
      void
      commit_step(const double          t,
                  const LA::Vector     &field,
                  const Vector<double> &border) override;
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field,
                     const double      t) const override;
      void
      add_output_fields(const LA::Vector &field, const double t) override;

    private:
      /// The reports and per-cell values of the state @p field.
      void
      record(const LA::Vector &field);

      Model                          &model;
      membrane::MembraneSubsystem    &membrane;
      SurfaceParameters               parameters;
      std::unique_ptr<SurfaceContact> contact;
      /// What the last refresh() found (reports, per-cell values).
      SurfaceRecord recorded;
      Vector<float> pressure_output, gap_output;
    };
  } // namespace contact
} // namespace pneuma
