#pragma once

/**
 * @file
 * Checkpoint and restart (doc/user-guide.md "Checkpoint and restart").
 *
 * A checkpoint is a directory with
 * - the membrane mesh and its displacement field, saved by p4est through
 *   deal.II (parallel::distributed::Triangulation::save() with a
 *   SolutionTransfer attached), so a restart may use another number of
 *   MPI ranks;
 * - `state.bin`: named sections of replicated or gathered state, each
 *   serialized with deal.II's Utilities::pack (boost serialization): the
 *   other subsystems' field values, the border unknowns, the chambers'
 *   gas state, the friction anchors, the cables' section rotations, the
 *   load path (time, increment, counters, Bergan's reference), the output
 *   records (history rows, the .pvd lists). Rank 0 writes it and reads it;
 *   every rank gets a copy.
 *
 * A new checkpoint is written into `checkpoint.new` and then renamed over
 * the previous one, so that a run killed while writing leaves the last
 * complete checkpoint.
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pneuma
{
  /// Named sections of the state of a run at a converged step.
  class Checkpoint
  {
  public:
    /// A checkpoint that writes into (or was read from) @p directory.
    explicit Checkpoint(const std::string &directory = "")
      : path(directory)
    {
    }

    /// The directory of the checkpoint's files (p4est's mesh files).
    const std::string &
    directory() const
    {
      return path;
    }

    /// Store @p value (anything boost can serialize) under @p name.
    template <typename T>
    void
    put(const std::string &name, const T &value)
    {
      sections[name] = dealii::Utilities::pack(value, false);
    }

    /// The value stored under @p name; an InputError naming the restart
    /// directory if there is none (a checkpoint of another scene).
    template <typename T>
    T
    get(const std::string &name) const
    {
      return dealii::Utilities::unpack<T>(section(name), false);
    }

    /// Write state.bin on rank 0 (all ranks call it); throws WriteError on
    /// every rank if the write failed.
    void
    write_state(const MPI_Comm comm) const;

    /// Read state.bin on rank 0 and give every rank a copy; throws an
    /// InputError naming the directory if it is missing or damaged.
    void
    read_state(const MPI_Comm comm);

  private:
    const std::vector<char> &
    section(const std::string &name) const;

    std::string                              path;
    std::map<std::string, std::vector<char>> sections;
  };

  /// The "Checkpoint" subsection: when checkpoints are written.
  class CheckpointPolicy
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Is a checkpoint due after converged step @p step, @p minutes of
    /// wall time after the last one (or the start)?
    bool
    due(const unsigned int step, const double minutes) const
    {
      return (steps > 0 && step % steps == 0)
             || (interval_minutes > 0. && minutes >= interval_minutes)
             || (stop_step > 0 && step == stop_step);
    }

    /// Stop the run after this converged step (0: never).
    unsigned int
    stop_after() const
    {
      return stop_step;
    }

    bool
    enabled() const
    {
      return steps > 0 || interval_minutes > 0. || stop_step > 0;
    }

  private:
    unsigned int steps            = 0;
    double       interval_minutes = 0.;
    unsigned int stop_step        = 0;
  };

  /**
   * Write a checkpoint: @p fill stores the sections and saves the mesh
   * files into the directory it is given (collectively); the new directory
   * then replaces @p directory. Throws WriteError naming @p directory if
   * any rank failed.
   */
  void
  write_checkpoint(const std::string                       &directory,
                   const MPI_Comm                           comm,
                   const std::function<void(Checkpoint &)> &fill);
} // namespace pneuma
