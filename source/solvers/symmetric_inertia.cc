#include <pneuma/solvers/symmetric_inertia.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace pneuma
{
  namespace solvers
  {
    struct SymmetricInertia::Data
    {
      DMUMPS_STRUC_C id;
      bool           initialized = false, analysed = false;
      // The triplets of the last analysis (1-based; MUMPS keeps pointers).
      std::vector<MUMPS_INT> rows, columns;
      std::vector<double>    values;
      MUMPS_INT8             n = 0;

      void
      call(const int job)
      {
        id.job = job;
        dmumps_c(&id);
        if (id.infog[0] < 0)
          throw std::runtime_error(
            "MUMPS (symmetric inertia) failed in job " + std::to_string(job)
            + " with INFOG(1) = " + std::to_string(id.infog[0])
            + ", INFOG(2) = " + std::to_string(id.infog[1]));
      }
    };

    SymmetricInertia::SymmetricInertia(const MPI_Comm comm,
                                       const double   zero_pivot_threshold,
                                       const bool     symmetric)
      : data(std::make_unique<Data>())
    {
      DMUMPS_STRUC_C &id = data->id;
      id                 = DMUMPS_STRUC_C();
      id.comm_fortran    = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
      id.par             = 1; // the host works too
      // General symmetric: LDL^T with 2x2 pivots; or LU.
      id.sym = symmetric ? 2 : 0;
      data->call(-1);
      data->initialized = true;
      id.icntl[0]       = -1; // no error, diagnostic or global output
      id.icntl[1]       = -1;
      id.icntl[2]       = -1;
      id.icntl[3]       = 0;
      id.icntl[12]      = 1; // ICNTL(13): no ScaLAPACK root (exact count)
      id.icntl[17]      = 3; // ICNTL(18): distributed triplets
      id.icntl[23]      = 1; // ICNTL(24): detect null pivots
      // ICNTL(7) = 2: the approximate minimum fill ordering, as for the
      // Newton solves (METIS's analysis costs several factorizations on
      // membrane meshes, benchmarks/inflated_cylinder/results.md).
      id.icntl[6] = 2;
      id.cntl[2]  = zero_pivot_threshold; // CNTL(3)
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
      // The owned rows' upper triangle, in global 1-based indices.
      const Epetra_CrsMatrix &M = A.trilinos_matrix();
      std::vector<MUMPS_INT>  rows, columns;
      std::vector<double>     values;
      for (int r = 0; r < M.NumMyRows(); ++r)
        {
          int     n       = 0;
          double *entries = nullptr;
          int    *local   = nullptr;
          M.ExtractMyRowView(r, n, entries, local);
          const long long row = M.GRID64(r);
          for (int k = 0; k < n; ++k)
            {
              const long long column = M.GCID64(local[k]);
              if (column >= row || data->id.sym == 0)
                {
                  rows.push_back(static_cast<MUMPS_INT>(row + 1));
                  columns.push_back(static_cast<MUMPS_INT>(column + 1));
                  values.push_back(entries[k]);
                }
            }
        }
      Data           &d            = *data;
      DMUMPS_STRUC_C &id           = d.id;
      const bool      same_pattern = d.analysed
                                && d.n == static_cast<MUMPS_INT8>(A.m())
                                && rows == d.rows && columns == d.columns;
      d.values = values;
      id.a_loc = d.values.data();
      if (!same_pattern)
        {
          d.rows     = rows;
          d.columns  = columns;
          d.n        = A.m();
          id.n       = static_cast<MUMPS_INT>(A.m());
          id.nnz_loc = static_cast<MUMPS_INT8>(d.rows.size());
          id.irn_loc = d.rows.data();
          id.jcn_loc = d.columns.data();
          d.call(1); // analysis
          d.analysed = true;
        }
      d.call(2); // factorization
      Inertia result;
      result.negative = id.sym == 0 ? 0 : id.infog[11]; // INFOG(12)
      result.zero     = id.infog[27];                   // INFOG(28)
      result.positive = A.m() - result.negative - result.zero;
      return result;
    }
    void
    SymmetricInertia::solve(const std::vector<dealii::Vector<double>> &b,
                            std::vector<dealii::Vector<double>>       &x)
    {
      Data           &d    = *data;
      DMUMPS_STRUC_C &id   = d.id;
      const MPI_Comm  comm = MPI_Comm_f2c(id.comm_fortran);
      const bool host = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
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
      id.icntl[19] = 0;
      id.icntl[20] = 0;
      id.nrhs      = static_cast<MUMPS_INT>(b.size());
      id.lrhs      = static_cast<MUMPS_INT>(n);
      id.rhs       = host ? block.data() : nullptr;
      d.call(3);
      id.nrhs = 1;
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
      Data           &d  = *data;
      DMUMPS_STRUC_C &id = d.id;
      const bool      host =
        dealii::Utilities::MPI::this_mpi_process(MPI_Comm_f2c(id.comm_fortran))
        == 0;
      // Centralized right-hand side and solution on the host (ICNTL(20) =
      // ICNTL(21) = 0), then shared.
      x            = b;
      id.icntl[19] = 0;
      id.icntl[20] = 0;
      id.nrhs      = 1;
      id.lrhs      = static_cast<MUMPS_INT>(x.size());
      id.rhs       = host ? x.data() : nullptr;
      d.call(3);
      x =
        dealii::Utilities::MPI::broadcast(MPI_Comm_f2c(id.comm_fortran), x, 0);
    }
  } // namespace solvers
} // namespace pneuma
