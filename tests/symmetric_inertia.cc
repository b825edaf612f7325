// The inertia of symmetric matrices by MUMPS' LDL^T (solvers/symmetric_
// inertia.h), distributed by rows over the MPI ranks, against exact counts:
// - the 1D Laplacian (n = 200) shifted by sigma: eigenvalues
//   2 - 2 cos(j pi/(n+1)) - sigma, j = 1..n, so the number below zero is
//   known in closed form; three shifts, and the analysis is reused;
// - a saddle-point matrix [I B; B^T 0] (B: m columns of n rows, full
//   rank): n positive and m negative eigenvalues, and zero diagonal
//   entries that need 2x2 pivots;
// - a singular matrix (a Laplacian with free ends has one zero
//   eigenvalue): the zero pivot is counted, not called negative;
// - the Newton solves (solvers/linear_solver.h): the LDL^T solve of the
//   indefinite shifted Laplacian and of the saddle point, distributed
//   vectors gathered to MUMPS and back, against the LU of Amesos_Mumps
//   (residuals and the difference of the two solutions); "automatic"
//   picks LDLT for these and LU for a non-symmetric matrix;
// - the Ordering entry reaches the LDL^T (AMD, PORD and METIS give
//   factors of different sizes for a 2D Laplacian, and all solve it;
//   METIS is pneuma's own call of METIS_NodeND, as Debian's MUMPS has no
//   METIS and its ICNTL(7) = 5 would be PORD's order);
// - the nested dissection of a graph of nodes with three unknowns each
//   (solvers/nested_dissection.h): a permutation with each node's
//   unknowns consecutive, the same on 1 and 2 ranks (its checksum is in
//   the output);
// - the pivot order is kept for a new pattern of the same size if its
//   estimated flops stay within 10 %, and computed anew otherwise;
// - factorization reuse, LDL^T and LU: a nearby matrix solved by GMRES on
//   the earlier factors (no new factorization), a far one factorized
//   afresh in the same kind.

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <deal.II/base/parameter_handler.h>

#include <pneuma/solvers/linear_solver.h>
#include <pneuma/solvers/nested_dissection.h>
#include <pneuma/solvers/symmetric_inertia.h>

#include "test_tools.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace
{
  using dealii::types::global_dof_index;

  /// A symmetric matrix of size n from its entries (row, column, value)
  /// for the owned rows; rows distributed in contiguous blocks.
  pneuma::LA::SparseMatrix
  make_matrix(
    const global_dof_index n,
    const std::function<
      std::vector<std::pair<global_dof_index, double>>(global_dof_index)> &row)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    const unsigned int p    = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int r    = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::IndexSet   owned(n);
    owned.add_range(n * r / p, n * (r + 1) / p);
    dealii::DynamicSparsityPattern dsp(n, n, owned);
    for (const auto i : owned)
      for (const auto &[j, v] : row(i))
        dsp.add(i, j);
    pneuma::LA::SparseMatrix A;
    A.reinit(owned, owned, dsp, comm);
    for (const auto i : owned)
      for (const auto &[j, v] : row(i))
        A.set(i, j, v);
    A.compress(dealii::VectorOperation::insert);
    return A;
  }

  /// The 2D Laplacian of an m x m grid (5-point stencil) shifted by 0.3,
  /// indefinite, with -0.01 couplings added where @p extra(i, j) or
  /// @p extra(j, i) (none if @p extra is empty).
  pneuma::LA::SparseMatrix
  shifted_grid(
    const global_dof_index                                         m,
    const std::function<bool(global_dof_index, global_dof_index)> &extra = {})
  {
    return make_matrix(m * m, [&](global_dof_index i) {
      std::vector<std::pair<global_dof_index, double>> e;
      const global_dof_index                           a = i % m, c = i / m;
      if (a > 0)
        e.emplace_back(i - 1, -1.);
      if (c > 0)
        e.emplace_back(i - m, -1.);
      e.emplace_back(i, 4. - 0.3);
      if (a + 1 < m)
        e.emplace_back(i + 1, -1.);
      if (c + 1 < m)
        e.emplace_back(i + m, -1.);
      if (extra)
        for (global_dof_index j = 0; j < m * m; ++j)
          if (j != i && (extra(i, j) || extra(j, i)))
            e.emplace_back(j, -0.01);
      return e;
    });
  }

  bool
  check_count(const std::string     &name,
              const global_dof_index value,
              const global_dof_index reference)
  {
    const bool ok = value == reference;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: reference %llu value %llu error %lld %s\n",
                  name.c_str(),
                  static_cast<unsigned long long>(reference),
                  static_cast<unsigned long long>(value),
                  static_cast<long long>(value)
                    - static_cast<long long>(reference),
                  ok ? "PASS" : "FAIL");
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  const global_dof_index                   n  = 200;

  // Shifted Laplacians, one analysis for all shifts.
  pneuma::solvers::SymmetricInertia inertia(MPI_COMM_WORLD);
  for (const double sigma : {0.5, 1.7, 3.9})
    {
      const auto       A        = make_matrix(n, [&](const global_dof_index i) {
        std::vector<std::pair<global_dof_index, double>> e;
        if (i > 0)
          e.emplace_back(i - 1, -1.);
        e.emplace_back(i, 2. - sigma);
        if (i + 1 < n)
          e.emplace_back(i + 1, -1.);
        return e;
      });
      global_dof_index negative = 0;
      for (global_dof_index j = 1; j <= n; ++j)
        if (2. - 2. * std::cos(j * M_PI / (n + 1)) < sigma)
          ++negative;
      const auto result = inertia.compute(A);
      ok &= check_count("Laplacian - " + std::to_string(sigma).substr(0, 3)
                          + " I: negative eigenvalues",
                        result.negative,
                        negative);
      ok &= check_count("  positive", result.positive, n - negative);
    }

  // Saddle point [I B; B^T 0]: B couples column k to rows 2k and 2k+1.
  const global_dof_index m = 60, size = n + m;
  const auto             S = make_matrix(size, [&](const global_dof_index i) {
    std::vector<std::pair<global_dof_index, double>> e;
    if (i < n)
      {
        e.emplace_back(i, 1.);
        if (i / 2 < m)
          e.emplace_back(n + i / 2, i % 2 ? 1. : 0.5);
      }
    else
      {
        e.emplace_back(i, 0.);
        e.emplace_back(2 * (i - n), 0.5);
        e.emplace_back(2 * (i - n) + 1, 1.);
      }
    return e;
  });
  pneuma::solvers::SymmetricInertia saddle(MPI_COMM_WORLD);
  const auto                        s = saddle.compute(S);
  ok &= check_count("saddle point: negative eigenvalues", s.negative, m);
  ok &= check_count("  positive", s.positive, n);
  ok &= check_count("  zero", s.zero, 0);

  // A Laplacian with free ends: one zero eigenvalue (constants).
  const auto L = make_matrix(n, [&](const global_dof_index i) {
    std::vector<std::pair<global_dof_index, double>> e;
    double                                           d = 0.;
    if (i > 0)
      {
        e.emplace_back(i - 1, -1.);
        d += 1.;
      }
    if (i + 1 < n)
      {
        e.emplace_back(i + 1, -1.);
        d += 1.;
      }
    e.emplace_back(i, d);
    return e;
  });
  pneuma::solvers::SymmetricInertia singular(MPI_COMM_WORLD, 1e-8);
  const auto                        z = singular.compute(L);
  ok &= check_count("free Laplacian: zero eigenvalues", z.zero, 1);
  ok &= check_count("  negative", z.negative, 0);

  // Newton's solves: LDL^T against LU.
  const auto solve = [&](const std::string              &factorization,
                         const pneuma::LA::SparseMatrix &A,
                         pneuma::LA::Vector             &x,
                         const pneuma::LA::Vector       &b) {
    pneuma::solvers::LinearSolver solver;
    dealii::ParameterHandler      prm;
    solver.declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Linear solver\n subsection direct\n  set Factorization = "
      + factorization + "\n end\nend\n");
    solver.factorize(A);
    solver.solve(A, x, b);
    return solver.factorization();
  };
  const bool root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const auto shifted = make_matrix(n, [&](const global_dof_index i) {
    std::vector<std::pair<global_dof_index, double>> e;
    if (i > 0)
      e.emplace_back(i - 1, -1.);
    e.emplace_back(i, 2. - 1.7);
    if (i + 1 < n)
      e.emplace_back(i + 1, -1.);
    return e;
  });
  for (const auto &[name, A] :
       std::vector<std::pair<std::string, const pneuma::LA::SparseMatrix *>>{
         {"Laplacian - 1.7 I", &shifted}, {"saddle point", &S}})
    {
      pneuma::LA::Vector b(A->locally_owned_range_indices(), MPI_COMM_WORLD);
      for (const auto i : b.locally_owned_elements())
        b[i] = std::sin(0.37 * i + 0.2);
      b.compress(dealii::VectorOperation::insert);
      pneuma::LA::Vector x_ldlt(b), x_lu(b), r(b);
      const std::string  kind = solve("automatic", *A, x_ldlt, b);
      solve("LU", *A, x_lu, b);
      A->vmult(r, x_ldlt);
      r -= b;
      const double residual = r.l2_norm() / b.l2_norm();
      x_lu -= x_ldlt;
      const double difference = x_lu.l2_norm() / x_ldlt.l2_norm();
      const bool   pass =
        kind == "LDLT" && residual < 1e-12 && difference < 1e-10;
      ok &= pass;
      if (root)
        std::printf("%s, Newton solve: automatic chose %s; |Ax - b|/|b| %s "
                    "1e-12, |x_LU - x_LDLT|/|x| %s 1e-10 %s\n",
                    name.c_str(),
                    kind.c_str(),
                    residual < 1e-12 ? "<" : ">=",
                    difference < 1e-10 ? "<" : ">=",
                    pass ? "PASS" : "FAIL");
    }
  // Not symmetric: an upwinded Laplacian.
  const auto N = make_matrix(n, [&](const global_dof_index i) {
    std::vector<std::pair<global_dof_index, double>> e;
    if (i > 0)
      e.emplace_back(i - 1, -1.5);
    e.emplace_back(i, 2.5);
    if (i + 1 < n)
      e.emplace_back(i + 1, -0.5);
    return e;
  });
  {
    pneuma::LA::Vector b(N.locally_owned_range_indices(), MPI_COMM_WORLD);
    b = 1.;
    pneuma::LA::Vector x(b), r(b);
    const std::string  kind = solve("automatic", N, x, b);
    N.vmult(r, x);
    r -= b;
    const bool small = r.l2_norm() < 1e-12 * b.l2_norm(); // on every rank
    const bool pass  = kind == "LU" && small;
    ok &= pass;
    if (root)
      std::printf("non-symmetric, Newton solve: automatic chose %s, residual "
                  "%s 1e-12 %s\n",
                  kind.c_str(),
                  small ? "<" : ">=",
                  pass ? "PASS" : "FAIL");
  }
  // The ordering entry reaches the LDL^T: the factors of a 2D Laplacian
  // (40 x 40 grid, 5-point stencil, shifted indefinite) differ in size
  // between AMD, PORD and METIS, and all solve it.
  {
    const auto         grid = shifted_grid(40);
    pneuma::LA::Vector b(grid.locally_owned_range_indices(), MPI_COMM_WORLD);
    b                      = 1.;
    double      entries[3] = {0., 0., 0.}, residuals[3] = {0., 0., 0.};
    const char *orderings[3] = {"amd", "pord", "metis"};
    for (unsigned int k = 0; k < 3; ++k)
      {
        pneuma::solvers::LinearSolver solver;
        dealii::ParameterHandler      prm;
        solver.declare_parameters(prm);
        prm.parse_input_from_string(
          std::string("subsection Linear solver\n subsection direct\n  set "
                      "Factorization = LDLT\n  set Ordering = ")
          + orderings[k] + "\n end\nend\n");
        pneuma::LA::Vector x(b), r(b);
        solver.factorize(grid);
        solver.solve(grid, x, b);
        grid.vmult(r, x);
        r -= b;
        residuals[k] = r.l2_norm() / b.l2_norm();
        entries[k]   = solver.factor_entries();
      }
    const bool differ = entries[0] != entries[2] && entries[1] != entries[2];
    const bool solved =
      residuals[0] < 1e-12 && residuals[1] < 1e-12 && residuals[2] < 1e-12;
    ok &= differ && solved;
    if (root)
      std::printf("ordering: LDL^T factor entries amd %.0f, pord %.0f, metis "
                  "%.0f (metis differs from both: %s), residuals < 1e-12: %s "
                  "%s\n",
                  entries[0],
                  entries[1],
                  entries[2],
                  differ ? "yes" : "no",
                  solved ? "yes" : "no",
                  differ && solved ? "PASS" : "FAIL");
  }

  // METIS' nested dissection of a graph of nodes, three unknowns each (a
  // 30 x 30 grid of nodes, 9-point stencil, every unknown of a node
  // coupled with every unknown of its neighbours): a permutation of
  // 1..n keeping each node's unknowns consecutive, and the same order on
  // any number of ranks (the checksum sum_i i * position(i) is printed).
  {
    const int  k = 30, n = 3 * k * k;
    const auto rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const auto n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    std::vector<int> rows, columns;
    // Rank r holds the upper triangle of its share of the node rows.
    for (int v = 0; v < k * k; ++v)
      if (static_cast<unsigned int>(v) % n_ranks == rank)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            {
              const int x = v % k + dx, y = v / k + dy;
              if (x < 0 || y < 0 || x >= k || y >= k)
                continue;
              const int w = y * k + x;
              for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 3; ++c)
                  if (3 * w + c >= 3 * v + a)
                    {
                      rows.push_back(3 * v + a + 1);
                      columns.push_back(3 * w + c + 1);
                    }
            }
    const std::vector<int> position = pneuma::solvers::nested_dissection(
      MPI_COMM_WORLD, n, rows.data(), columns.data(), rows.size(), 3);
    if (root)
      {
        std::vector<int> sorted(position);
        std::sort(sorted.begin(), sorted.end());
        bool permutation = static_cast<int>(sorted.size()) == n;
        for (int i = 0; permutation && i < n; ++i)
          permutation = sorted[i] == i + 1;
        bool blocks = permutation;
        for (int v = 0; blocks && v < n / 3; ++v)
          blocks = position[3 * v] % 3 == 1
                   && position[3 * v + 1] == position[3 * v] + 1
                   && position[3 * v + 2] == position[3 * v] + 2;
        long long checksum = 0;
        for (int i = 0; permutation && i < n; ++i)
          checksum += static_cast<long long>(i + 1) * position[i];
        ok &= permutation && blocks;
        std::printf("nested dissection of %d nodes x 3: permutation %s, "
                    "node blocks consecutive %s, checksum %lld %s\n",
                    n / 3,
                    permutation ? "yes" : "no",
                    blocks ? "yes" : "no",
                    checksum,
                    permutation && blocks ? "PASS" : "FAIL");
      }
  }

  // The pivot order across patterns (SymmetricInertia::PivotOrder): the
  // 40 x 40 grid of above; after LinearSolver::reset() (a new pattern in a
  // simulation) the grid with a few short couplings added (as contact
  // adds) is analysed with the kept METIS order, no new ordering; with a
  // coupling of every node to a far one (much more fill under the old
  // order) a new order is computed. Each solves to 1e-10 (the far
  // couplings' matrix is the worst conditioned: 3e-12).
  {
    const global_dof_index m = 40;
    const auto none = [](global_dof_index, global_dof_index) { return false; };
    const auto short_couplings = [&](global_dof_index i, global_dof_index j) {
      return i % m == 5 && i / m < 5 && j == i + 2;
    };
    const auto far_couplings = [&](global_dof_index i, global_dof_index j) {
      return j == (i * 797 + 11) % (m * m);
    };
    pneuma::solvers::LinearSolver solver;
    dealii::ParameterHandler      prm;
    solver.declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Linear solver\n subsection direct\n  set Factorization = "
      "LDLT\n  set Ordering = metis\n end\nend\n");
    double       residual = 0.;
    unsigned int analyses[3], orderings[3];
    const std::function<bool(global_dof_index, global_dof_index)> extras[3] = {
      none, short_couplings, far_couplings};
    for (unsigned int k = 0; k < 3; ++k)
      {
        const auto         A = shifted_grid(m, extras[k]);
        pneuma::LA::Vector b(A.locally_owned_range_indices(), MPI_COMM_WORLD);
        b = 1.;
        pneuma::LA::Vector x(b), r(b);
        solver.reset();
        solver.factorize(A);
        solver.solve(A, x, b);
        A.vmult(r, x);
        r -= b;
        residual     = std::max(residual, r.l2_norm() / b.l2_norm());
        analyses[k]  = solver.symmetric_work().analyses;
        orderings[k] = solver.symmetric_work().orderings;
      }
    const bool pass = residual < 1e-10 && analyses[0] == 1 && orderings[0] == 1
                      && analyses[1] == 2 && orderings[1] == 1
                      && orderings[2] == 2;
    ok &= pass;
    if (root)
      std::printf("pivot order across patterns: analyses / orderings: grid "
                  "%u / %u (reference 1 / 1), short couplings %u / %u "
                  "(reference 2 / 1: the order kept), far couplings "
                  "orderings %u (reference 2: a new order); residuals %s "
                  "1e-10 %s\n",
                  analyses[0],
                  orderings[0],
                  analyses[1],
                  orderings[1],
                  orderings[2],
                  residual < 1e-10 ? "<" : ">=",
                  pass ? "PASS" : "FAIL");
  }

  // Factorization reuse (direct/Reuse factorization): the tangent's values
  // change in place; GMRES on the earlier factors solves a nearby matrix,
  // and a far one, which GMRES cannot solve in 'Reuse iterations', is
  // factorized afresh, LDL^T or LU as the earlier factors were.
  for (const std::string factorization : {"automatic", "LU"})
    {
      pneuma::solvers::LinearSolver solver;
      dealii::ParameterHandler      prm;
      solver.declare_parameters(prm);
      prm.parse_input_from_string(
        "subsection Linear solver\n subsection direct\n  set Factorization = "
        + factorization
        + "\n  set Reuse factorization = true\n  set Reuse iterations = 4\n"
          "  set Reuse tolerance = 1e-13\n end\nend\n");
      pneuma::LA::SparseMatrix A;
      A.reinit(shifted);
      A.copy_from(shifted);
      pneuma::LA::Vector b(A.locally_owned_range_indices(), MPI_COMM_WORLD);
      for (const auto i : b.locally_owned_elements())
        b[i] = std::cos(0.21 * i);
      b.compress(dealii::VectorOperation::insert);
      pneuma::LA::Vector x(b), r(b);
      // |A x - b| / |b| after factorize + solve with the diagonal at d.
      const auto residual_at = [&](const double d) {
        for (const auto i : A.locally_owned_range_indices())
          A.set(i, i, d);
        A.compress(dealii::VectorOperation::insert);
        solver.factorize(A);
        x = 0.;
        solver.solve(A, x, b);
        A.vmult(r, x);
        r -= b;
        return r.l2_norm() / b.l2_norm();
      };
      const double       r1   = residual_at(2. - 1.7);
      const double       r2   = residual_at(2. - 1.7 + 1e-6);
      const unsigned int f2   = solver.n_factorizations(),
                         k2   = solver.n_krylov_iterations();
      const double       r3   = residual_at(2. - 0.5);
      const unsigned int f3   = solver.n_factorizations();
      const std::string  kind = solver.factorization();
      const bool pass = r1 < 1e-12 && r2 < 1e-12 && r3 < 1e-12 && f2 == 1
                        && k2 > 0 && f3 == 2
                        && kind == (factorization == "LU" ? "LU" : "LDLT");
      ok &= pass;
      if (root)
        std::printf("reuse (%s): residuals %s 1e-12; nearby matrix on the "
                    "earlier factors: factorizations %u (reference 1), GMRES "
                    "iterations %s; far matrix: factorizations %u (reference "
                    "2), %s %s\n",
                    factorization.c_str(),
                    std::max({r1, r2, r3}) < 1e-12 ? "<" : ">=",
                    f2,
                    k2 > 0 ? "> 0" : "0",
                    f3,
                    kind.c_str(),
                    pass ? "PASS" : "FAIL");
      // The factors refer to A, which is destroyed first: release them
      // while it lives (as Model::~Model does).
      solver.reset();
    }
  return ok ? 0 : 1;
}
