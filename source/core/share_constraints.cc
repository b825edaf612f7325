#include <pneuma/core/share_constraints.h>

#include <vector>

namespace pneuma
{
  void
  share_constraint_lines(AffineConstraints<double> &constraints,
                         const IndexSet            &shared,
                         const IndexSet            &locally_owned,
                         const MPI_Comm             comm)
  {
    // Owned, constrained dofs as (dof, inhomogeneity, n, (column, weight)
    // x n).
    std::vector<double> local;
    for (const auto m : shared)
      if (locally_owned.is_element(m) && constraints.is_constrained(m))
        {
          const auto *entries = constraints.get_constraint_entries(m);
          local.insert(local.end(),
                       {double(m),
                        constraints.get_inhomogeneity(m),
                        double(entries->size())});
          for (const auto &e : *entries)
            local.insert(local.end(), {double(e.first), e.second});
        }
    for (const auto &part : Utilities::MPI::all_gather(comm, local))
      for (std::size_t k = 0; k + 2 < part.size();)
        {
          const auto m = static_cast<types::global_dof_index>(part[k]);
          const auto n = static_cast<std::size_t>(part[k + 2]);
          if (constraints.can_store_line(m) && !constraints.is_constrained(m))
            {
              constraints.add_line(m);
              for (std::size_t e = 0; e < n; ++e)
                constraints.add_entry(m,
                                      static_cast<types::global_dof_index>(
                                        part[k + 3 + 2 * e]),
                                      part[k + 4 + 2 * e]);
              constraints.set_inhomogeneity(m, part[k + 1]);
            }
          k += 3 + 2 * n;
        }
  }
} // namespace pneuma
