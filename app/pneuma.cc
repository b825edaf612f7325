/**
 * @file
 * The pneuma main program: reads a parameter file, runs the simulation and
 * maps every outcome to an exit code (0 success, 1 bad input, 2 solver
 * failure after cut-backs with the last converged state written).
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/interrupt.h>
#include <pneuma/core/mpi_start.h>
#include <pneuma/core/output.h>
#include <pneuma/core/threads.h>
#include <pneuma/simulator/simulator.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "pneuma: inflatable membrane structures (deal.II)\n\n"
        << "Usage:\n"
        << "  pneuma FILE.prm [--set \"Path/To/Entry=value\"]... "
           "[--restart DIR]\n"
        << "  mpirun -np N pneuma FILE.prm\n"
        << "  pneuma --print-parameters        every parameter with default, "
           "pattern and doc\n"
        << "  pneuma --print-parameters-json   the same as JSON (for tools)\n"
        << "  pneuma --help\n\n"
        << "  --restart DIR continues the run of the checkpoint in DIR "
           "(Output/Directory/checkpoint)\n\n"
        << "Exit codes: 0 success, 1 bad input, 2 solver failure "
           "(last converged state written), 130/143 stopped by SIGINT/"
           "SIGTERM (checkpoint written).\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  // Destroyed after MPI_Finalize (mpi's destructor).
  const pneuma::MpiStart                   mpi_start;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  pneuma::set_thread_counts(comm);

  std::string              file;
  std::vector<std::string> overrides;
  std::string              restart;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
        {
          if (root)
            print_usage(std::cout);
          return 0;
        }
      if (arg == "--print-parameters" || arg == "--print-parameters-json")
        {
          // One template of each repeated subsection, every variant.
          const auto        layout = pneuma::InputLayout::template_layout();
          pneuma::Simulator simulator(comm, layout);
          dealii::ParameterHandler prm;
          simulator.declare_parameters(prm);
          if (root)
            {
              if (arg == "--print-parameters-json")
                prm.print_parameters(std::cout, dealii::ParameterHandler::JSON);
              else
                prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
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
      if (arg == "--restart")
        {
          if (i + 1 >= argc)
            {
              if (root)
                std::cerr << "pneuma: --restart needs a checkpoint "
                             "directory\n";
              return pneuma::bad_input;
            }
          restart = argv[++i];
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

  pneuma::install_interrupt_handlers();
  int exit_code = pneuma::success;
  try
    {
      // Phase 1, before any work: read, declare, parse, set up. An input
      // error on any rank is agreed on by all (no rank waits for ever) and
      // reported once.
      std::unique_ptr<pneuma::Simulator> simulator;
      std::string                        error, output_directory;
      try
        {
          // What the input uses decides what is declared.
          const auto layout = pneuma::InputLayout::read(file, overrides);
          simulator         = std::make_unique<pneuma::Simulator>(comm, layout);
          dealii::ParameterHandler prm;
          simulator->declare_parameters(prm);
          pneuma::parse_input(prm, file, overrides);
          simulator->parse_parameters(prm);
          if (!restart.empty())
            simulator->restart_from(restart);
          simulator->setup();
          // Keep a copy of the parameters as used.
          prm.enter_subsection("Output");
          output_directory = prm.get("Directory");
          prm.leave_subsection();
          if (root)
            {
              std::filesystem::create_directories(output_directory);
              std::ofstream copy(output_directory + "/parameters.prm");
              prm.print_parameters(copy, dealii::ParameterHandler::ShortText);
            }
        }
      catch (const pneuma::InputError &e)
        {
          error = e.what();
        }
      error = pneuma::agree_on_error(comm, error, pneuma::bad_input);
      if (!error.empty())
        {
          if (root)
            std::cerr << "pneuma: error in " << error << std::endl;
          return pneuma::bad_input;
        }

      // Phase 2: the run (an input error can still show in the reference
      // state, e.g. chamber walls that face inward).
      pneuma::RunResult result;
      try
        {
          result = simulator->run();
        }
      catch (const pneuma::InputError &e)
        {
          error = e.what();
        }
      error = pneuma::agree_on_error(comm, error, pneuma::bad_input);
      if (!error.empty())
        {
          // No output of the run is left, but a summary.json that records
          // the error (a restart's files continue its checkpoint's run).
          if (root)
            {
              pneuma::record_input_error(output_directory,
                                         error,
                                         restart.empty());
              std::cerr << "pneuma: error in " << error << std::endl;
            }
          return pneuma::bad_input;
        }
      exit_code = result.exit_code;
      if (root && exit_code != pneuma::success)
        std::cerr << "pneuma: " << result.message << std::endl;
      const auto &summary = result.summary;
      if (root)
        for (unsigned int m = 0; summary.has("m" + std::to_string(m) + "_u");
             ++m)
          {
            const std::string key = "m" + std::to_string(m);
            const auto        x   = summary.get_vector(key + "_position");
            const auto        u   = summary.get_vector(key + "_u");
            std::cout << "monitor " << m << " at (" << x[0] << ", " << x[1]
                      << ", " << x[2] << "): u = (" << u[0] << ", " << u[1]
                      << ", " << u[2] << ") m" << std::endl;
          }
      if (root && exit_code == pneuma::success && !result.message.empty())
        std::cout << "pneuma: " << result.message << std::endl;
      if (root && exit_code == pneuma::success)
        std::cout << "pneuma: finished, " << summary.get("steps") << " steps, "
                  << summary.get("newton_iterations") << " Newton iterations, "
                  << summary.get("wall_seconds") << " s" << std::endl;
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
