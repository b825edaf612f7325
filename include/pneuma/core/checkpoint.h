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
 *   records (history rows, the .pvd lists), the parameters as used. Rank 0
 *   writes it and reads it; every rank gets a copy. Its layout (format 2,
 *   native byte order): the line "pneuma-checkpoint-2\n", the number of
 *   sections (uint64), then per section the length of its name (uint64),
 *   the name, the length of its value (uint64) and the value;
 * - `manifest`: the format line "pneuma checkpoint manifest, format 2",
 *   one line "<CRC32 in hex> <size in bytes> <file name>" for every other
 *   file of the directory, and "end <CRC32 of the lines before>".
 *
 * Before anything is restored, every rank checks every file the manifest
 * lists (present, of its size, of its CRC32) and rank 0 checks that every
 * length in state.bin fits in the file: a damaged, truncated or older
 * checkpoint is an InputError naming the file and what is wrong (exit 1),
 * never a crash or a run from another state.
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

#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace pneuma
{
  namespace internal
  {
    /// Nesting of std::vector around a trivially copyable element (not
    /// bool): the layouts Utilities::unpack copies without boost.
    template <typename T>
    struct VectorLayout
    {
      static constexpr int depth = 0;
      using element              = T;
    };
    template <typename T>
    struct VectorLayout<std::vector<T>>
    {
      static constexpr int depth =
        std::is_trivially_copyable<T>::value && !std::is_same<T, bool>::value
          ? 1
          : 0;
      using element = T;
    };
    template <typename T>
    struct VectorLayout<std::vector<std::vector<T>>>
    {
      static constexpr int depth =
        std::is_trivially_copyable<T>::value && !std::is_same<T, bool>::value
          ? 2
          : 0;
      using element = T;
    };

    /**
     * Does @p bytes hold a @p T as Utilities::unpack() reads it without
     * checking the size (release builds): a small trivially copyable
     * object of exactly its size, a vector (of vectors) of one whose
     * stored counts match the length? Everything else goes through boost,
     * which checks its reads against the buffer.
     */
    template <typename T>
    bool
    unpackable(const std::vector<char> &bytes)
    {
      using Element           = typename VectorLayout<T>::element;
      constexpr auto e        = sizeof(Element);
      std::uint64_t  n        = 0;
      const auto     count_at = [&](const std::size_t pos) {
        std::memcpy(&n, bytes.data() + pos, sizeof(n));
        return n;
      };
      if constexpr (std::is_trivially_copyable<T>::value && sizeof(T) < 256)
        return bytes.size() == sizeof(T);
      else if constexpr (VectorLayout<T>::depth == 1)
        return bytes.size() >= sizeof(n) && (bytes.size() - sizeof(n)) % e == 0
               && count_at(0) == (bytes.size() - sizeof(n)) / e;
      else if constexpr (VectorLayout<T>::depth == 2)
        {
          if (bytes.size() < sizeof(n)
              || count_at(0) > bytes.size() / sizeof(n) - 1)
            return false;
          const std::uint64_t outer = n;
          std::size_t         left  = bytes.size() - sizeof(n) * (outer + 1);
          for (std::uint64_t k = 0; k < outer; ++k)
            {
              if (count_at(sizeof(n) * (k + 1)) > left / e)
                return false;
              left -= n * e;
            }
          return left == 0;
        }
      else
        return true;
    }
  } // namespace internal

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
    /// directory if there is none (a checkpoint of another scene) or if
    /// it does not hold a @p T.
    template <typename T>
    T
    get(const std::string &name) const
    {
      const std::vector<char> &bytes = section(name);
      if (!internal::unpackable<T>(bytes))
        unreadable(name);
      try
        {
          return dealii::Utilities::unpack<T>(bytes, false);
        }
      catch (const std::exception &)
        {
          unreadable(name);
        }
    }

    /// Write state.bin on rank 0 (all ranks call it); throws WriteError on
    /// every rank if the write failed.
    void
    write_state(const MPI_Comm comm) const;

    /// Write the manifest of every file in the directory (rank 0; all
    /// ranks call it, after all files are written); throws WriteError on
    /// every rank if the write failed.
    void
    write_manifest(const MPI_Comm comm) const;

    /// Verify the checkpoint on every rank (the manifest and every file it
    /// lists), then read state.bin on rank 0 and give every rank a copy;
    /// throws the same InputError on every rank, naming the file and what
    /// is wrong, if anything is missing, damaged or of another format.
    void
    read_state(const MPI_Comm comm);

  private:
    const std::vector<char> &
    section(const std::string &name) const;

    /// Throw the InputError for a section that cannot be unpacked.
    [[noreturn]] void
    unreadable(const std::string &name) const;

    std::string                              path;
    std::map<std::string, std::vector<char>> sections;
  };

  /// The "Checkpoint" subsection: when checkpoints are written.
  class CheckpointPolicy
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm);
    /// Parse the subsection and keep every entry of @p prm (the whole
    /// input, as used), which each checkpoint stores for the restart's
    /// comparison (core/restart_check.h).
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Every entry of the input as used, "Path/To/Entry" -> value.
    const std::map<std::string, std::string> &
    parameters() const
    {
      return used;
    }

    /// write_checkpoint() with the parameters as used stored in it.
    void
    write(const std::string                       &directory,
          const MPI_Comm                           comm,
          const std::function<void(Checkpoint &)> &fill) const;

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
    unsigned int                       steps            = 0;
    double                             interval_minutes = 0.;
    unsigned int                       stop_step        = 0;
    std::map<std::string, std::string> used;
  };

  /**
   * Write a checkpoint: @p fill stores the sections and saves the mesh
   * files into the directory it is given (collectively); state.bin and
   * the manifest follow, and the new directory then replaces
   * @p directory. Throws WriteError naming @p directory if any rank
   * failed.
   */
  void
  write_checkpoint(const std::string                       &directory,
                   const MPI_Comm                           comm,
                   const std::function<void(Checkpoint &)> &fill);
} // namespace pneuma
