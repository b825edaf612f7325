#pragma once

/**
 * @file
 * The Simulator owns a pneuma run: the membrane mesh and its unknowns, the
 * loads and boundary conditions, the Newton solver with adaptive load
 * stepping through the load stages, and the output. The header is kept
 * light (the implementation is private) so that tests and the main program
 * compile fast.
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pneuma
{
  /// Exit codes of a run (README, doc/user-guide.md).
  enum ExitCode : int
  {
    success       = 0,
    bad_input     = 1,
    solver_failed = 2
  };

  /// State of one chamber (doc/user-guide.md "Chambers").
  struct ChamberState
  {
    double pressure = 0., absolute_pressure = 0., volume = 0.,
           gas_volume = 0., liquid_volume = 0., level = 0.,
           wetted_area = 0., gas_amount = 0., pv_kappa = 0.;
  };

  /// State of one cable (doc/user-guide.md "Cables").
  struct CableState
  {
    /// Largest and smallest axial force [N], current length [m].
    double max_force = 0., min_force = 0., length = 0.;
    /// Solid-beam: largest bending and torsion moments [N m].
    double max_bending = 0., max_torsion = 0.;
    /// Solid-beam with an end moment: rotation of the end section about the
    /// moment axis [rad].
    double end_rotation = 0.;
    /// Support reactions (force on the cable) at the start and end [N].
    std::array<double, 3> start_reaction{{0., 0., 0.}},
      end_reaction{{0., 0., 0.}};
    /// Displacements of the start, end and middle node [m].
    std::array<double, 3> start_displacement{{0., 0., 0.}},
      end_displacement{{0., 0., 0.}}, mid_displacement{{0., 0., 0.}};
  };

  /// State of one contact pair (doc/user-guide.md "Contact").
  struct ContactState
  {
    unsigned int active_points = 0, points = 0;
    /// Integral of the contact line load [N], resultant force on the
    /// cable [N], largest penetration [m].
    double                total_force = 0., max_penetration = 0.;
    std::array<double, 3> force{{0., 0., 0.}};
    /// Friction: slipping points, integral of the tangential load [N].
    unsigned int slip_points    = 0;
    double       friction_force = 0.;
  };

  /// What a finished run reports (also written to summary.json).
  struct RunSummary
  {
    int          exit_code = success;
    std::string  message;
    unsigned int n_cells = 0, n_cable_cells = 0, n_dofs = 0, n_steps = 0, n_cutbacks = 0,
                 n_newton_iterations = 0, n_linear_solves = 0,
                 n_factorizations = 0, n_krylov_iterations = 0;
    double final_time = 0., wall_seconds = 0.;
    /// Displacement at each monitor point at the end of the run.
    std::vector<std::array<double, 3>> monitor_displacements;
    /// Reference position of each monitor point (the nearest vertex).
    std::vector<std::array<double, 3>> monitor_positions;
    /// Enclosed volume, reference and current (closed surfaces only).
    double initial_volume = 0., volume = 0.;
    /// Sum of the reactions at prescribed dofs and of the external loads.
    std::array<double, 3> reaction{{0., 0., 0.}}, applied_load{{0., 0., 0.}};
    /// Newton residual norms of the last load step.
    std::vector<double> last_residual_history;
    /// Chamber states at the end, and after every converged step (time,
    /// states); empty without chambers.
    std::vector<ChamberState> chambers;
    std::vector<std::pair<double, std::vector<ChamberState>>> chamber_history;
    /// Cable states at the end (empty without cables).
    std::vector<CableState> cables;
    /// Contact pair states at the end (empty without contact).
    std::vector<ContactState> contact;
    /// Newton iterations of every converged step.
    std::vector<unsigned int> step_iterations;
    /// Adaptive refinement: one record per cycle (empty without).
    struct Cycle
    {
      unsigned int                       n_cells = 0, n_dofs = 0,
                                         n_newton_iterations = 0;
      int                                exit_code = success;
      double                             volume    = 0.;
      std::vector<std::array<double, 3>> monitor_displacements;
    };
    std::vector<Cycle> cycles;
  };

  /// Result of a finite-difference check of the tangent.
  struct TangentCheck
  {
    double relative_error = 0.;
    double tangent_norm   = 0.;
  };

  /// One pneuma run, configured by a ParameterHandler.
  class Simulator
  {
  public:
    explicit Simulator(const MPI_Comm comm);
    ~Simulator();

    /// Declare every parameter of a run.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read the parameters; throws InputError with a clear message.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Build the mesh, check it against the input, and set up the system.
    void
    setup();

    /// Run all load stages; returns the summary (and writes outputs).
    RunSummary
    run();

    /**
     * Compare the assembled tangent at the current state plus a random
     * perturbation of size @p amplitude with central finite differences of
     * the residual (step @p h), at pseudo time @p t.
     */
    TangentCheck
    check_tangent(const double t, const double amplitude, const double h);

  private:
    class Impl;
    std::unique_ptr<Impl> impl;
  };

  /**
   * Declare all parameters, read @p file (.prm or .json) and apply the
   * "Path/To/Entry=value" overrides; throws InputError naming the file or
   * parameter.
   */
  void
  read_parameters(dealii::ParameterHandler       &prm,
                  const std::string              &file,
                  const std::vector<std::string> &overrides = {});
} // namespace pneuma
