#include <pneuma/core/constraint_distribution.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_index_access.h>

#include <Epetra_FEVector.h>
#include <Epetra_Import.h>

namespace pneuma
{
  using namespace dealii;

  ConstraintDistribution::ConstraintDistribution() = default;

  ConstraintDistribution::~ConstraintDistribution() = default;

  void
  ConstraintDistribution::reinit(const AffineConstraints<double> &constraints,
                                 const IndexSet                  &owned,
                                 const MPI_Comm                   comm)
  {
    line_local.clear();
    inhomogeneity.clear();
    line_start.assign(1, 0);
    master_position.clear();
    weight.clear();
    importer.reset();
    this->constraints = &constraints;

    // The masters of the owned lines, owned or not.
    IndexSet needed(owned.size());
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        for (const auto &entry : line.entries)
          needed.add_index(entry.first);
    needed.add_indices(owned);
    needed.compress();
    buffer.reinit(owned, needed, comm);
    // The buffer's map holds the owned and the needed entries; the source
    // map is that of a vector made from @p owned alone.
    const LA::Vector source(owned, comm);
    importer = std::make_unique<Epetra_Import>(buffer.trilinos_vector().Map(),
                                               source.trilinos_vector().Map());
    const auto &buffer_map = buffer.trilinos_vector().Map();
    const auto &source_map = source.trilinos_vector().Map();
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          line_local.push_back(source_map.LID(
            static_cast<TrilinosWrappers::types::int_type>(line.index)));
          inhomogeneity.push_back(line.inhomogeneity);
          for (const auto &entry : line.entries)
            {
              master_position.push_back(buffer_map.LID(
                static_cast<TrilinosWrappers::types::int_type>(entry.first)));
              weight.push_back(entry.second);
            }
          line_start.push_back(static_cast<int>(master_position.size()));
        }
    any =
      Utilities::MPI::max(static_cast<unsigned int>(!line_local.empty()), comm)
      > 0;
  }

  void
  ConstraintDistribution::distribute(LA::Vector &x) const
  {
    AssertThrow(constraints != nullptr, ExcNotInitialized());
    if (!any)
      return;
    Assert(!x.has_ghost_elements(), ExcGhostsPresent());
    // A vector of another layout takes deal.II's way (SameAs is
    // collective, as this function is).
    if (!x.trilinos_vector().Map().SameAs(importer->SourceMap()))
      {
        constraints->distribute(x);
        return;
      }
    buffer.trilinos_vector().Import(x.trilinos_vector(), *importer, Insert);
    const double *g = buffer.trilinos_vector()[0];
    double       *v = x.trilinos_vector()[0];
    for (std::size_t k = 0; k < line_local.size(); ++k)
      {
        double value = inhomogeneity[k];
        for (int m = line_start[k]; m < line_start[k + 1]; ++m)
          value += weight[m] * g[master_position[m]];
        v[line_local[k]] = value;
      }
  }
} // namespace pneuma
