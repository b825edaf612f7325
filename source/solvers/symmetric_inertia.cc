#include <pneuma/solvers/nested_dissection.h>
#include <pneuma/solvers/symmetric_inertia.h>

#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace pneuma
{
  namespace solvers
  {
    namespace
    {
      /// Whether MUMPS factorizes on all ranks (Linear solver/direct/
      /// Distributed factorization); see SymmetricInertia::
      /// set_distributed_factorization().
      bool distributed_default = false;

      /**
       * Wait for @p request without spinning: the ranks that wait while
       * rank 0 factorizes sleep between tests, so that they leave the
       * cores to its BLAS threads (Open MPI's blocking calls poll at full
       * speed).
       */
      void
      wait_idle(MPI_Request &request)
      {
        int done = 0;
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        while (!done)
          {
            std::this_thread::sleep_for(std::chrono::microseconds(100));
            MPI_Test(&request, &done, MPI_STATUS_IGNORE);
          }
      }
    } // namespace

    void
    SymmetricInertia::set_distributed_factorization(const bool distributed)
    {
      distributed_default = distributed;
    }

    bool
    SymmetricInertia::distributed_factorization()
    {
      return distributed_default;
    }

    struct SymmetricInertia::Data
    {
      DMUMPS_STRUC_C id;
      /// All ranks of the matrix, and MUMPS' own: the same, or in the
      /// central mode rank 0 alone (MPI_COMM_SELF there; the other ranks
      /// have no MUMPS instance and pass their triplets and right-hand
      /// sides to rank 0).
      MPI_Comm comm        = MPI_COMM_NULL;
      bool     central     = false;
      bool     initialized = false, analysed = false;
      // The triplets of the last analysis (1-based; MUMPS keeps pointers):
      // this rank's owned rows first (n_own of them), then, on rank 0 in
      // the central mode, those of the other ranks in rank order.
      std::vector<MUMPS_INT> rows, columns;
      std::vector<double>    values;
      std::size_t            n_own = 0;
      /// The other ranks' numbers of triplets and their offsets in the
      /// arrays of rank 0 (central mode).
      std::vector<int> counts, offsets;
      MUMPS_INT8       n = 0;
      Work             work;
      PivotOrder       order;

      /// This rank calls MUMPS.
      bool
      runs_mumps() const
      {
        return !central || dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      }

      /// Rank 0 collects the other ranks' triplets behind its own
      /// (central mode): the values only if @p values_only (the pattern
      /// is the analysed one), else the indices too.
      void
      gather_triplets(const bool values_only)
      {
        if (!central)
          return;
        const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
        const unsigned int n_ranks =
          dealii::Utilities::MPI::n_mpi_processes(comm);
        const int mine = static_cast<int>(n_own);
        if (!values_only)
          {
            counts.assign(root ? n_ranks : 0, 0);
            MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
            offsets.assign(counts.size(), 0);
            for (unsigned int r = 1; r < counts.size(); ++r)
              offsets[r] = offsets[r - 1] + counts[r - 1];
            if (root)
              {
                const std::size_t total = offsets.back() + counts.back();
                rows.resize(total);
                columns.resize(total);
                values.resize(total);
              }
          }
        const auto gather = [&](auto *data, const MPI_Datatype type) {
          MPI_Gatherv(root ? MPI_IN_PLACE : data,
                      mine,
                      type,
                      data,
                      counts.data(),
                      offsets.data(),
                      type,
                      0,
                      comm);
        };
        if (!values_only)
          {
            gather(rows.data(), MPI_INT);
            gather(columns.data(), MPI_INT);
          }
        gather(values.data(), MPI_DOUBLE);
      }

      /// Rank 0's MUMPS call and what the others read of it: the status
      /// (an error is thrown on every rank), the inertia, the sizes and
      /// flops (central mode).
      void
      call(const int job)
      {
        const auto  start = std::chrono::steady_clock::now();
        std::string error;
        if (runs_mumps())
          try
            {
              timed_call(job);
            }
          catch (const std::runtime_error &e)
            {
              error = e.what();
            }
        const double seconds = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
        if (job == 1)
          {
            ++work.analyses;
            work.analysis_seconds += seconds;
          }
        else if (job == 2)
          work.factorization_seconds += seconds;
        else if (job == 3)
          work.solve_seconds += seconds;
        if (central)
          {
            double      status[8] = {static_cast<double>(id.infog[0]),
                                     static_cast<double>(id.infog[1]),
                                     static_cast<double>(id.infog[11]),
                                     static_cast<double>(id.infog[27]),
                                     static_cast<double>(id.infog[28]),
                                     id.rinfog[0],
                                     id.rinfog[2],
                                error.empty() ? 0. : 1.};
            MPI_Request request;
            MPI_Ibcast(status, 8, MPI_DOUBLE, 0, comm, &request);
            wait_idle(request);
            id.infog[0]  = static_cast<MUMPS_INT>(status[0]);
            id.infog[1]  = static_cast<MUMPS_INT>(status[1]);
            id.infog[11] = static_cast<MUMPS_INT>(status[2]);
            id.infog[27] = static_cast<MUMPS_INT>(status[3]);
            id.infog[28] = static_cast<MUMPS_INT>(status[4]);
            id.rinfog[0] = status[5];
            id.rinfog[2] = status[6];
            if (status[7] != 0.)
              error = dealii::Utilities::MPI::broadcast(comm, error, 0);
          }
        if (!error.empty())
          throw std::runtime_error(error);
      }

      void
      timed_call(const int job)
      {
        id.job = job;
        dmumps_c(&id);
        // The factorization's workspace is the analysis' estimate plus
        // ICNTL(14) percent. Pivots delayed beyond that (an indefinite
        // tangent) make MUMPS stop with INFOG(1) = -8, -9, -14, -15 or
        // -17 (a workspace too small): the relaxation grows and the
        // factorization is repeated, so that a small default relaxation
        // keeps the peak memory low without ever failing on it.
        while (job == 2 && id.icntl[13] < 1000
               && (id.infog[0] == -8 || id.infog[0] == -9 || id.infog[0] == -14
                   || id.infog[0] == -15 || id.infog[0] == -17))
          {
            id.icntl[13] = 2 * id.icntl[13] + 20;
            dmumps_c(&id);
          }
        if (id.infog[0] < 0)
          throw std::runtime_error(
            "MUMPS (symmetric inertia) failed in job " + std::to_string(job)
            + " with INFOG(1) = " + std::to_string(id.infog[0])
            + ", INFOG(2) = " + std::to_string(id.infog[1]));
      }

      /// Analysis of the pattern in irn_loc/jcn_loc. A pattern that
      /// changed (contact's couplings) but kept its size first reuses the
      /// last computed pivot order (ICNTL(7) = 1): only the symbolic
      /// factorization is redone. If that order's estimated flops exceed
      /// those it had on its own pattern by more than 10 %, a new order is
      /// computed.
      void
      analyse()
      {
        const bool host = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
        static_assert(std::is_same_v<MUMPS_INT, int>,
                      "PivotOrder holds MUMPS_INT as int");
        // The host holds the order; all ranks decide alike.
        int reuse =
          id.icntl[6] != 1
          && (!host || static_cast<MUMPS_INT8>(order.position.size()) == id.n);
        reuse = dealii::Utilities::MPI::min(reuse, comm);
        if (reuse)
          {
            const int icntl7 = id.icntl[6];
            id.icntl[6]      = 1;
            id.perm_in       = host ? order.position.data() : nullptr;
            call(1);
            id.icntl[6] = icntl7;
            id.perm_in  = nullptr;
            // RINFOG(1): the analysis' estimate of the flops, on all ranks.
            if (id.rinfog[0] <= 1.1 * order.flops)
              return;
          }
        if (id.icntl[6] == 5)
          {
            // METIS, which Debian's MUMPS lacks (it would fall back to
            // PORD): its nested dissection on the host, given to MUMPS as
            // the pivot order.
            const auto       start = std::chrono::steady_clock::now();
            std::vector<int> position =
              nested_dissection(comm,
                                id.n,
                                rows.data(),
                                columns.data(),
                                n_own,
                                id.n % 3 == 0 ? 3 : 1);
            work.analysis_seconds += std::chrono::duration<double>(
                                       std::chrono::steady_clock::now() - start)
                                       .count();
            id.icntl[6] = 1;
            id.perm_in  = host ? position.data() : nullptr;
            call(1);
            id.icntl[6] = 5;
            id.perm_in  = nullptr;
          }
        else
          call(1);
        ++work.orderings;
        order.flops = id.rinfog[0];
        if (host)
          order.position.assign(id.sym_perm, id.sym_perm + id.n);
      }

      /// Solve with the factors for @p nrhs right-hand sides of length
      /// @p n, column-major in @p rhs on the host (nullptr elsewhere),
      /// overwritten by the solutions (ICNTL(20) = ICNTL(21) = 0:
      /// centralized right-hand side and solution).
      void
      solve_on_host(double *rhs, const std::size_t n, const std::size_t nrhs)
      {
        id.icntl[19] = 0;
        id.icntl[20] = 0;
        id.nrhs      = static_cast<MUMPS_INT>(nrhs);
        id.lrhs      = static_cast<MUMPS_INT>(n);
        id.rhs       = rhs;
        call(3);
        id.nrhs = 1;
      }
    };

    void
    SymmetricInertia::set_ordering(const int icntl7)
    {
      if (data->id.icntl[6] != icntl7)
        data->analysed = false;
      data->id.icntl[6] = icntl7;
    }

    const SymmetricInertia::PivotOrder &
    SymmetricInertia::pivot_order() const
    {
      return data->order;
    }

    void
    SymmetricInertia::set_pivot_order(PivotOrder order)
    {
      data->order = std::move(order);
    }

    double
    mumps_count(const int infog)
    {
      return infog < 0 ? -1e6 * infog : static_cast<double>(infog);
    }

    SymmetricInertia::SymmetricInertia(const MPI_Comm comm,
                                       const double   zero_pivot_threshold,
                                       const bool     symmetric)
      : data(std::make_unique<Data>())
    {
      DMUMPS_STRUC_C &id = data->id;
      id                 = DMUMPS_STRUC_C();
      data->comm         = comm;
      data->central      = !distributed_default
                      && dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
      id.comm_fortran = static_cast<MUMPS_INT>(
        MPI_Comm_c2f(data->central ? MPI_COMM_SELF : comm));
      id.par = 1; // the host works too
      // General symmetric: LDL^T with 2x2 pivots; or LU.
      id.sym = symmetric ? 2 : 0;
      if (data->runs_mumps())
        {
          id.job = -1;
          dmumps_c(&id);
          data->initialized = true;
        }
      id.icntl[0] = -1; // no error, diagnostic or global output
      id.icntl[1] = -1;
      id.icntl[2] = -1;
      id.icntl[3] = 0;
      // ICNTL(13) = 1: no ScaLAPACK root, whose pivots INFOG(12) would not
      // count in parallel (Newton's factorizations give the stability
      // count too).
      id.icntl[12] = 1;
      id.icntl[17] = 3; // ICNTL(18): distributed triplets
      // ICNTL(24): detect null pivots (or, without a threshold, fail on
      // them).
      id.icntl[23] = zero_pivot_threshold > 0. ? 1 : 0;
      // ICNTL(7) = 2: the approximate minimum fill ordering, the default
      // of the Newton solves (the cheapest analysis,
      // benchmarks/inflated_cylinder/results.md).
      id.icntl[6] = 2;
      // ICNTL(14): 10 % over the analysis' workspace estimate (MUMPS'
      // default 20 % held 24 MB that the cylinder at 47k cells never used;
      // call() grows it where delayed pivots need more).
      id.icntl[13] = 10;
      id.cntl[2]   = zero_pivot_threshold; // CNTL(3)
    }

    SymmetricInertia::~SymmetricInertia()
    {
      if (data && data->initialized)
        {
          data->id.job = -2;
          dmumps_c(&data->id);
        }
    }

    Inertia
    SymmetricInertia::compute(const LA::SparseMatrix &A)
    {
      // The owned rows' upper triangle, in global 1-based indices. The
      // entries are counted first and written in place: at 400k rows the
      // triplets are 90 MB, and growing vectors or a second copy of them
      // next to MUMPS' own arrays would raise the peak memory of the
      // factorization. With the analysed pattern unchanged only the values
      // are rewritten (the indices are compared where they stand).
      const Epetra_CrsMatrix &M  = A.trilinos_matrix();
      Data                   &d  = *data;
      DMUMPS_STRUC_C         &id = d.id;
      // The global index of each local column, once (not per entry).
      std::vector<long long> global_column(M.NumMyCols());
      for (int c = 0; c < M.NumMyCols(); ++c)
        global_column[c] = M.GCID64(c);
      const auto for_each_entry = [&](const auto &visit) {
        for (int r = 0; r < M.NumMyRows(); ++r)
          {
            int     n       = 0;
            double *entries = nullptr;
            int    *local   = nullptr;
            M.ExtractMyRowView(r, n, entries, local);
            const long long row = M.GRID64(r);
            for (int k = 0; k < n; ++k)
              {
                const long long column = global_column[local[k]];
                if (column >= row || id.sym == 0)
                  visit(static_cast<MUMPS_INT>(row + 1),
                        static_cast<MUMPS_INT>(column + 1),
                        entries[k]);
              }
          }
      };
      std::size_t count = 0;
      for_each_entry([&](MUMPS_INT, MUMPS_INT, double) { ++count; });
      bool same_pattern =
        d.analysed && d.n == static_cast<MUMPS_INT8>(A.m()) && count == d.n_own;
      if (same_pattern)
        {
          std::size_t k = 0;
          for_each_entry([&](const MUMPS_INT i, const MUMPS_INT j, double v) {
            same_pattern  = same_pattern && d.rows[k] == i && d.columns[k] == j;
            d.values[k++] = v;
          });
          if (!same_pattern) // same size, other entries: new indices
            {
              k = 0;
              for_each_entry([&](const MUMPS_INT i, const MUMPS_INT j, double) {
                d.rows[k]      = i;
                d.columns[k++] = j;
              });
            }
        }
      else
        {
          // Release the old arrays before the new ones are allocated.
          std::vector<MUMPS_INT>().swap(d.rows);
          std::vector<MUMPS_INT>().swap(d.columns);
          std::vector<double>().swap(d.values);
          d.rows.reserve(count);
          d.columns.reserve(count);
          d.values.reserve(count);
          for_each_entry([&](const MUMPS_INT i, const MUMPS_INT j, double v) {
            d.rows.push_back(i);
            d.columns.push_back(j);
            d.values.push_back(v);
          });
        }
      d.n_own = count;
      // MUMPS needs the same JOB on every rank: a pattern that changed on
      // one rank only (contact adding entries to its rows) is a new
      // analysis everywhere.
      same_pattern =
        dealii::Utilities::MPI::min(same_pattern ? 1 : 0, d.comm) == 1;
      d.gather_triplets(same_pattern);
      id.a_loc = d.values.data();
      if (!same_pattern)
        {
          d.n        = A.m();
          id.n       = static_cast<MUMPS_INT>(A.m());
          id.nnz_loc = static_cast<MUMPS_INT8>(d.rows.size());
          id.irn_loc = d.rows.data();
          id.jcn_loc = d.columns.data();
          id.a_loc   = d.values.data();
          // ICNTL(15) = -3: the unknowns come in blocks of three (the
          // displacement components of a node, a cable's directors), so
          // the ordering works on the graph of the nodes, a third of the
          // size (MUMPS 5.5 user guide, ICNTL(15)): MUMPS' own nested
          // dissection (PORD, as Debian builds it) of the waterbeam at
          // 158k unknowns takes 0.9 s instead of 4.3 s. It is only a hint
          // to the analysis; the factors are exact for any pattern. (The
          // metis ordering compresses the graph itself,
          // nested_dissection.h.)
          id.icntl[14] = id.n % 3 == 0 ? -3 : 0;
          d.analyse();
          d.analysed = true;
        }
      d.call(2); // factorization
      Inertia result;
      result.negative = id.sym == 0 ? 0 : id.infog[11]; // INFOG(12)
      result.zero     = id.infog[27];                   // INFOG(28)
      result.positive = A.m() - result.negative - result.zero;
      last_inertia    = result;
      return result;
    }

    void
    SymmetricInertia::solve(const std::vector<dealii::Vector<double>> &b,
                            std::vector<dealii::Vector<double>>       &x)
    {
      Data          &d    = *data;
      const MPI_Comm comm = d.comm;
      const bool     host = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      x.resize(b.size());
      if (b.empty())
        return;
      // All right-hand sides in one column-major block on the host: one
      // pass over the factors for all of them.
      const std::size_t   n = b[0].size();
      std::vector<double> block(host ? n * b.size() : 0);
      if (host)
        for (std::size_t j = 0; j < b.size(); ++j)
          std::copy(b[j].begin(), b[j].end(), block.begin() + j * n);
      d.solve_on_host(host ? block.data() : nullptr, n, b.size());
      for (std::size_t j = 0; j < b.size(); ++j)
        {
          x[j].reinit(n);
          if (host)
            std::copy(block.begin() + j * n,
                      block.begin() + (j + 1) * n,
                      x[j].begin());
          x[j] = dealii::Utilities::MPI::broadcast(comm, x[j], 0);
        }
    }

    void
    SymmetricInertia::solve(const dealii::Vector<double> &b,
                            dealii::Vector<double>       &x)
    {
      Data      &d    = *data;
      const bool host = dealii::Utilities::MPI::this_mpi_process(d.comm) == 0;
      // Solved on the host, then shared.
      x = b;
      d.solve_on_host(host ? x.data() : nullptr, x.size(), 1);
      x = dealii::Utilities::MPI::broadcast(d.comm, x, 0);
    }

    void
    SymmetricInertia::solve(const LA::Vector &b, LA::Vector &x)
    {
      solve(std::vector<const LA::Vector *>{&b}, std::vector<LA::Vector *>{&x});
    }

    void
    SymmetricInertia::solve(const std::vector<const LA::Vector *> &b,
                            const std::vector<LA::Vector *>       &x)
    {
      AssertDimension(b.size(), x.size());
      if (b.empty())
        return;
      Data              &d    = *data;
      const MPI_Comm     comm = d.comm;
      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(comm);
      const bool host     = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      const std::size_t n = b[0]->size(), nrhs = b.size();
      // The owned entries of every b with their global indices, to the
      // host: the indices once, the values column by column.
      const dealii::IndexSet    &owned = b[0]->locally_owned_elements();
      std::vector<std::uint64_t> indices;
      indices.reserve(owned.n_elements());
      for (const auto i : owned)
        indices.push_back(i);
      const int        n_local = static_cast<int>(indices.size());
      std::vector<int> counts(host ? n_ranks : 0), offsets;
      MPI_Gather(&n_local, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
      std::size_t total = 0;
      if (host)
        {
          offsets.assign(n_ranks, 0);
          for (unsigned int r = 1; r < n_ranks; ++r)
            offsets[r] = offsets[r - 1] + counts[r - 1];
          total = offsets.back() + counts.back();
        }
      std::vector<std::uint64_t> all_indices(total);
      MPI_Gatherv(indices.data(),
                  n_local,
                  MPI_UINT64_T,
                  all_indices.data(),
                  counts.data(),
                  offsets.data(),
                  MPI_UINT64_T,
                  0,
                  comm);
      // Column-major n x nrhs on the host.
      std::vector<double> block(host ? n * nrhs : 0), values(n_local),
        all_values(total);
      for (std::size_t j = 0; j < nrhs; ++j)
        {
          AssertDimension(b[j]->size(), n);
          for (int k = 0; k < n_local; ++k)
            values[k] = (*b[j])[indices[k]];
          MPI_Gatherv(values.data(),
                      n_local,
                      MPI_DOUBLE,
                      all_values.data(),
                      counts.data(),
                      offsets.data(),
                      MPI_DOUBLE,
                      0,
                      comm);
          if (host)
            for (std::size_t k = 0; k < total; ++k)
              block[j * n + all_indices[k]] = all_values[k];
        }
      d.solve_on_host(host ? block.data() : nullptr, n, nrhs);
      // Back in the gathered order, then to the owners.
      for (std::size_t j = 0; j < nrhs; ++j)
        {
          if (host)
            for (std::size_t k = 0; k < total; ++k)
              all_values[k] = block[j * n + all_indices[k]];
          MPI_Scatterv(all_values.data(),
                       counts.data(),
                       offsets.data(),
                       MPI_DOUBLE,
                       values.data(),
                       n_local,
                       MPI_DOUBLE,
                       0,
                       comm);
          LA::Vector &xj = *x[j];
          if (xj.size() != n)
            xj.reinit(*b[j]);
          for (int k = 0; k < n_local; ++k)
            xj[indices[k]] = values[k];
          xj.compress(dealii::VectorOperation::insert);
        }
    }

    double
    SymmetricInertia::factor_entries() const
    {
      return mumps_count(data->id.infog[28]); // INFOG(29)
    }

    const SymmetricInertia::Work &
    SymmetricInertia::work() const
    {
      return data->work;
    }

    double
    SymmetricInertia::factorization_flops() const
    {
      return data->id.rinfog[2]; // RINFOG(3)
    }
  } // namespace solvers
} // namespace pneuma
