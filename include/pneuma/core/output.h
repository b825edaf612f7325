#pragma once

/**
 * @file
 * The files of a run (doc/user-guide.md "Outputs"), all written from
 * Statistics rows (core/statistics.h): history.csv (one row per converged
 * step, columns "name [unit]"), summary.json (the final row, grouped:
 * top-level values, then "chambers", "cables", ... arrays, a "units" map,
 * the timings), and the regression-test output "output" (the entries
 * marked for tests, at fixed precision, round-off zeros printed as 0).
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <pneuma/core/statistics.h>

#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pneuma
{
  /// An output of the run that was not written: the run stops with exit
  /// code 2 and the message.
  class OutputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A file of the run could not be written (full disk, removed
  /// directory); the message names it.
  class WriteError : public OutputError
  {
  public:
    explicit WriteError(const std::string &file)
      : OutputError("cannot write '" + file
                    + "' (is the disk full or the directory gone?)")
    {
    }
  };

  /// A state that is not finite was to be written (it is not: NaN and inf
  /// are never written); thrown on every rank alike.
  class NonFiniteOutput : public OutputError
  {
  public:
    explicit NonFiniteOutput(const std::string &what)
      : OutputError(what)
    {
    }
  };

  /**
   * After an input error found once the run had started (rank 0): remove
   * the files of the run in @p directory if @p remove_outputs (a fresh
   * run's: history.csv, parameters.prm, the VTU and .pvd series,
   * refinement.csv, cycle-*, checkpoint/, as OutputWriter::prepare() does
   * before a run; a restart's continue its checkpoint's run and stay),
   * and write summary.json with exit_code 1 and @p message. Nothing if
   * @p directory does not exist.
   */
  void
  record_input_error(const std::string &directory,
                     const std::string &message,
                     const bool         remove_outputs);

  /// The "Output" subsection and the writers of history and summary.
  class OutputWriter
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// Create the directory and check that it can be written (all ranks
    /// agree); throws InputError naming Output/Directory if not.
    void
    check_directory(const MPI_Comm comm) const;

    /// Check the directory, remove the files of an earlier run there
    /// (solution_*, cables_*, the .pvd records, history.csv, summary.json,
    /// checkpoint/,
    /// refinement.csv, cycle-*/) and start history.csv.
    void
    prepare(const MPI_Comm comm);

    /**
     * Continue the run of a checkpoint at @p step: history.csv is
     * @p history_so_far (its rows up to that step), the VTU files of later
     * steps and summary.json of the earlier run go.
     */
    void
    prepare_restart(const MPI_Comm     comm,
                    const unsigned int step,
                    const std::string &history_so_far);
    /// Everything history.csv holds so far (rank 0), for a checkpoint.
    const std::string &
    history_so_far() const
    {
      return history_text;
    }
    /// Append a row to history.csv (the first row writes the header).
    void
    history_row(const Statistics &row);

    /// Write summary.json from @p row (with @p message after the exit code
    /// and @p timer's sections at the end).
    void
    summary(const Statistics          &row,
            const std::string         &message,
            const dealii::TimerOutput &timer) const;

    /// Write refinement.csv: one row per adaptive refinement cycle of the
    /// test-level values of its @p summaries (rank 0).
    void
    refinement_table(const MPI_Comm                 comm,
                     const std::vector<Statistics> &summaries) const;

    /// Write the regression-test output "output" in the working directory
    /// if Output/Test output is set.
    void
    test_output(const Statistics &row) const;

    const std::string &
    directory() const
    {
      return output_directory;
    }
    void
    set_directory(const std::string &d)
    {
      output_directory = d;
    }
    bool
    write_vtu() const
    {
      return vtu;
    }
    unsigned int
    vtu_interval() const
    {
      return interval;
    }
    bool
    quiet() const
    {
      return be_quiet;
    }

  private:
    /// Start history.csv with @p text (its rows so far; empty: none) and
    /// check on every rank that it could be opened.
    void
    start_history(const MPI_Comm comm, const std::string &text);

    std::string                    output_directory = "output";
    bool                           vtu              = true;
    unsigned int                   interval         = 1;
    bool                           be_quiet         = false;
    bool                           test             = false;
    bool                           root             = true;
    std::unique_ptr<std::ofstream> history;
    unsigned int                   history_columns = 0;
    std::string                    history_text;
    bool                           header_written = false;
  };
} // namespace pneuma
