#pragma once

/**
 * @file
 * Cable-membrane contact as a subsystem of the coupled model
 * (core/subsystem.h): penalty forces between the cable mid-lines and the
 * membrane, with their exact tangent, a candidate search renewed at the
 * start of every step (contact/contact_system.h, doc/theory.md "Contact").
 * Present only when "Contact/Number of pairs" is positive. It has no
 * unknowns of its own: its forces enter the membrane and cable rows.
 */

#include <pneuma/cables/cable_subsystem.h>
#include <pneuma/contact/contact_parameters.h>
#include <pneuma/contact/contact_system.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>
#include <pneuma/membrane/membrane_subsystem.h>

namespace pneuma
{
  namespace contact
  {
    /// The contact subsystem.
    class ContactSubsystem : public Subsystem,
                             public LinearSolverHints,
                             public Checkpointed,
                             public OutputFiles,
                             public Holds
    {
    public:
      explicit ContactSubsystem(Model &model);

      /// "Contact/Number of pairs".
      static void
      declare_switches(ParameterHandler &prm);
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "contact";
      }
      /// The membrane may be held by the cables it touches.
      bool
      holds(const Subsystem &other) const override;
      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;

      void
      add_locally_relevant(IndexSet &relevant) override;
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const override;

      void
      initialize(const LA::Vector &field, const double t) override;
      std::string
      begin_step(const double t, const LA::Vector &field, bool &grown) override;
      void
      assemble(const Assembly &a) override;
      std::string
      check_state(const LA::Vector &field) const override;
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
      void
      refresh(const LA::Vector &field) override;
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field,
                     const double      t) const override;
      void
      add_output_fields(const LA::Vector &field, const double t) override;
      /// False while any pair uses the smoothed master normal, or while a point
      /// of a pair with friction slips (in the last assembly).
      bool
      symmetric_tangent() const override;

    private:
      Model                         &model;
      membrane::MembraneSubsystem   &membrane;
      cables::CableSubsystem        *cables;
      ContactParameters              parameters;
      std::unique_ptr<ContactSystem> contact;
      Vector<float>                  pressure_output;
    };
  } // namespace contact
} // namespace pneuma
