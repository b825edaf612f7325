#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <pneuma/core/reproducible_output.h>
#include <pneuma/core/vtu_series.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace pneuma
{
  std::string
  VtuSeries::file_name(const unsigned int step,
                       const unsigned int part,
                       const unsigned int n_parts) const
  {
    return series + (n_parts > 1 ? "_" + std::to_string(part + 1) : "") + "_"
           + dealii::Utilities::int_to_string(step, 4);
  }

  void
  VtuSeries::add(const unsigned int step,
                 const double       t,
                 const std::string &file,
                 const unsigned int part)
  {
    if (step == 0 && part == 0)
      records.clear();
    if (std::none_of(records.begin(), records.end(), [&](const Record &r) {
          return r.file == file;
        }))
      records.push_back({t, file, part});
  }

  bool
  VtuSeries::write_pvd(const std::string &directory) const
  {
    std::ostringstream pvd;
    const bool         parts = std::any_of(records.begin(),
                                   records.end(),
                                   [](const Record &r) { return r.part > 0; });
    if (!parts)
      {
        // deal.II's writer (one dataset per time).
        std::vector<std::pair<double, std::string>> times;
        for (const auto &r : records)
          times.emplace_back(r.time, r.file);
        dealii::DataOutBase::write_pvd_record(pvd, times);
      }
    else
      {
        // Several datasets per time ("part"), which deal.II's writer does
        // not know.
        pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
               "version=\"0.1\">\n<Collection>\n";
        for (const auto &r : records)
          pvd << "  <DataSet timestep=\"" << r.time << "\" part=\"" << r.part
              << "\" file=\"" << r.file << "\"/>\n";
        pvd << "</Collection>\n</VTKFile>\n";
      }
    // deal.II's writer adds the date; a run repeated writes the same bytes.
    std::ofstream file(directory + "/" + series + ".pvd");
    file << without_date(pvd.str());
    file.flush();
    return static_cast<bool>(file);
  }
} // namespace pneuma
