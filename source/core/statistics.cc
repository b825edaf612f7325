#include <deal.II/base/array_view.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <pneuma/core/statistics.h>

namespace pneuma
{
  using namespace dealii;

  std::string
  Statistics::Entry::column(const unsigned int c) const
  {
    std::string key;
    if (!group.prefix.empty())
      key = group.prefix + std::to_string(group.index) + "_";
    key += name;
    if (values.size() == 3)
      key += std::string("_") + "xyz"[c];
    return key;
  }

  std::string
  Statistics::Entry::header(const unsigned int c) const
  {
    return unit.empty() ? column(c) : column(c) + " [" + unit + "]";
  }

  void
  Statistics::add(const StatisticsGroup &group,
                  const std::string     &name,
                  const std::string     &unit,
                  const double           value,
                  const unsigned int     uses,
                  const Reduction        reduction)
  {
    table.push_back({group, name, unit, {value}, false, uses, reduction});
  }

  void
  Statistics::add_count(const StatisticsGroup &group,
                        const std::string     &name,
                        const double           value,
                        const unsigned int     uses,
                        const Reduction        reduction)
  {
    table.push_back({group, name, "", {value}, true, uses, reduction});
  }

  void
  Statistics::add_vector(const StatisticsGroup       &group,
                         const std::string           &name,
                         const std::string           &unit,
                         const std::array<double, 3> &value,
                         const unsigned int           uses,
                         const Reduction              reduction)
  {
    table.push_back({group,
                     name,
                     unit,
                     {value[0], value[1], value[2]},
                     false,
                     uses,
                     reduction});
  }

  void
  Statistics::reduce(const MPI_Comm comm)
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // One reduction per kind over all entries of that kind.
    for (const Reduction kind :
         {Reduction::sum, Reduction::max, Reduction::min, Reduction::root})
      {
        std::vector<double> values;
        for (const auto &e : table)
          if (e.reduction == kind)
            values.insert(values.end(), e.values.begin(), e.values.end());
        if (values.empty())
          continue;
        switch (kind)
          {
              case Reduction::sum: {
                auto in_ = values;
                Utilities::MPI::sum(ArrayView<const double>(in_),
                                    comm,
                                    ArrayView<double>(values));
              }
              break;
              case Reduction::max: {
                auto in_ = values;
                Utilities::MPI::max(ArrayView<const double>(in_),
                                    comm,
                                    ArrayView<double>(values));
              }
              break;
              case Reduction::min: {
                auto in_ = values;
                Utilities::MPI::min(ArrayView<const double>(in_),
                                    comm,
                                    ArrayView<double>(values));
              }
              break;
            default:
              values = Utilities::MPI::broadcast(comm, values, 0);
          }
        unsigned int k = 0;
        for (auto &e : table)
          if (e.reduction == kind)
            {
              for (auto &v : e.values)
                v = values[k++];
              e.reduction = Reduction::same;
            }
      }
  }

  bool
  Statistics::has(const std::string &column) const
  {
    for (const auto &e : table)
      if (e.column() == column
          || (e.values.size() == 3
              && e.column().substr(0, e.column().size() - 2) == column))
        return true;
    return false;
  }

  double
  Statistics::get(const std::string &column) const
  {
    for (const auto &e : table)
      for (unsigned int c = 0; c < e.values.size(); ++c)
        if (e.column(c) == column)
          return e.values[c];
    AssertThrow(false, ExcMessage("no statistic named '" + column + "'"));
    return 0.;
  }

  std::array<double, 3>
  Statistics::get_vector(const std::string &column) const
  {
    for (const auto &e : table)
      if (e.values.size() == 3 && e.column(0) == column + "_x")
        return {{e.values[0], e.values[1], e.values[2]}};
    AssertThrow(false,
                ExcMessage("no vector statistic named '" + column + "'"));
    return {{0., 0., 0.}};
  }
} // namespace pneuma
