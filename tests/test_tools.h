#pragma once

// Shared helpers of the pneuma verification tests: set a scene up from
// "Path/To/Entry" = value settings (through the same input path as the
// main program: layout, declaration, parse), run it, and compare a value
// with its reference, printing the reference, the value and the relative
// error at fixed precision.

#include "test_paths.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <pneuma/core/input_layout.h>
#include <pneuma/simulator/simulator.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pneuma_test
{
  using Settings = std::vector<std::pair<std::string, std::string>>;

  /// @p x with all its digits, for a setting's value.
  inline std::string
  number(const double x)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.15g", x);
    return buffer;
  }

  /// Quiet runs without VTU into "run-output".
  inline Settings
  quiet()
  {
    return {{"Output/Quiet", "true"},
            {"Output/Directory", "run-output"},
            {"Output/Write VTU", "false"},
            {"Newton/Print convergence table", "false"}};
  }

  /**
   * A simulator set up from @p settings on top of the defaults, or of the
   * parameter file @p file if given (settings then act as --set).
   */
  inline std::unique_ptr<pneuma::Simulator>
  make(const Settings    &settings,
       const std::string &file = "",
       const MPI_Comm     comm = MPI_COMM_WORLD)
  {
    // Never the default directory "output": in a deal.II test folder that
    // name is the test's own output file.
    std::vector<std::string> overrides = {"Output/Directory=run-output"};
    for (const auto &s : settings)
      overrides.push_back(s.first + "=" + s.second);
    const auto layout    = file.empty()
                             ? pneuma::InputLayout::from_text("", overrides)
                             : pneuma::InputLayout::read(file, overrides);
    auto       simulator = std::make_unique<pneuma::Simulator>(comm, layout);
    // Input errors (in the parameters or found on the mesh) destroy the
    // simulator here, not while the exception unwinds (its timers would
    // print a warning into the test output).
    std::exception_ptr error;
    try
      {
        dealii::ParameterHandler prm;
        simulator->declare_parameters(prm);
        if (file.empty())
          pneuma::parse_input_text(prm, "", overrides);
        else
          pneuma::parse_input(prm, file, overrides);
        simulator->parse_parameters(prm);
        simulator->setup();
      }
    catch (...)
      {
        error = std::current_exception();
      }
    if (error)
      {
        simulator.reset();
        std::rethrow_exception(error);
      }
    return simulator;
  }

  /// Declare material regions @p ids with the default material (the input
  /// must name every region of the mesh).
  inline Settings
  regions(const std::vector<unsigned int> &ids)
  {
    Settings s;
    for (const auto id : ids)
      s.emplace_back("Materials/Region " + std::to_string(id) + "/Thickness",
                     "1e-3");
    return s;
  }

  /// Is this rank 0 of MPI_COMM_WORLD (the one that prints)?
  inline bool
  root()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  /// Whether the run @p s failed; if so, rank 0 prints "what: run failed
  /// (exit code): message".
  inline bool
  failed(const pneuma::RunResult &s, const std::string &what)
  {
    if (s.exit_code == 0)
      return false;
    if (root())
      std::printf("%s: run failed (exit %d): %s\n",
                  what.c_str(),
                  s.exit_code,
                  s.message.c_str());
    return true;
  }

  /// Run pneuma quietly with @p settings on top of the defaults.
  inline pneuma::RunResult
  run(const Settings &settings, const MPI_Comm comm = MPI_COMM_WORLD)
  {
    Settings all = quiet();
    all.insert(all.end(), settings.begin(), settings.end());
    return make(all, "", comm)->run();
  }

  /// Print "name: reference r, value v, relative error e" and return
  /// whether |e| <= tolerance. Values with @p precision digits after the
  /// mantissa's point (4; fewer for a state that round-off moves in the
  /// 5th significant digit, so that the output compares).
  inline bool
  check(const std::string &name,
        const double       value,
        const double       reference,
        const double       tolerance,
        const int          precision = 4)
  {
    const double error = (value - reference) / std::abs(reference);
    const bool   ok    = std::abs(error) <= tolerance && std::isfinite(value);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: reference %.*e value %.*e relative error %.1e "
                  "(tolerance %.1e) %s\n",
                  name.c_str(),
                  precision,
                  reference,
                  precision,
                  value,
                  std::abs(error) < 5e-6 ? 0. : error,
                  tolerance,
                  ok ? "PASS" : "FAIL");
    return ok;
  }

  /**
   * The incompressible neo-Hookean sphere of V3 (R = 1 m, H = 1 mm,
   * mu = 1 MPa, Q2 on 3 refinements) as the one wall of chamber 1, inflated
   * through three stages to t = 2 (the chamber's control comes from the
   * caller).
   */
  inline Settings
  neo_hookean_sphere_chamber()
  {
    return {{"Geometry/Type", "sphere"},
            {"Geometry/sphere/Radius", "1"},
            {"Geometry/Global refinements", "3"},
            {"Discretisation/Polynomial degree", "2"},
            {"Materials/Region 0/Law", "neo-Hookean"},
            {"Materials/Region 0/Thickness", "1e-3"},
            {"Materials/Region 0/neo-Hookean/Shear modulus", "1e6"},
            {"Boundary conditions/Fixed points",
             "0,0,1: xy; 0,0,-1: xy; 1,0,0: yz; -1,0,0: yz"},
            {"Chambers/Number of chambers", "1"},
            {"Chambers/Chamber 1/Regions", "0"},
            {"Load stepping/Stage end times", "0.5, 1, 2"},
            {"Load stepping/Initial increment", "0.1"},
            {"Load stepping/Maximum increment", "0.25"}};
  }

  /**
   * The airbeam tube (R 0.23 m, L 2 m, 1 mm SVK wall, rigid steel end
   * plates, Q1, 3 refinements) as one chamber of liquid and gas: the gas
   * amount doubles over t in [0, 1], then 0.15 m^3 of liquid is pumped in
   * over [1, 2] (two stages). The stepping comes from the caller.
   */
  inline Settings
  liquid_gas_tube()
  {
    return {
      {"Geometry/Type", "closed cylinder"},
      {"Geometry/closed cylinder/Radius", "0.23"},
      {"Geometry/closed cylinder/Length", "2"},
      {"Geometry/Global refinements", "3"},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "7.6e9"},
      {"Materials/Region 1/Thickness", "1e-2"},
      {"Materials/Region 1/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
      {"Materials/Region 2/Thickness", "1e-2"},
      {"Materials/Region 2/Saint Venant-Kirchhoff/Young's modulus", "2.1e11"},
      {"Boundary conditions/Rigid regions", "1, 2"},
      {"Boundary conditions/Fixed points",
       "0,0,0: xyz; 2,0,0: yz; 0.05,0,0.23: y"},
      {"Chambers/Number of chambers", "1"},
      {"Chambers/Chamber 1/Regions", "0, 1, 2"},
      {"Chambers/Chamber 1/Filling", "liquid and gas"},
      {"Chambers/Chamber 1/Gas/Control", "gas amount"},
      {"Chambers/Chamber 1/Gas/Gas amount/Function expression",
       "1 + min(t, 1)"},
      {"Chambers/Chamber 1/Liquid/Volume/Function expression",
       "0.15*max(t - 1, 0)"},
      {"Load stepping/Stage end times", "1, 2"}};
  }

  /// The gas amount V_n/V0 (adiabatic air, kappa 1.4, p_a = 101325 Pa)
  /// that keeps a neo-Hookean balloon (mu H/R = 1000 Pa) on its
  /// equilibrium path at the stretch l = 1 + t: l^3 (1 + p(l)/p_a)^(1/kappa).
  inline const char *
  balloon_gas_amount()
  {
    return "(1+t)^3*(1+2000*(1/(1+t)-1/(1+t)^7)/101325)^(1/1.4)";
  }

  /**
   * Two such balloons (unit spheres of meshes/two_spheres.msh, Q2,
   * mu = 1 MPa, H = 1 mm) connected into one chamber group, chamber 1
   * controlling it (its control comes from the caller), one stage to
   * t = 1 from increments of 0.1, with the stability check.
   */
  /**
   * The square airbag of Contri & Schrefler (1988): two flat square sheets
   * of diagonal 1.2 m seamed along their edges (meshes/square_airbag.msh,
   * 4 x 4 Q1 cells per sheet, @p refinements global refinements),
   * E = 588 MPa, nu = 0.4, t = 0.6 mm, tension-field wrinkling, inflated
   * from flat by p = 5000 t Pa; only the rigid-body motions held; the
   * centre monitored.
   */
  inline Settings
  square_airbag(const unsigned int refinements)
  {
    const std::string L = "0.848528", c = "0.424264";
    Settings          s = {{"Geometry/Type", "gmsh"},
                           {"Geometry/gmsh/Mesh file",
                            std::string(PNEUMA_SOURCE_DIR)
                              + "/meshes/square_airbag.msh"},
                           {"Geometry/Global refinements", std::to_string(refinements)},
                           {"Boundary conditions/Fixed points",
                            "0,0,0: xyz; " + L + ",0,0: yz; 0," + L + ",0: z"},
                           {"Loads/Pressure regions", "1, 2"},
                           {"Loads/Pressure/Function expression", "5000*t"},
                           {"Output/Monitor points", c + "," + c + ",0"}};
    for (const std::string region : {"1", "2"})
      for (const auto &[entry, value] :
           Settings{{"Thickness", "6e-4"},
                    {"Wrinkling", "tension field"},
                    {"Saint Venant-Kirchhoff/Young's modulus", "5.88e8"},
                    {"Saint Venant-Kirchhoff/Poisson's ratio", "0.4"}})
        s.push_back({"Materials/Region " + region + "/" + entry, value});
    return s;
  }

  inline Settings
  two_connected_balloons()
  {
    Settings s = {{"Geometry/Type", "gmsh"},
                  {"Geometry/gmsh/Mesh file",
                   std::string(PNEUMA_SOURCE_DIR) + "/meshes/two_spheres.msh"},
                  {"Geometry/Global refinements", "0"},
                  {"Discretisation/Polynomial degree", "2"},
                  {"Boundary conditions/Fixed points",
                   "0,0,1: xy; 0,0,-1: xy; 1,0,0: yz; -1,0,0: yz; "
                   "3,0,1: xy; 3,0,-1: xy; 4,0,0: yz; 2,0,0: yz"},
                  {"Chambers/Number of chambers", "2"},
                  {"Chambers/Chamber 1/Regions", "0"},
                  {"Chambers/Chamber 1/Interior point", "0, 0, 0"},
                  {"Chambers/Chamber 2/Regions", "1"},
                  {"Chambers/Chamber 2/Interior point", "3, 0, 0"},
                  {"Chambers/Chamber 2/Filling", "connected"},
                  {"Chambers/Chamber 2/Connected to", "1"},
                  {"Load stepping/Stage end times", "1"},
                  {"Load stepping/Initial increment", "0.1"},
                  {"Stability/Check inertia", "true"}};
    for (const std::string r : {"0", "1"})
      {
        s.push_back({"Materials/Region " + r + "/Law", "neo-Hookean"});
        s.push_back({"Materials/Region " + r + "/Thickness", "1e-3"});
        s.push_back(
          {"Materials/Region " + r + "/neo-Hookean/Shear modulus", "1e6"});
      }
    return s;
  }

  /// |reactions + applied loads| / |applied vertical load| of a run: zero
  /// up to round-off when every force reaches the supports.
  inline double
  load_imbalance(const pneuma::RunResult &s)
  {
    const auto r   = s.summary.get_vector("reaction");
    const auto f   = s.summary.get_vector("applied_load");
    double     sum = 0.;
    for (unsigned int c = 0; c < 3; ++c)
      sum += std::pow(r[c] + f[c], 2);
    return std::sqrt(sum) / std::abs(f[2]);
  }

  /// Newton's observed order in the last step of a run: log(r_{k+1}/r_0)
  /// / log(r_k/r_0) at its last pair of iterations between 1e-1 and 1e-12
  /// of the first residual (0 if there is none).
  inline double
  last_step_order(const pneuma::RunResult &s)
  {
    const auto &r     = s.last_residual_history;
    double      order = 0.;
    for (unsigned int k = 1; k + 1 < r.size(); ++k)
      if (r[k + 1] / r[0] > 1e-12 && r[k] / r[0] < 1e-1)
        order = std::log(r[k + 1] / r[0]) / std::log(r[k] / r[0]);
    return order;
  }
} // namespace pneuma_test
