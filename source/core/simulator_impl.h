#pragma once

// Private to the Simulator: its state, shared by the .cc files of core/.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>

#include <pneuma/geometry/adaptive_refinement.h>
#include <pneuma/cables/cable_parameters.h>
#include <pneuma/cables/cable_system.h>
#include <pneuma/chambers/chamber_assembler.h>
#include <pneuma/contact/contact_parameters.h>
#include <pneuma/contact/contact_system.h>
#include <pneuma/chambers/chamber_parameters.h>
#include <pneuma/chambers/chamber_system.h>
#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/simulator.h>
#include <pneuma/geometry/junctions.h>
#include <pneuma/geometry/scene_generator.h>
#include <pneuma/loads/boundary_conditions.h>
#include <pneuma/loads/loads.h>
#include <pneuma/loads/rigid_regions.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/membrane_assembler.h>
#include <pneuma/solvers/linear_solver.h>
#include <pneuma/solvers/load_stepping.h>
#include <pneuma/solvers/newton_solver.h>

#include <fstream>
#include <memory>

namespace pneuma
{
  using namespace dealii;

  /// "Output" subsection.
  struct OutputParameters
  {
    std::string           directory    = "output";
    unsigned int          vtu_interval = 1;
    bool                  write_vtu    = true;
    bool                  test_output  = false;
    bool                  quiet        = false;
    std::vector<Point<3>> monitor_points;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  class Simulator::Impl : public solvers::NonlinearProblem
  {
  public:
    explicit Impl(const MPI_Comm comm);
    /// The direct solver refers to the tangent: release it first.
    ~Impl() override
    {
      linear_solver.reset();
    }

    // --- setup (simulator.cc)
    void
    setup_system();
    void
    make_constraints();
    /// Refine by the error indicator of the current solution and set the
    /// system up again (adaptive_refinement.h).
    void
    refine_mesh();
    /// The mapping of the current mesh, its support points cached.
    void
    cache_mapping();
    /// Masters that dependent dofs refer to (share_constraints.h).
    IndexSet
    shared_masters() const;
    /// Sparsity pattern, tangent and regularisation matrix (again when the
    /// contact couplings grow).
    void
    build_matrices();
    /// Set rigid-plate and junction-copy dofs from their masters.
    void
    apply_kinematic_constraints();

    // --- NonlinearProblem
    void
    assemble(const solvers::BorderedVector &u,
             solvers::BorderedVector       &residual) override;
    void
    set_linear_tolerance(const double eta) override
    {
      linear_solver.set_forcing(eta);
    }
    void
    solve_linear(const double                   shift,
                 const solvers::BorderedVector &rhs,
                 solvers::BorderedVector       &du) override;
    double
    shift_scale() override;
    double
    load_norm() override;
    void
    laplacian_vmult(const solvers::BorderedVector &x,
                    solvers::BorderedVector       &y) override;
    /// Chamber states of the last converged step.
    std::vector<ChamberState>
    chamber_states() const;

    // --- run (simulator.cc)
    RunSummary
    run();

    // --- output (simulator_output.cc)
    void
    prepare_output_directory();
    /// Output/Directory/refinement.csv: one row per refinement cycle.
    void
    write_refinement_table(const std::vector<RunSummary::Cycle> &cycles) const;
    void
    write_vtu(const unsigned int step, const double t);
    void
    write_history_row(const unsigned int step,
                      const double       t,
                      const unsigned int newton_iterations);
    void
    write_summary(const RunSummary &summary);
    void
    locate_monitor_points();
    std::vector<std::array<double, 3>>
    monitor_displacements();
    void
    compute_reactions(std::array<double, 3> &reaction,
                      std::array<double, 3> &applied);

    MPI_Comm           comm;
    ConditionalOStream pcout;
    TimerOutput        timer;
    Timer              wall_clock;

    // Parameters.
    geometry::SceneGenerator  geometry;
    geometry::AdaptiveRefinement refinement;
    membrane::MaterialRegions materials;
    loads::Loads              loads;
    loads::BoundaryConditions boundary_conditions;
    loads::RigidRegions       rigid_regions;
    solvers::NewtonSolver     newton;
    solvers::LinearSolver     linear_solver;
    solvers::LoadStepping     stepping;
    OutputParameters          output;
    chambers::ChamberParameters chamber_parameters;
    cables::CableParameters   cable_parameters;
    contact::ContactParameters contact_parameters;
    unsigned int              degree = 1;
    /// Contact reports (and output fields) at the current solution.
    void
    refresh_contact();
    /// Contact pair states of the last assembly.
    std::vector<ContactState>
    contact_states() const;

    /// False for Geometry/Type = none (a scene of cables only).
    bool
    has_membrane() const
    {
      return geometry.type() != "none";
    }
    /// Cable states at the current solution (rank 0; empty elsewhere).
    std::vector<CableState>
    cable_states();

    // Discretisation.
    parallel::distributed::Triangulation<2, 3> triangulation;
    std::unique_ptr<FESystem<2, 3>>            fe;
    std::unique_ptr<MappingQ<2, 3>>            mapping;
    DoFHandler<2, 3>                           dof_handler;
    IndexSet                                   locally_owned, locally_relevant;
    AffineConstraints<double>                  constraints;
    /// Hanging nodes and rigid plates only (no prescribed values): used to
    /// condense forces onto the independent dofs for the reactions.
    AffineConstraints<double>                  kinematic_constraints;
    /// Coincident copies of junction dofs (dividers, shared seams).
    geometry::JunctionTies                     junction_ties;
    membrane::MembraneAssembler                assembler;
    chambers::ChamberAssembler                 chamber_assembler;
    chambers::ChamberSystem                    chamber_system;
    std::vector<chambers::ChamberMeasures>     chamber_measures;
    /// The cable block (own meshes and DoFHandlers; rank 0 owns its dofs).
    cables::CableSystem                        cable_system;
    /// Cable-membrane contact (empty: no search at all).
    contact::ContactSystem                     contact_system;

    // State.
    LA::SparseMatrix tangent, laplacian;
    LA::Vector       solution, ghosted, external;
    double           current_time    = 0.;
    double           initial_volume  = 0.;
    unsigned int     n_linear_solves = 0;

    // Monitor points: (owning rank's) dof indices of the nearest vertex.
    std::vector<std::array<types::global_dof_index, 3>> monitor_dofs;
    std::vector<std::array<double, 3>>                  monitor_positions;

    // Output records.
    std::vector<std::pair<double, std::string>> pvd_records;
    std::unique_ptr<std::ofstream>              history;
  };
} // namespace pneuma
