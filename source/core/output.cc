#include <deal.II/base/mpi.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/output.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>

namespace pneuma
{
  using namespace dealii;

  namespace
  {
    /// summary.json's writer (nlohmann's JSON for Modern C++, Debian's
    /// nlohmann-json3-dev), keeping the entries in the order added.
    using Json = nlohmann::ordered_json;

    /// A number as summary.json keeps it: integers exact, other values to
    /// 10 significant digits; non-finite values become null.
    Json
    json_number(const double v, const bool integer)
    {
      if (!std::isfinite(v))
        return nullptr;
      if (integer)
        return static_cast<long long>(std::llround(v));
      char text[32];
      std::snprintf(text, sizeof(text), "%.10g", v);
      return std::strtod(text, nullptr);
    }

    Json
    json_value(const Statistics::Entry &e)
    {
      if (e.values.size() == 1)
        return json_number(e.values[0], e.integer);
      Json array = Json::array();
      for (const double v : e.values)
        array.push_back(json_number(v, e.integer));
      return array;
    }

    /// Write @p j to @p file; false if the write failed. Invalid UTF-8
    /// in a message (a file name) is replaced, never an exception.
    bool
    write_json(const std::string &file, const Json &j)
    {
      std::ofstream out(file);
      out << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
      out.flush();
      return static_cast<bool>(out);
    }
    /**
     * Remove the files a run writes into @p directory (solution_*,
     * cables_*, the .pvd records, history.csv, summary.json,
     * refinement.csv, cycle-*, checkpoint/).
     */
    void
    remove_run_outputs(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      // Every VTU series (core/vtu_series.h): <name>[_<part>]_NNNN files
      // and <name>.pvd.
      static const std::regex files(
        "[A-Za-z0-9]+(_[0-9]+)?_[0-9]{4}(\\.[0-9]+)?\\.(vtu|pvtu)|"
        "[A-Za-z0-9]+\\.pvd|"
        "history\\.csv|summary\\.json|refinement\\.csv");
      static const std::regex folders(
        "cycle-[0-9]+|checkpoint(\\.new|\\.old)?");
      for (const auto &entry : fs::directory_iterator(directory, ec))
        {
          const std::string name = entry.path().filename().string();
          const bool        ours =
            (entry.is_regular_file(ec) && std::regex_match(name, files))
            || (entry.is_directory(ec) && std::regex_match(name, folders));
          if (ours)
            fs::remove_all(entry.path(), ec);
        }
    }
  } // namespace

  void
  record_input_error(const std::string &directory,
                     const std::string &message,
                     const bool         remove_outputs)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (directory.empty() || !fs::is_directory(directory, ec))
      return;
    if (remove_outputs)
      {
        remove_run_outputs(directory);
        fs::remove(directory + "/parameters.prm", ec);
      }
    Json j;
    j["exit_code"] = 1;
    j["message"]   = message;
    write_json(directory + "/summary.json", j);
  }

  void
  OutputWriter::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.add_parameter("Directory",
                      output_directory,
                      "Where solution.pvd, history.csv, summary.json and "
                      "parameters.prm are written (created if missing).",
                      Patterns::Anything());
    prm.add_parameter("Write VTU",
                      vtu,
                      "Write solution-NNNN.pvtu/.vtu and solution.pvd.");
    prm.add_parameter("VTU interval",
                      interval,
                      "Write VTU every this many converged steps (0: only "
                      "the initial and final states).",
                      Patterns::Integer(0));
    prm.add_parameter("Quiet",
                      be_quiet,
                      "Print nothing while running (tests, scripted "
                      "studies).");
    prm.add_parameter("Test output",
                      test,
                      "Also write a file 'output' in the working directory "
                      "with physics-level numbers at fixed precision (used "
                      "by the regression tests).");
    prm.leave_subsection();
  }

  void
  OutputWriter::parse_parameters(ParameterHandler &)
  {
    check_input(!output_directory.empty(),
                "Output/Directory",
                "must not be empty");
  }

  void
  OutputWriter::check_directory(const MPI_Comm comm) const
  {
    // Rank 0 creates the directory and writes a probe file; every rank
    // learns the outcome (no rank is left waiting).
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::create_directories(output_directory, ec);
        const std::string probe = output_directory + "/.pneuma-write-test";
        {
          std::ofstream out(probe);
          out << "pneuma\n";
          out.flush();
          if (!fs::is_directory(output_directory, ec) || !out)
            error =
              "Output/Directory: cannot write into '" + output_directory + "'";
        }
        fs::remove(probe, ec);
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  void
  OutputWriter::prepare(const MPI_Comm comm)
  {
    root = Utilities::MPI::this_mpi_process(comm) == 0;
    check_directory(comm);
    if (root)
      {
        // The files of an earlier run into this directory go, so that no
        // file series mixes two runs (doc/user-guide.md "Outputs").
        remove_run_outputs(output_directory);
      }
    start_history(comm, "");
  }

  void
  OutputWriter::start_history(const MPI_Comm comm, const std::string &text)
  {
    if (root)
      {
        history =
          std::make_unique<std::ofstream>(output_directory + "/history.csv");
        *history << text << std::flush;
      }
    bool ok = !root || static_cast<bool>(*history);
    ok      = Utilities::MPI::broadcast(comm, ok, 0);
    check_input(ok,
                "Output/Directory",
                "cannot write into '" + output_directory + "'");
    history_text    = text;
    history_columns = 0;
    header_written  = !text.empty();
  }

  void
  OutputWriter::history_row(const Statistics &row)
  {
    if (!history)
      return;
    std::vector<const Statistics::Entry *> columns;
    for (const auto &e : row.entries())
      if (e.uses & Statistics::history)
        columns.push_back(&e);
    std::ostringstream line;
    if (history_columns == 0 && header_written)
      history_columns = columns.size(); // a restart: the header is there
    if (history_columns == 0)
      {
        bool first = true;
        for (const auto *e : columns)
          for (unsigned int c = 0; c < e->values.size(); ++c)
            {
              line << (first ? "" : ",") << e->header(c);
              first = false;
            }
        line << "\n";
        history_columns = columns.size();
        header_written  = true;
      }
    AssertThrow(columns.size() == history_columns,
                ExcMessage("history.csv: the columns changed during the run"));
    bool first = true;
    for (const auto *e : columns)
      for (const double v : e->values)
        {
          line << (first ? "" : ",");
          first = false;
          if (!std::isfinite(v))
            ; // an empty field: never "nan" or "inf" in the file
          else if (e->integer)
            line << static_cast<long long>(std::llround(v));
          else
            line << std::setprecision(e->name == "wall_seconds" ? 4 : 10) << v;
        }
    line << "\n";
    history_text += line.str();
    *history << line.str() << std::flush;
    if (!*history)
      throw WriteError(output_directory + "/history.csv");
  }

  void
  OutputWriter::prepare_restart(const MPI_Comm     comm,
                                const unsigned int step,
                                const std::string &history_so_far)
  {
    root = Utilities::MPI::this_mpi_process(comm) == 0;
    check_directory(comm);
    if (root)
      {
        // Files of steps after the checkpoint's (a run that went on past
        // it) and the earlier summary go; the rest continues.
        namespace fs = std::filesystem;
        std::error_code         ec;
        static const std::regex files(
          "[A-Za-z0-9]+(?:_[0-9]+)?_([0-9]{4})(?:\\.[0-9]+)?\\.(?:vtu|pvtu)");
        for (const auto &entry : fs::directory_iterator(output_directory, ec))
          {
            std::smatch       match;
            const std::string name = entry.path().filename().string();
            if (entry.is_regular_file(ec)
                && std::regex_match(name, match, files)
                && std::stoul(match[1].str()) > step)
              fs::remove(entry.path(), ec);
          }
        fs::remove(output_directory + "/summary.json", ec);
      }
    start_history(comm, history_so_far);
  }

  namespace
  {
    /// The entries of group @p array, one object per index.
    Json
    summary_array(const Statistics &row, const std::string &array)
    {
      std::map<unsigned int, std::vector<const Statistics::Entry *>> items;
      std::string                                                    index_key;
      for (const auto &e : row.entries())
        if ((e.uses & Statistics::summary) && e.group.array == array)
          {
            items[e.group.index].push_back(&e);
            index_key = e.group.index_key;
          }
      Json list = Json::array();
      for (const auto &[index, entries] : items)
        {
          Json item;
          item[index_key] = index;
          for (const auto *e : entries)
            item[e->name] = json_value(*e);
          list.push_back(item);
        }
      return list;
    }
  } // namespace

  void
  OutputWriter::summary(const Statistics  &row,
                        const std::string &message,
                        const TimerOutput &timer) const
  {
    if (!root)
      return;
    Json j = Json::object();
    // Top-level values, then one array per group, in the order added.
    std::vector<std::string> arrays;
    for (const auto &e : row.entries())
      {
        if (!(e.uses & Statistics::summary))
          continue;
        if (e.group.array.empty())
          {
            j[e.name] = json_value(e);
            if (e.name == "exit_code")
              j["message"] = message;
          }
        else if (std::find(arrays.begin(), arrays.end(), e.group.array)
                 == arrays.end())
          arrays.push_back(e.group.array);
      }
    for (const auto &array : arrays)
      j[array] = summary_array(row, array);
    // Units of every value that has one.
    std::map<std::string, std::string> units;
    for (const auto &e : row.entries())
      if ((e.uses & Statistics::summary) && !e.unit.empty())
        units[e.group.array.empty() ? e.name : e.group.array + "." + e.name] =
          e.unit;
    j["units"]   = Json(units);
    Json timings = Json::object();
    for (const auto &[name, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      timings[name] = json_number(seconds, false);
    j["timings"] = timings;
    if (!write_json(output_directory + "/summary.json", j))
      throw WriteError(output_directory + "/summary.json");
  }

  void
  OutputWriter::refinement_table(const MPI_Comm                 comm,
                                 const std::vector<Statistics> &summaries) const
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0 || summaries.empty())
      return;
    std::ofstream table(output_directory + "/refinement.csv");
    table << "cycle";
    for (const auto &e : summaries[0].entries())
      if (e.uses & Statistics::test)
        for (unsigned int c = 0; c < e.values.size(); ++c)
          table << "," << e.header(c);
    table << "\n" << std::setprecision(10);
    for (unsigned int k = 0; k < summaries.size(); ++k)
      {
        table << k;
        for (const auto &e : summaries[k].entries())
          if (e.uses & Statistics::test)
            for (const double v : e.values)
              table << "," << v;
        table << "\n";
      }
  }

  void
  OutputWriter::test_output(const Statistics &row) const
  {
    if (!root || !test)
      return;
    // Round-off zeros: a component below 1e-9 of the largest value of the
    // same quantity in its group family prints as 0 (no spurious digits of
    // values that are zero up to round-off, e.g. on 1 and 2 ranks).
    std::map<std::string, double> scale;
    for (const auto &e : row.entries())
      if (e.uses & Statistics::test)
        for (const double v : e.values)
          {
            double &s = scale[e.group.array + "/" + e.name];
            s         = std::max(s, std::abs(v));
          }
    const auto number = [&](const Statistics::Entry &e, const double v) {
      char buffer[64];
      if (e.integer)
        std::snprintf(buffer, sizeof(buffer), "%lld", std::llround(v));
      else
        std::snprintf(buffer,
                      sizeof(buffer),
                      "%.4e",
                      std::abs(v) < 1e-9 * scale[e.group.array + "/" + e.name]
                        ? 0.
                        : v);
      return std::string(buffer);
    };
    std::ofstream out("output");
    // Run-level values one per line, then one line per group instance.
    std::vector<std::pair<std::string, unsigned int>> instances;
    for (const auto &e : row.entries())
      {
        if (!(e.uses & Statistics::test))
          continue;
        if (e.group.array.empty())
          {
            out << e.name;
            for (const double v : e.values)
              out << " " << number(e, v);
            out << "\n";
          }
        else if (std::find(instances.begin(),
                           instances.end(),
                           std::make_pair(e.group.array, e.group.index))
                 == instances.end())
          instances.emplace_back(e.group.array, e.group.index);
      }
    for (const auto &[array, index] : instances)
      {
        bool first = true;
        for (const auto &e : row.entries())
          if ((e.uses & Statistics::test) && e.group.array == array
              && e.group.index == index)
            {
              if (first)
                out << e.group.index_key << " " << index << ":";
              out << (first ? " " : ", ") << e.name << " =";
              for (const double v : e.values)
                out << " " << number(e, v);
              first = false;
            }
        out << "\n";
      }
  }
} // namespace pneuma
