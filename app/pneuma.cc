/**
 * @file
 * The pneuma main program: reads a parameter file, runs the simulation and
 * maps every outcome to an exit code (0 success, 1 bad input, 2 solver
 * failure after cut-backs with the last converged state written).
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/simulator.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "pneuma: inflatable membrane structures (deal.II)\n\n"
        << "Usage:\n"
        << "  pneuma FILE.prm [--set \"Path/To/Entry=value\"]...\n"
        << "  mpirun -np N pneuma FILE.prm\n"
        << "  pneuma --print-parameters   every parameter with default, "
           "pattern and doc\n"
        << "  pneuma --help\n\n"
        << "Exit codes: 0 success, 1 bad input, 2 solver failure "
           "(last converged state written).\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

  std::string              file;
  std::vector<std::string> overrides;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
        {
          if (root)
            print_usage(std::cout);
          return 0;
        }
      if (arg == "--print-parameters")
        {
          dealii::ParameterHandler prm;
          pneuma::Simulator::declare_parameters(prm);
          // Defaults with their documentation, then the allowed values.
          if (root)
            {
              prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
              std::cout << "\n# Allowed values of every entry\n"
                        << "# ------------------------------\n";
              prm.print_parameters(std::cout,
                                   dealii::ParameterHandler::Description);
            }
          return 0;
        }
      if (arg == "--set")
        {
          if (i + 1 >= argc)
            {
              if (root)
                std::cerr << "pneuma: --set needs \"Path/To/Entry=value\"\n";
              return pneuma::bad_input;
            }
          overrides.emplace_back(argv[++i]);
          continue;
        }
      if (!arg.empty() && arg[0] == '-')
        {
          if (root)
            std::cerr << "pneuma: unknown option '" << arg
                      << "' (see pneuma --help)\n";
          return pneuma::bad_input;
        }
      if (!file.empty())
        {
          if (root)
            std::cerr << "pneuma: more than one parameter file given\n";
          return pneuma::bad_input;
        }
      file = arg;
    }
  if (file.empty())
    {
      if (root)
        print_usage(std::cerr);
      return pneuma::bad_input;
    }

  int exit_code = pneuma::success;
  try
    {
      dealii::ParameterHandler prm;
      pneuma::read_parameters(prm, file, overrides);
      // The simulator is destroyed only after its errors are handled, so
      // no destructor ever runs with an exception in flight.
      pneuma::Simulator simulator(comm);
      try
        {
          simulator.parse_parameters(prm);
          simulator.setup();
          // Keep a copy of the parameters as used.
          prm.enter_subsection("Output");
          const std::string dir = prm.get("Directory");
          prm.leave_subsection();
          if (root)
            {
              std::filesystem::create_directories(dir);
              std::ofstream copy(dir + "/parameters.prm");
              prm.print_parameters(copy, dealii::ParameterHandler::ShortText);
            }
          const pneuma::RunSummary summary = simulator.run();
          exit_code                        = summary.exit_code;
          if (root && exit_code != pneuma::success)
            std::cerr << "pneuma: " << summary.message << std::endl;
          if (root)
            for (unsigned int m = 0; m < summary.monitor_displacements.size();
                 ++m)
              {
                const auto &x = summary.monitor_positions[m];
                const auto &u = summary.monitor_displacements[m];
                std::cout << "monitor " << m << " at (" << x[0] << ", " << x[1]
                          << ", " << x[2] << "): u = (" << u[0] << ", " << u[1]
                          << ", " << u[2] << ") m" << std::endl;
              }
          if (root && exit_code == pneuma::success)
            std::cout << "pneuma: finished, " << summary.n_steps << " steps, "
                      << summary.n_newton_iterations << " Newton iterations, "
                      << summary.wall_seconds << " s" << std::endl;
        }
      catch (const pneuma::InputError &e)
        {
          if (root)
            std::cerr << "pneuma: error in " << e.what() << std::endl;
          exit_code = pneuma::bad_input;
        }
    }
  catch (const pneuma::InputError &e)
    {
      if (root)
        std::cerr << "pneuma: error in " << e.what() << std::endl;
      exit_code = pneuma::bad_input;
    }
  catch (const std::exception &e)
    {
      std::cerr << "pneuma (rank "
                << dealii::Utilities::MPI::this_mpi_process(comm)
                << "): internal error: " << e.what() << std::endl;
      MPI_Abort(comm, 3);
    }
  return exit_code;
}
