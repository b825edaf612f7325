#include <pneuma/solvers/nested_dissection.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cstdint>
#include <metis.h>
#include <stdexcept>
#include <string>
#include <utility>

namespace pneuma
{
  namespace solvers
  {
    std::vector<int>
    nested_dissection(const MPI_Comm     comm,
                      const int          n,
                      const int         *rows,
                      const int         *columns,
                      const std::size_t  n_entries,
                      const unsigned int block)
    {
      if (block == 0 || n % static_cast<int>(block) != 0)
        throw std::invalid_argument("nested_dissection: " + std::to_string(n)
                                    + " unknowns in blocks of "
                                    + std::to_string(block));
      const int n_nodes = n / static_cast<int>(block);
      // This rank's edges between nodes (lower node first), each once.
      std::vector<std::int64_t> edges;
      edges.reserve(n_entries / (block * block) + 1);
      for (std::size_t k = 0; k < n_entries; ++k)
        {
          const std::int64_t a = (rows[k] - 1) / static_cast<int>(block),
                             b = (columns[k] - 1) / static_cast<int>(block);
          if (a != b)
            edges.push_back(std::min(a, b) * n_nodes + std::max(a, b));
        }
      std::sort(edges.begin(), edges.end());
      edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

      // All ranks' edges on the host.
      const auto gathered = dealii::Utilities::MPI::gather(comm, edges, 0);
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return {};
      std::vector<std::int64_t>().swap(edges);
      std::vector<std::int64_t> all;
      for (const auto &part : gathered)
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());

      // The adjacency in METIS' compressed rows, both directions.
      std::vector<idx_t> xadj(n_nodes + 1, 0), adjncy(2 * all.size());
      for (const auto e : all)
        {
          ++xadj[e / n_nodes + 1];
          ++xadj[e % n_nodes + 1];
        }
      for (int v = 0; v < n_nodes; ++v)
        xadj[v + 1] += xadj[v];
      std::vector<idx_t> next(xadj.begin(), xadj.end() - 1);
      for (const auto e : all)
        {
          const idx_t a     = static_cast<idx_t>(e / n_nodes),
                      b     = static_cast<idx_t>(e % n_nodes);
          adjncy[next[a]++] = b;
          adjncy[next[b]++] = a;
        }
      std::vector<std::int64_t>().swap(all);

      idx_t nv = n_nodes;
      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      options[METIS_OPTION_NUMBERING] = 0;
      std::vector<idx_t> perm(n_nodes), iperm(n_nodes);
      const int          status = METIS_NodeND(&nv,
                                      xadj.data(),
                                      adjncy.data(),
                                      nullptr,
                                      options,
                                      perm.data(),
                                      iperm.data());
      if (status != METIS_OK)
        throw std::runtime_error("METIS_NodeND failed with status "
                                 + std::to_string(status));
      // iperm[v]: the position of node v in the order.
      std::vector<int> position(n);
      for (int v = 0; v < n_nodes; ++v)
        for (unsigned int c = 0; c < block; ++c)
          position[v * block + c] = static_cast<int>(iperm[v] * block + c + 1);
      return position;
    }
  } // namespace solvers
} // namespace pneuma
