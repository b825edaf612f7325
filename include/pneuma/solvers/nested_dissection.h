#pragma once

/**
 * @file
 * A fill-reducing pivot order from METIS' nested dissection
 * (METIS_NodeND, G. Karypis and V. Kumar, SIAM J. Sci. Comput. 20 (1998)
 * 359-392) for MUMPS' analysis with a given order (ICNTL(7) = 1).
 *
 * Debian's MUMPS 5.5 is built with PORD as its only nested dissection
 * (libmumps_common links neither METIS nor SCOTCH), so that MUMPS' own
 * ICNTL(7) = 5 silently falls back to PORD. METIS itself comes with
 * deal.II. The order is computed on the graph of the nodes: unknowns in
 * consecutive blocks of @p block (a node's three displacements, a cable
 * node's directors) are one vertex, a ninth of the edges of the graph of
 * the unknowns for blocks of three, and the block's unknowns follow each
 * other in the order.
 */

#include <mpi.h>

#include <vector>

namespace pneuma
{
  namespace solvers
  {
    /**
     * The positions (1-based, MUMPS' PERM_IN) of the @p n unknowns in a
     * nested-dissection order of the symmetric pattern whose entries
     * (1-based row and column indices, any triangle, duplicates allowed)
     * the ranks of @p comm hold in @p rows and @p columns. On rank 0;
     * empty elsewhere. Collective.
     */
    std::vector<int>
    nested_dissection(const MPI_Comm     comm,
                      const int          n,
                      const int         *rows,
                      const int         *columns,
                      const std::size_t  n_entries,
                      const unsigned int block);
  } // namespace solvers
} // namespace pneuma
