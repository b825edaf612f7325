#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/output.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace pneuma
{
  using namespace dealii;

  namespace
  {
    /// First bytes of state.bin: the format and its version.
    const std::string magic = "pneuma-checkpoint-1";
  } // namespace

  const std::vector<char> &
  Checkpoint::section(const std::string &name) const
  {
    const auto it = sections.find(name);
    if (it == sections.end())
      throw InputError("--restart " + path,
                       "the checkpoint has no '" + name
                         + "' (it was written by another scene or version)");
    return it->second;
  }

  void
  Checkpoint::write_state(const MPI_Comm comm) const
  {
    bool ok = true;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream           out(path + "/state.bin", std::ios::binary);
        const std::vector<char> bytes = Utilities::pack(sections, false);
        const std::uint64_t     size  = bytes.size();
        out.write(magic.data(), magic.size());
        out.write(reinterpret_cast<const char *>(&size), sizeof(size));
        out.write(bytes.data(), bytes.size());
        out.close();
        ok = static_cast<bool>(out);
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(path + "/state.bin");
  }

  void
  Checkpoint::read_state(const MPI_Comm comm)
  {
    std::string       error;
    std::vector<char> bytes;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ifstream in(path + "/state.bin", std::ios::binary);
        std::string   head(magic.size(), '\0');
        std::uint64_t size = 0;
        if (!in)
          error = "cannot open '" + path
                  + "/state.bin' (is it a checkpoint directory?)";
        else if (!in.read(head.data(), head.size()) || head != magic
                 || !in.read(reinterpret_cast<char *>(&size), sizeof(size)))
          error = "'" + path + "/state.bin' is not a pneuma checkpoint";
        else
          {
            bytes.resize(size);
            if (!in.read(bytes.data(), size))
              error = "'" + path + "/state.bin' is truncated";
          }
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError("--restart " + path, error);
    bytes = Utilities::MPI::broadcast(comm, bytes, 0);
    sections =
      Utilities::unpack<std::map<std::string, std::vector<char>>>(bytes, false);
  }

  void
  CheckpointPolicy::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.add_parameter("Interval steps",
                      steps,
                      "Write a checkpoint (Output/Directory/checkpoint) "
                      "every this many converged steps (0: never). A run "
                      "stopped by SIGINT or SIGTERM always writes one.",
                      Patterns::Integer(0));
    prm.add_parameter("Interval minutes",
                      interval_minutes,
                      "Also write one when this much wall time has passed "
                      "since the last (0: never).",
                      Patterns::Double(0.));
    prm.add_parameter("Stop after step",
                      stop_step,
                      "Write a checkpoint after this converged step and "
                      "stop (exit 0; continue with --restart). 0: run to "
                      "the end.",
                      Patterns::Integer(0));
    prm.leave_subsection();
  }

  void
  CheckpointPolicy::parse_parameters(ParameterHandler &)
  {
    check_input(std::isfinite(interval_minutes),
                "Checkpoint/Interval minutes",
                "must be finite");
  }

  void
  write_checkpoint(const std::string                       &directory,
                   const MPI_Comm                           comm,
                   const std::function<void(Checkpoint &)> &fill)
  {
    namespace fs            = std::filesystem;
    const bool        root  = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string fresh = directory + ".new", old = directory + ".old";
    bool              ok = true;
    if (root)
      {
        std::error_code ec;
        fs::remove_all(fresh, ec);
        ok = fs::create_directories(fresh, ec) && !ec;
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(fresh);
    Checkpoint checkpoint(fresh);
    fill(checkpoint);
    checkpoint.write_state(comm);
    // The new checkpoint replaces the old one only when it is complete.
    if (root)
      {
        std::error_code ec;
        fs::remove_all(old, ec);
        if (fs::exists(directory, ec))
          fs::rename(directory, old, ec);
        fs::rename(fresh, directory, ec);
        ok = !ec;
        fs::remove_all(old, ec);
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(directory);
  }
} // namespace pneuma
