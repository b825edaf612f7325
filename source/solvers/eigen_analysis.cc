#include <deal.II/base/timer.h>

#include <deal.II/lac/parpack_solver.h>
#include <deal.II/lac/solver_control.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/border.h>
#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/solvers/stability.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;

    namespace
    {
      /// Relative size below which an entry of A D counts as zero.
      constexpr double round_off = 1e-12;
    } // namespace

    void
    EigenAnalysis::check_size(const Model &model, const unsigned int n_modes)
    {
      types::global_dof_index n_free = 0;
      for (const auto i : model.locally_owned())
        if (!model.constraints().is_constrained(i))
          ++n_free;
      n_free = Utilities::MPI::sum(n_free, model.mpi_communicator());
      const types::global_dof_index n =
        n_free > model.n_border() ? n_free - model.n_border() : 0;
      check_input(n_modes + 1 < n,
                  "Eigen analysis/Number of modes",
                  std::to_string(n_modes) + " modes asked of a problem with "
                    + std::to_string(n) + " free unknowns; at most "
                    + std::to_string(n > 1 ? n - 2 : 0) + " can be computed");
    }

    namespace
    {
      /**
       * The tangent with the chamber unknowns condensed (see the header):
       * y = K x - B (A D)^+ B^T x, where the unknowns with a diagonal in
       * A D (gas, liquid level) are eliminated and those without (volume
       * constraints) restrict x instead (the inverse keeps B^T x = 0).
       */
      class CondensedTangent
      {
      public:
        CondensedTangent(const LA::SparseMatrix &K,
                         const BorderCoupling   &c,
                         const EnergyBorder     &e)
          : K(K)
        {
          const unsigned int m = e.size();
          for (unsigned int j = 0; j < m; ++j)
            B.push_back(c.B[e.kept[j]]);
          double scale = 0.;
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              scale = std::max(scale, std::abs(e.AD(i, j)));
          std::vector<unsigned int> eliminated;
          std::vector<bool>         is_eliminated(m, false);
          for (unsigned int i = 0; i < m; ++i)
            if (std::abs(e.AD(i, i)) > round_off * scale)
              {
                eliminated.push_back(i);
                is_eliminated[i] = true;
              }
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              if (is_eliminated[i] != is_eliminated[j]
                  && std::abs(e.AD(i, j)) > round_off * scale)
                throw std::runtime_error(
                  "a chamber constraint is coupled to a compressible "
                  "chamber unknown; the eigen analysis does not condense "
                  "such a border");
          const unsigned int g = eliminated.size();
          FullMatrix<double> sub(g, g);
          for (unsigned int i = 0; i < g; ++i)
            for (unsigned int j = 0; j < g; ++j)
              sub(i, j) = e.AD(eliminated[i], eliminated[j]);
          if (g > 0)
            sub.gauss_jordan();
          pseudo_inverse.reinit(m, m);
          for (unsigned int i = 0; i < g; ++i)
            for (unsigned int j = 0; j < g; ++j)
              pseudo_inverse(eliminated[i], eliminated[j]) = sub(i, j);
        }

        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          K.vmult(y, x);
          const unsigned int m = B.size();
          if (m == 0)
            return;
          Vector<double> w(m), mu(m);
          for (unsigned int j = 0; j < m; ++j)
            w[j] = B[j] * x;
          pseudo_inverse.vmult(mu, w);
          for (unsigned int j = 0; j < m; ++j)
            y.add(-mu[j], B[j]);
        }

      private:
        const LA::SparseMatrix &K;
        std::vector<LA::Vector> B;
        FullMatrix<double>      pseudo_inverse;
      };

      /**
       * x = (K_c - sigma B)^{-1} y by the bordered solve on MUMPS' LDL^T
       * factorization of the shifted field block A = K - sigma B:
       * [A B; B^T AD] [x; mu] = [y; 0], mu = -S^{-1} B^T A^{-1} y with
       * S = AD - B^T A^{-1} B. Counts the eigenvalues below the shift.
       */
      class ShiftedInverse
      {
      public:
        ShiftedInverse(const MPI_Comm          comm,
                       const LA::SparseMatrix &A,
                       const BorderCoupling   &c,
                       const EnergyBorder     &e,
                       const IndexSet         &owned,
                       const bool              symmetric = true)
          : factorization(comm, 1e-12, symmetric)
          , owned(owned)
        {
          const Inertia k      = factorization.compute(A);
          zero_pivots          = k.zero;
          const unsigned int m = e.size();
          FullMatrix<double> S(m, m);
          for (unsigned int j = 0; j < m; ++j)
            B.emplace_back(c.B[e.kept[j]]);
          for (unsigned int j = 0; j < m; ++j)
            {
              Z.emplace_back(B[j].size());
              factorization.solve(B[j], Z[j]);
            }
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              S(i, j) = e.AD(i, j) - B[i] * Z[j];
          // Sylvester's count (an LU's pivots count nothing).
          negative  = symmetric
                        ? static_cast<long long>(k.negative)
                           + negative_eigenvalues(S) - static_cast<long long>(m)
                        : -1;
          S_inverse = S;
          if (m > 0)
            S_inverse.gauss_jordan();
        }

        void
        vmult(LA::Vector &x, const LA::Vector &y) const
        {
          ++solves;
          const Vector<double> b(y); // every entry, on every rank
          Vector<double>       z(b.size());
          factorization.solve(b, z);
          const unsigned int m = B.size();
          if (m > 0)
            {
              Vector<double> w(m), mu(m);
              for (unsigned int j = 0; j < m; ++j)
                w[j] = B[j] * z;
              S_inverse.vmult(mu, w);
              for (unsigned int j = 0; j < m; ++j)
                z.add(mu[j], Z[j]);
            }
          for (const auto i : owned)
            x[i] = z[i];
          x.compress(VectorOperation::insert);
        }

        /// x_j = (K_c - sigma B)^{-1} y_j for all j in one MUMPS solve.
        void
        vmult(std::vector<LA::Vector>       &x,
              const std::vector<LA::Vector> &y) const
        {
          std::vector<Vector<double>> b, z;
          for (const auto &v : y)
            b.emplace_back(v); // every entry, on every rank
          solves += y.size();
          factorization.solve(b, z);
          const unsigned int m = B.size();
          for (unsigned int k = 0; k < y.size(); ++k)
            {
              if (m > 0)
                {
                  Vector<double> w(m), mu(m);
                  for (unsigned int j = 0; j < m; ++j)
                    w[j] = B[j] * z[k];
                  S_inverse.vmult(mu, w);
                  for (unsigned int j = 0; j < m; ++j)
                    z[k].add(mu[j], Z[j]);
                }
              for (const auto i : owned)
                x[k][i] = z[k][i];
              x[k].compress(VectorOperation::insert);
            }
        }

        long long               negative    = 0;
        types::global_dof_index zero_pivots = 0;
        /// Substitutions done (ARPACK's operator applications).
        mutable unsigned int solves = 0;

      private:
        mutable SymmetricInertia    factorization;
        const IndexSet             &owned;
        std::vector<Vector<double>> B, Z;
        FullMatrix<double>          S_inverse;
      };

      /// The metric of the tangent problem: the identity on free dofs.
      class FreeIdentity
      {
      public:
        explicit FreeIdentity(const AffineConstraints<double> &constraints)
          : constraints(constraints)
        {
        }
        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          y = x;
          constraints.set_zero(y);
        }

      private:
        const AffineConstraints<double> &constraints;
      };

      /**
       * -K' on the free dofs, K' = dK_c/dt along the linear response
       * (u + s v, t + s) by the second-order one-sided difference
       * K' = (-3 K_c(0) + 4 K_c(h) - K_c(2h)) / (2h).
       */
      class TangentRate
      {
      public:
        TangentRate(const CondensedTangent          &K0,
                    const CondensedTangent          &K1,
                    const CondensedTangent          &K2,
                    const double                     h,
                    const AffineConstraints<double> &constraints)
          : K0(K0)
          , K1(K1)
          , K2(K2)
          , h(h)
          , constraints(constraints)
        {
        }
        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          LA::Vector free(x), y1(x), y2(x);
          constraints.set_zero(free);
          K0.vmult(y, free);
          K1.vmult(y1, free);
          K2.vmult(y2, free);
          y *= -3.;
          y.add(4., y1, -1., y2);
          y *= -1. / (2. * h);
          constraints.set_zero(y);
        }

      private:
        const CondensedTangent          &K0, &K1, &K2;
        const double                     h;
        const AffineConstraints<double> &constraints;
      };

      /**
       * The largest relative residual of the eigenpairs (mu_k, x_k) of
       * A x = mu B x, measured as the solver sees it (through the inverse
       * C = (K_c - sigma B)^{-1} of the shifted tangent, so that stiff and
       * soft dofs weigh alike): |C (A x - mu B x)| / (s |x|), s = 1 for
       * shift-and-invert (C (A - mu B) x = x - (mu - sigma) C B x) and
       * s = |mu| for buckling's mode 2 (C = A_metric^{-1}). One MUMPS solve
       * for all pairs.
       */
      template <typename OperatorA, typename OperatorB>
      double
      relative_residual(const OperatorA               &A,
                        const OperatorB               &B,
                        const ShiftedInverse          &inverse,
                        const std::vector<double>     &mu,
                        const std::vector<LA::Vector> &modes,
                        const bool                     scale_by_mu)
      {
        std::vector<LA::Vector> r(modes), cr(modes);
        for (unsigned int k = 0; k < modes.size(); ++k)
          {
            LA::Vector b(modes[k]);
            A.vmult(r[k], modes[k]);
            B.vmult(b, modes[k]);
            r[k].add(-mu[k], b);
          }
        inverse.vmult(cr, r);
        double worst = 0.;
        for (unsigned int k = 0; k < modes.size(); ++k)
          {
            const double scale =
              (scale_by_mu ? std::abs(mu[k]) : 1.) * modes[k].l2_norm();
            worst = std::max(worst, cr[k].l2_norm() / std::max(scale, 1e-300));
          }
        return worst;
      }

      /**
       * ARPACK's vectors: the model's partition, or, when some rank owns
       * no unknowns (PARPACK needs local ones on every rank: a scene of
       * cables alone, which one rank owns), a balanced one; the operators
       * then see the model's partition through this map.
       */
      class ArpackPartition
      {
      public:
        ArpackPartition(const IndexSet &model_owned, const MPI_Comm comm)
          : model_owned(model_owned)
          , comm(comm)
        {
          const types::global_dof_index empty =
            Utilities::MPI::min(static_cast<types::global_dof_index>(
                                  model_owned.n_elements()),
                                comm);
          repartitioned = empty == 0;
          if (!repartitioned)
            owned = model_owned;
          else
            {
              const types::global_dof_index n = model_owned.size();
              const unsigned int rank = Utilities::MPI::this_mpi_process(comm),
                                 p    = Utilities::MPI::n_mpi_processes(comm);
              owned                   = IndexSet(n);
              owned.add_range(n * rank / p, n * (rank + 1) / p);
            }
        }
        /// A vector of partition @p to with the entries of @p v.
        LA::Vector
        convert(const LA::Vector &v, const IndexSet &to) const
        {
          LA::Vector           result(to, comm);
          const Vector<double> all(v); // every entry, on every rank
          for (const auto i : to)
            result[i] = all[i];
          result.compress(VectorOperation::insert);
          return result;
        }
        LA::Vector
        to_model(const LA::Vector &v) const
        {
          return repartitioned ? convert(v, model_owned) : v;
        }
        LA::Vector
        to_arpack(const LA::Vector &v) const
        {
          return repartitioned ? convert(v, owned) : v;
        }

        const IndexSet &model_owned;
        const MPI_Comm  comm;
        IndexSet        owned;
        bool            repartitioned = false;
      };

      /// An operator of the model seen in ARPACK's partition.
      template <typename Operator>
      class InPartition
      {
      public:
        InPartition(const Operator &op, const ArpackPartition &partition)
          : op(op)
          , partition(partition)
        {
        }
        void
        vmult(LA::Vector &y, const LA::Vector &x) const
        {
          if (!partition.repartitioned)
            {
              op.vmult(y, x);
              return;
            }
          const LA::Vector x_model = partition.to_model(x);
          LA::Vector       y_model(x_model);
          op.vmult(y_model, x_model);
          y = partition.to_arpack(y_model);
        }

      private:
        const Operator        &op;
        const ArpackPartition &partition;
      };

      template <typename Operator>
      InPartition<Operator>
      in_partition(const Operator &op, const ArpackPartition &partition)
      {
        return InPartition<Operator>(op, partition);
      }

      /// Scale @p v to a largest component of +1 (the first such entry
      /// in the global numbering decides the sign: the same on any number
      /// of ranks).
      void
      normalize(LA::Vector &v, const IndexSet &owned, const MPI_Comm comm)
      {
        const double largest = v.linfty_norm();
        if (largest == 0.)
          return;
        types::global_dof_index first = numbers::invalid_dof_index;
        double                  sign  = 1.;
        for (const auto i : owned)
          if (std::abs(v[i]) >= (1. - 1e-9) * largest)
            {
              first = i;
              sign  = v[i] > 0. ? 1. : -1.;
              break;
            }
        const types::global_dof_index winner = Utilities::MPI::min(first, comm);
        const double s = Utilities::MPI::sum(first == winner ? sign : 0., comm);
        v *= s / largest;
      }
    } // namespace

    EigenResult
    EigenAnalysis::run(Model                 &model,
                       const BorderedVector  &state,
                       const double           t,
                       const EigenParameters &p,
                       const bool             assembled)
    {
      TimerOutput::Scope timing(model.timer(), "eigen analysis");
      Timer              wall;
      EigenResult        result;
      result.type                 = p.type;
      result.time                 = t;
      const MPI_Comm  comm        = model.mpi_communicator();
      const IndexSet &owned       = model.locally_owned();
      const auto     &constraints = model.constraints();
      try
        {
          // The tangent of the state and its chamber border.
          if (!assembled)
            {
              BorderedVector residual;
              residual.field.reinit(state.field);
              model.assemble(state, t, residual);
            }
          const LA::SparseMatrix &K = model.tangent_matrix();
          const BorderCoupling   &c = model.border_coupling();
          const EnergyBorder      e = energy_border(c);
          if (!e.energy_form)
            throw std::runtime_error(
              "the chamber terms are not of energy form (their columns are "
              "not in the span of their rows, or the combined border is not "
              "symmetric and negative semi-definite)");
          const double asym = asymmetry(K, owned);
          // Also where a subsystem says so (a smoothed contact normal,
          // friction in slip): the measure can miss a small, local part.
          const bool declared      = !model.symmetric_by_construction();
          const bool non_symmetric = p.solver == EigenSolver::non_symmetric
                                     || (p.solver == EigenSolver::automatic
                                         && (asym > 1e-8 || declared));
          if (p.type == EigenProblem::buckling && (asym > 1e-8 || declared))
            throw std::runtime_error(
              "linear buckling needs a symmetric tangent; this one is not "
              "(friction, follower pressure on free edges, or a smoothed "
              "contact normal)");
          result.non_symmetric = non_symmetric;
          result.asymmetry     = asym;

          // The dimension of the problem: free dofs less constraints.
          types::global_dof_index n_free = 0;
          for (const auto i : owned)
            if (!constraints.is_constrained(i))
              ++n_free;
          n_free = Utilities::MPI::sum(n_free, comm);
          const CondensedTangent K_c(K, c, e);
          unsigned int           n_constraints = 0;
          for (unsigned int i = 0; i < e.size(); ++i)
            if (std::abs(e.AD(i, i)) <= round_off * e.AD.linfty_norm())
              ++n_constraints;
          const types::global_dof_index n = n_free - n_constraints;
          if (p.n_modes + 1 >= n)
            throw std::runtime_error(
              "Eigen analysis/Number of modes (" + std::to_string(p.n_modes)
              + ") must be below the free unknowns less one ("
              + std::to_string(n > 0 ? n - 1 : 0) + ")");
          const ArpackPartition partition(owned, comm);
          // A start vector that is the same on any number of ranks.
          LA::Vector start(owned, comm);
          for (const auto i : owned)
            start[i] = 1. + 0.5 * std::sin(1.3 * i + 0.1);
          start.compress(VectorOperation::insert);
          constraints.set_zero(start);
          const bool buckling = p.type == EigenProblem::buckling;
          using Arpack        = PArpackSolver<LA::Vector>;
          // One ARPACK solve for @p nev eigenpairs (@p which of the
          // transformed problem) in ARPACK's partition; the eigenvalues
          // of A x = mu B x and the modes in the model's partition are
          // appended to mu and result.modes.
          std::vector<double> mu;
          const auto          solve = [&](const auto                    &A,
                                 const auto                    &B,
                                 const auto                    &C,
                                 const Arpack::WhichEigenvalues which,
                                 const unsigned int             nev,
                                 const double                   sigma) {
            const unsigned int ncv = static_cast<unsigned int>(
              std::min<types::global_dof_index>(n, std::max(2 * nev + 2, 20u)));
            SolverControl control(p.max_iterations, p.tolerance, false, false);
            const Arpack::AdditionalData data(ncv,
                                              which,
                                              !non_symmetric,
                                              buckling ? 2 : 3);
            Arpack                       solver(control, comm, data);
            solver.reinit(partition.owned);
            solver.set_initial_vector(partition.to_arpack(start));
            if (!buckling)
              solver.set_shift(sigma);
            // Arnoldi returns nev + 1 vectors (a complex pair's real and
            // imaginary parts side by side).
            std::vector<std::complex<double>> lambda(nev + 1);
            std::vector<LA::Vector>           modes(nev + 1,
                                          LA::Vector(partition.owned, comm));
            try
              {
                solver.solve(in_partition(A, partition),
                             in_partition(B, partition),
                             in_partition(C, partition),
                             lambda,
                             modes,
                             nev);
              }
            catch (const ExceptionBase &)
              {
                // deal.II's multi-line report of ARPACK's info code.
                std::ostringstream m;
                m << "ARPACK did not find " << nev
                  << " converged eigenpairs within Eigen analysis/Maximum "
                              "iterations = "
                  << p.max_iterations
                  << " to Eigen analysis/Tolerance = " << p.tolerance;
                throw std::runtime_error(m.str());
              }
            result.iterations += control.last_step();
            for (unsigned int k = 0; k < nev; ++k)
              {
                mu.push_back(lambda[k].real());
                result.modes.push_back(partition.to_model(modes[k]));
                if (std::abs(lambda[k]) > 0.)
                  result.imaginary =
                    std::max(result.imaginary,
                             std::abs(lambda[k].imag()) / std::abs(lambda[k]));
              }
          };
          // The lowest eigenvalues by shift-and-invert at sigma, whose
          // factorization counts the n_below eigenvalues under sigma:
          // those are the most negative of 1/(lambda - sigma) (all of
          // them), the rest the largest positive.
          const auto lowest = [&](const auto     &A,
                                  const auto     &B,
                                  const auto     &C,
                                  const double    sigma,
                                  const long long n_below) {
            const unsigned int below =
              std::min<long long>(std::max(n_below, 0ll), p.n_modes);
            if (below > 0)
              solve(A, B, C, Arpack::algebraically_smallest, below, sigma);
            if (p.n_modes > below)
              solve(A,
                    B,
                    C,
                    Arpack::algebraically_largest,
                    p.n_modes - below,
                    sigma);
          };

          // The mass of a modal analysis (for the solve and the effective
          // masses).
          LA::SparseMatrix M;
          if (p.type == EigenProblem::tangent || p.type == EigenProblem::modal)
            {
              LA::SparseMatrix shifted;
              const double     sigma = p.type == EigenProblem::modal
                                         ? std::pow(2. * M_PI * p.shift, 2)
                                         : p.shift;
              shifted.copy_from(K);
              if (p.type == EigenProblem::modal)
                {
                  model.assemble_mass(M);
                  if (M.frobenius_norm() == 0.)
                    throw std::runtime_error(
                      "the model has no mass: give a density to the "
                      "membrane regions (Materials/.../Density) or the "
                      "cables (Cables/.../Density)");
                  shifted.add(-sigma, M);
                }
              else if (sigma != 0.)
                {
                  for (const auto i : owned)
                    if (!constraints.is_constrained(i))
                      shifted.add(i, i, -sigma);
                  shifted.compress(VectorOperation::add);
                }
              Timer                factorizing;
              const ShiftedInverse inverse(
                comm, shifted, c, e, owned, !non_symmetric);
              result.factorization_seconds = factorizing.wall_time();
              if (inverse.zero_pivots > 0)
                throw std::runtime_error(
                  "the tangent minus the shift is singular (an eigenvalue "
                  "at the shift, or a free rigid motion): change Eigen "
                  "analysis/Shift");
              result.below_shift = inverse.negative;
              const FreeIdentity I(constraints);
              // Non-symmetric: the eigenvalues nearest the shift (no
              // count to find those below it first).
              if (non_symmetric && p.type == EigenProblem::modal)
                solve(
                  K_c, M, inverse, Arpack::largest_magnitude, p.n_modes, sigma);
              else if (non_symmetric)
                solve(
                  K_c, I, inverse, Arpack::largest_magnitude, p.n_modes, sigma);
              else if (p.type == EigenProblem::modal)
                lowest(K_c, M, inverse, sigma, inverse.negative);
              else
                lowest(K_c, I, inverse, sigma, inverse.negative);
              result.values = mu;
              result.residual =
                p.type == EigenProblem::modal
                  ? relative_residual(
                    K_c, M, inverse, result.values, result.modes, false)
                  : relative_residual(
                    K_c, I, inverse, result.values, result.modes, false);
              result.substitutions = inverse.solves;
            }
          else
            {
              // The base state must be stable: K_c is the metric.
              Timer                factorizing;
              const ShiftedInverse inverse(comm, K, c, e, owned);
              result.factorization_seconds = factorizing.wall_time();
              if (inverse.negative > 0 || inverse.zero_pivots > 0)
                throw std::runtime_error(
                  "linear buckling needs a stable state; this one has "
                  + std::to_string(inverse.negative)
                  + " negative eigenvalue(s) and "
                  + std::to_string(inverse.zero_pivots) + " zero pivot(s)");
              result.below_shift = 0;
              // The state's rate du/dt under the loads' rate dR/dt (from
              // the left: the loads of the step that led here).
              // h: 1e-3 of the pseudo time (second order: the tangent
              // of a nonlinear prebuckling path to about 1e-6; the
              // difference of tangents is not lost in round-off).
              const double   t0 = t;
              const double   h  = t0 > 0. ? -1e-3 * t0 : 1e-3;
              BorderedVector r0, rh, rate, v;
              r0.field.reinit(state.field);
              rh.field.reinit(state.field);
              model.assemble_residual(state, t0, r0);
              model.assemble_residual(state, t0 + 1e-3 * h, rh);
              rate = rh;
              rate -= r0;
              rate *= -1. / (1e-3 * h);
              v = rate;
              model.solve_linear(0., rate, v);
              if (v.l2_norm() == 0.)
                throw std::runtime_error(
                  "no load changes at the final state (linear buckling "
                  "follows the rate of the loads of the last stage)");
              std::array<LA::SparseMatrix, 2> Kh;
              std::array<BorderCoupling, 2>   ch;
              std::vector<EnergyBorder>       eh;
              std::vector<CondensedTangent>   Kh_c;
              for (unsigned int s = 0; s < 2; ++s)
                {
                  BorderedVector shifted_state(state);
                  shifted_state.add((s + 1) * h, v);
                  Kh[s].copy_from(K);
                  model.assemble_tangent(shifted_state,
                                         t0 + (s + 1) * h,
                                         Kh[s],
                                         ch[s]);
                  eh.push_back(energy_border(ch[s]));
                }
              for (unsigned int s = 0; s < 2; ++s)
                Kh_c.emplace_back(Kh[s], ch[s], eh[s]);
              const TangentRate rate_op(K_c, Kh_c[0], Kh_c[1], h, constraints);
              // The largest nu = 1/lambda.
              solve(rate_op,
                    K_c,
                    inverse,
                    Arpack::algebraically_largest,
                    p.n_modes,
                    0.);
              for (const double nu : mu)
                {
                  if (nu == 0.)
                    throw std::runtime_error(
                      "a buckling mode has no load factor (nu = 0)");
                  result.values.push_back(1. / nu);
                }
              result.residual = relative_residual(
                rate_op, K_c, inverse, mu, result.modes, true);
              result.substitutions = inverse.solves;
            }

          // Modal: effective masses (the mass that moves with each mode
          // under a base motion along x, y, z).
          if (p.type == EigenProblem::modal)
            {
              std::array<LA::Vector, 3> Mr;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const LA::Vector r = model.rigid_translation(d);
                  Mr[d].reinit(r);
                  M.vmult(Mr[d], r);
                  if (d == 0)
                    result.total_mass = r * Mr[d];
                }
              for (const auto &phi : result.modes)
                {
                  LA::Vector Mphi(phi);
                  M.vmult(Mphi, phi);
                  const double          m = phi * Mphi;
                  std::array<double, 3> e;
                  for (unsigned int d = 0; d < 3; ++d)
                    e[d] = m > 0. ? std::pow(phi * Mr[d], 2) / m : 0.;
                  result.effective_mass.push_back(e);
                }
            }

          // Ascending values (buckling: positive factors first), unit
          // largest component.
          std::vector<unsigned int> order(result.values.size());
          std::iota(order.begin(), order.end(), 0u);
          auto key = [&](const unsigned int i) {
            const double v = result.values[i];
            return buckling && v < 0.
                     ? std::numeric_limits<double>::max() / 2 - v
                     : v;
          };
          std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
            return key(a) < key(b);
          });
          std::vector<double>                values;
          std::vector<LA::Vector>            modes;
          std::vector<std::array<double, 3>> effective;
          for (const auto i : order)
            {
              values.push_back(result.values[i]);
              modes.push_back(result.modes[i]);
              normalize(modes.back(), owned, comm);
              if (!result.effective_mass.empty())
                effective.push_back(result.effective_mass[i]);
            }
          result.values         = values;
          result.modes          = modes;
          result.effective_mass = effective;
          for (const double v : result.values)
            if (!std::isfinite(v))
              throw std::runtime_error("an eigenvalue is not finite");
          result.computed = true;
          result.seconds  = wall.wall_time();
        }
      catch (const std::exception &e)
        {
          result.computed = false;
          result.values.clear();
          result.modes.clear();
          result.error = e.what();
        }
      return result;
    }
  } // namespace solvers
} // namespace pneuma
