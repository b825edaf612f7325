#pragma once

/**
 * @file
 * The cables as a subsystem of the coupled model (core/subsystem.h): each
 * cable on its own `Triangulation<1,3>` and `DoFHandler`, numbered after
 * the membrane dofs, owned by rank 0 (cables/cable_system.h,
 * doc/theory.md "Cables"). Present only when "Cables/Number of cables" is
 * positive.
 */

#include <pneuma/cables/cable_parameters.h>
#include <pneuma/cables/cable_system.h>
#include <pneuma/core/capabilities.h>
#include <pneuma/core/subsystem.h>

#include <set>

namespace pneuma
{
  namespace cables
  {
    /// The cable subsystem.
    class CableSubsystem : public Subsystem,
                           public NewtonAids,
                           public Inertia,
                           public LinearSolverHints,
                           public Checkpointed,
                           public OutputFiles
    {
    public:
      explicit CableSubsystem(Model &model);

      /// "Cables/Number of cables".
      static void
      declare_switches(ParameterHandler &prm);
      static bool
      is_active(const InputLayout &layout);

      std::string
      name() const override
      {
        return "cables";
      }
      void
      declare_parameters(ParameterHandler  &prm,
                         const InputLayout &layout) override;
      void
      parse_parameters(ParameterHandler &prm) override;

      types::global_dof_index
      setup_unknowns(const types::global_dof_index first,
                     const MPI_Comm                comm) override;
      void
      add_locally_owned(IndexSet &owned) const override;
      /// Every rank sees all cable unknowns: it assembles a share of the
      /// elements (CableSystem::assemble()).
      void
      add_locally_relevant(IndexSet &relevant) override;
      void
      add_update_constraints(AffineConstraints<double> &c) const override;
      void
      add_sparsity(DynamicSparsityPattern          &dsp,
                   const AffineConstraints<double> &constraints) const override;
      void
      add_regularisation(const AffineConstraints<double> &constraints,
                         LA::SparseMatrix                &L) const override;
      void
      add_mass(const AffineConstraints<double> &constraints,
               LA::SparseMatrix                &M) const override;
      void
      add_lumped_mass(LA::Vector &m) const override;
      void
      largest_per_node(LA::Vector &v) const override;
      void
      add_mode_fields(const std::vector<std::string> &names,
                      const std::vector<LA::Vector>  &modes) override;
      void
      add_near_null_space(
        const IndexSet                   &owned,
        std::vector<std::vector<double>> &modes) const override;
      double
      initial_shift(
        const double                     factor,
        const UnknownRange              &range,
        const LA::SparseMatrix          &K,
        const LA::SparseMatrix          &L,
        const LA::Vector                &external,
        const AffineConstraints<double> &constraints) const override;

      void
      first_guess(const double t, LA::Vector &field) const override;
      bool
      ramp_initial_loads(const double t0, const double t1) override;
      /// A staged prestress that is not finite at @p t is an input error.
      std::string
      begin_step(const double t, const LA::Vector &field, bool &grown) override;
      void
      set_prescribed_values(const double t, LA::Vector &field) const override;
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
      double
      force_scale(const LA::Vector &field) const override;
      void
      add_statistics(Statistics       &statistics,
                     const LA::Vector &field,
                     const double      t) const override;
      void
      write_output_files(const std::string &directory,
                         const unsigned int step,
                         const double       t,
                         const LA::Vector  &field) override;

      void
      check_well_posed() const override;
      /// Cable @p k (0-based) touches something that may hold it (a
      /// contact pair): a cable without supports is then allowed.
      void
      hold(const unsigned int k)
      {
        held.insert(k);
      }

      /// The cable block (for the contact).
      CableSystem &
      system()
      {
        return cables;
      }
      const CableParameters &
      definitions() const
      {
        return parameters;
      }

    private:
      Model                 &model;
      CableParameters        parameters;
      CableSystem            cables;
      std::set<unsigned int> held;
    };
  } // namespace cables
} // namespace pneuma
