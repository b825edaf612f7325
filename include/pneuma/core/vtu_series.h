#pragma once

/**
 * @file
 * A time series of VTU files and its PVD record, ParaView's collection of
 * (time, file) pairs (doc/user-guide.md "Outputs"): the membrane's
 * `solution.pvd` over its `solution_NNNN.pvtu` files, the cables'
 * `cables.pvd` over one `cables_<k>_NNNN.vtu` per cable ("part") and
 * step, and any later mesh's. The records survive a restart in the
 * checkpoint; a file written again (the final state with its modes) keeps
 * one record.
 */

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <string>
#include <utility>
#include <vector>

namespace pneuma
{
  /// The records of one series, `<name>.pvd`.
  class VtuSeries
  {
  public:
    explicit VtuSeries(const std::string &name = "")
      : series(name)
    {
    }

    /// The series' name (its .pvd file without the extension).
    const std::string &
    name() const
    {
      return series;
    }

    /// `<name>[_<part + 1>]_NNNN` of step @p step: the file name without
    /// extension of a part of the series (one part: no part number).
    std::string
    file_name(const unsigned int step,
              const unsigned int part    = 0,
              const unsigned int n_parts = 1) const;

    /**
     * Record that @p file (relative to the output directory) holds part
     * @p part of the state at time @p t of step @p step (parts in order);
     * part 0 of step 0 starts the series anew, a file already recorded is
     * not recorded again.
     */
    void
    add(const unsigned int step,
        const double       t,
        const std::string &file,
        const unsigned int part = 0);

    /// Write `<directory>/<name>.pvd` (the caller chooses the rank);
    /// false if the file could not be written.
    bool
    write_pvd(const std::string &directory) const;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &series &records;
    }

  private:
    struct Record
    {
      double       time = 0.;
      std::string  file;
      unsigned int part = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &time &file &part;
      }
    };
    std::string         series;
    std::vector<Record> records;
  };
} // namespace pneuma
