#pragma once

/**
 * @file
 * One table of the named quantities a run reports. Every subsystem adds its
 * values (with units) to a Statistics row at each converged step and at
 * the end; history.csv, summary.json and the regression-test output are
 * all written from such rows (core/output.h), so a quantity is named once.
 *
 * A value belongs to a group: the run itself (no prefix), or one instance
 * of a repeated thing, e.g. chamber 2 ("c2_pressure [Pa]" in history.csv,
 * `"chambers": [{"chamber": 2, "pressure": ...}]` in summary.json). Values
 * may be vectors of three components (CSV columns `<name>x`, `<name>y`,
 * `<name>z`; a JSON array). Each value says how its parts on the MPI ranks
 * combine (reduce()), so no caller packs MPI buffers by hand.
 */

#include <deal.II/base/mpi.h>

#include <array>
#include <string>
#include <vector>

namespace pneuma
{
  /// A group of statistics: the run, or instance @p index of a family.
  struct StatisticsGroup
  {
    /// Column prefix in history.csv ("c" gives c1_pressure); empty: run.
    std::string prefix;
    /// Array name in summary.json ("chambers"); empty: top level.
    std::string array;
    /// Name of the instance number in summary.json ("chamber").
    std::string index_key;
    /// Instance number as the user counts it (Chamber 1 is 1).
    unsigned int index = 0;

    /// The run itself.
    static StatisticsGroup
    run()
    {
      return {};
    }
  };

  /// A table row of named values with units.
  class Statistics
  {
  public:
    /// @p summary_row: the row of summary.json (subsystems add their
    /// summary-only values, which may cost an assembly, only to it).
    explicit Statistics(const bool summary_row = false)
      : summary_row(summary_row)
    {
    }

    /// True for the row of summary.json.
    bool
    is_summary() const
    {
      return summary_row;
    }

    /// Where a value is written (a bit mask).
    enum Use : unsigned int
    {
      history = 1, ///< a column of history.csv
      summary = 2, ///< an entry of summary.json
      test    = 4, ///< a line of the regression-test output
      /// history.csv and summary.json.
      report = history | summary,
      all    = history | summary | test
    };

    /// How the parts of a value on the MPI ranks combine in reduce().
    enum class Reduction
    {
      same, ///< every rank has the value already
      sum,  ///< each rank holds its part
      max,
      min,
      root ///< only rank 0 has it
    };

    /// One named value.
    struct Entry
    {
      StatisticsGroup     group;
      std::string         name;
      std::string         unit;   ///< SI unit, empty for counts and ratios
      std::vector<double> values; ///< one or three components
      bool                integer   = false;
      unsigned int        uses      = all;
      Reduction           reduction = Reduction::same;

      /// history.csv column of component @p c ("c1_pressure").
      std::string
      column(const unsigned int c = 0) const;
      /// The column with its unit ("c1_pressure [Pa]").
      std::string
      header(const unsigned int c = 0) const;
    };

    /// Add a scalar.
    void
    add(const StatisticsGroup &group,
        const std::string     &name,
        const std::string     &unit,
        const double           value,
        const unsigned int     uses      = all,
        const Reduction        reduction = Reduction::same);

    /// Add a count (printed as an integer).
    void
    add_count(const StatisticsGroup &group,
              const std::string     &name,
              const double           value,
              const unsigned int     uses      = all,
              const Reduction        reduction = Reduction::same);

    /// Add a vector of three components.
    void
    add_vector(const StatisticsGroup       &group,
               const std::string           &name,
               const std::string           &unit,
               const std::array<double, 3> &value,
               const unsigned int           uses      = all,
               const Reduction              reduction = Reduction::same);

    /// Combine the ranks' parts: afterwards every rank has every value.
    void
    reduce(const MPI_Comm comm);

    /// Every entry, in the order added.
    const std::vector<Entry> &
    entries() const
    {
      return table;
    }

    /// True if @p column (e.g. "c1_pressure", "m0_ux") exists.
    bool
    has(const std::string &column) const;

    /// The value of @p column; throws if there is none.
    double
    get(const std::string &column) const;

    /// The three components of vector @p column ("cable1_start_reaction").
    std::array<double, 3>
    get_vector(const std::string &column) const;

  private:
    bool               summary_row;
    std::vector<Entry> table;
  };
} // namespace pneuma
