#include <deal.II/base/timer.h>

#include <deal.II/lac/parpack_solver.h>
#include <deal.II/lac/solver_control.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/eigen_analysis.h>

#include "eigen_operators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace pneuma
{
  namespace solvers
  {
    using namespace dealii;
    using namespace eigen;

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
      using Arpack = PArpackSolver<LA::Vector>;

      /// One eigen analysis of a converged state (EigenAnalysis::run): its
      /// operators, ARPACK's solves, and the modes sorted.
      class EigenSolve
      {
      public:
        EigenSolve(Model                 &model,
                   const BorderedVector  &state,
                   const double           t,
                   const EigenParameters &p,
                   EigenResult           &result)
          : model(model)
          , state(state)
          , t(t)
          , p(p)
          , result(result)
          , comm(model.mpi_communicator())
          , owned(model.locally_owned())
          , constraints(model.constraints())
          , partition(owned, comm)
        {
        }

        /// The tangent of the state with its border (assembled unless
        /// @p assembled), the solver's kind, the problem's dimension, a
        /// start vector.
        void
        prepare(const bool assembled);
        /// Tangent and modal problems: shift-and-invert (ARPACK mode 3).
        void
        shift_invert();
        /// Linear buckling: (K_c + lambda K') phi = 0 (mode 2).
        void
        buckling();
        /// Modal: the effective mass of each mode along x, y, z.
        void
        effective_masses();
        /// Ascending values (buckling: positive factors first), modes
        /// scaled to a largest component of +1.
        void
        sort();

      private:
        /// One ARPACK solve for @p nev eigenpairs (@p which of the
        /// transformed problem A x = mu B x with the inverse C) in
        /// ARPACK's partition; mu and the modes (model's partition) are
        /// appended.
        template <typename A, typename B, typename C>
        void
        arpack(const A                       &a,
               const B                       &b,
               const C                       &c,
               const Arpack::WhichEigenvalues which,
               const unsigned int             nev,
               const double                   sigma);
        /// The lowest eigenvalues by shift-and-invert at sigma, whose
        /// factorization counts the @p n_below eigenvalues under sigma:
        /// those are the most negative of 1/(lambda - sigma) (all of
        /// them), the rest the largest positive.
        template <typename A, typename B, typename C>
        void
        lowest(const A        &a,
               const B        &b,
               const C        &c,
               const double    sigma,
               const long long n_below);
        /// The state's rate du/dt under the loads' rate at t0 (from the
        /// left), by one substitution; throws if no load changes.
        BorderedVector
        load_rate(const double t0, const double h);

        /// The condensed tangents at (state + k ds v, t + k dt), k = 1, 2.
        struct ShiftedTangents
        {
          std::array<LA::SparseMatrix, 2> K;
          std::array<BorderCoupling, 2>   c;
          std::vector<EnergyBorder>       e;
          std::vector<CondensedTangent>   K_c;
        };
        void
        shifted_tangents(const BorderedVector &v,
                         const double          ds,
                         const double          dt,
                         ShiftedTangents      &out) const;
        /// |(K_1 - K_c) v| / |K_c v| on the free dofs: the relative
        /// change of the tangent over the first shift.
        double
        relative_change(const CondensedTangent &K_1,
                        const BorderedVector   &v) const;

        Model                            &model;
        const BorderedVector             &state;
        const double                      t;
        const EigenParameters            &p;
        EigenResult                      &result;
        const MPI_Comm                    comm;
        const IndexSet                   &owned;
        const AffineConstraints<double>  &constraints;
        const ArpackPartition             partition;
        EnergyBorder                      border;
        std::unique_ptr<CondensedTangent> K_c;
        bool                              non_symmetric = false;
        /// The dimension: free dofs less constraints.
        types::global_dof_index n = 0;
        /// A start vector that is the same on any number of ranks.
        LA::Vector start;
        /// The eigenvalues of the transformed problems solved.
        std::vector<double> mu;
        /// The mass of a modal analysis.
        LA::SparseMatrix M;
      };

      void
      EigenSolve::prepare(const bool assembled)
      {
        if (!assembled)
          {
            BorderedVector residual;
            residual.field.reinit(state.field);
            model.assemble(state, t, residual);
          }
        const LA::SparseMatrix &K = model.tangent_matrix();
        border                    = energy_border(model.border_coupling());
        if (!border.energy_form)
          throw std::runtime_error(
            "the chamber terms are not of energy form (their columns are "
            "not in the span of their rows, or the combined border is not "
            "symmetric and negative semi-definite)");
        const double asym = asymmetry(K, owned);
        // Also where a subsystem says so (a smoothed contact normal,
        // friction in slip): the measure can miss a small, local part.
        const bool declared = !model.symmetric_by_construction();
        non_symmetric =
          p.solver == EigenSolver::non_symmetric
          || (p.solver == EigenSolver::automatic && (asym > 1e-8 || declared));
        if (p.type == EigenProblem::buckling && (asym > 1e-8 || declared))
          throw std::runtime_error(
            "linear buckling needs a symmetric tangent; this one is not "
            "(friction, follower pressure on free edges, or a smoothed "
            "contact normal)");
        result.non_symmetric           = non_symmetric;
        result.asymmetry               = asym;
        types::global_dof_index n_free = 0;
        for (const auto i : owned)
          if (!constraints.is_constrained(i))
            ++n_free;
        n_free                     = Utilities::MPI::sum(n_free, comm);
        K_c                        = std::make_unique<CondensedTangent>(K,
                                                 model.border_coupling(),
                                                 border);
        unsigned int n_constraints = 0;
        for (unsigned int i = 0; i < border.size(); ++i)
          if (std::abs(border.AD(i, i)) <= round_off * border.AD.linfty_norm())
            ++n_constraints;
        n = n_free - n_constraints;
        if (p.n_modes + 1 >= n)
          throw std::runtime_error(
            "Eigen analysis/Number of modes (" + std::to_string(p.n_modes)
            + ") must be below the free unknowns less one ("
            + std::to_string(n > 0 ? n - 1 : 0) + ")");
        start.reinit(owned, comm);
        for (const auto i : owned)
          start[i] = 1. + 0.5 * std::sin(1.3 * i + 0.1);
        start.compress(VectorOperation::insert);
        constraints.set_zero(start);
      }

      template <typename A, typename B, typename C>
      void
      EigenSolve::arpack(const A                       &a,
                         const B                       &b,
                         const C                       &c,
                         const Arpack::WhichEigenvalues which,
                         const unsigned int             nev,
                         const double                   sigma)
      {
        const bool         buckling = p.type == EigenProblem::buckling;
        const unsigned int ncv      = static_cast<unsigned int>(
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
            solver.solve(in_partition(a, partition),
                         in_partition(b, partition),
                         in_partition(c, partition),
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
      }

      template <typename A, typename B, typename C>
      void
      EigenSolve::lowest(const A        &a,
                         const B        &b,
                         const C        &c,
                         const double    sigma,
                         const long long n_below)
      {
        const unsigned int below =
          std::min<long long>(std::max(n_below, 0ll), p.n_modes);
        if (below > 0)
          arpack(a, b, c, Arpack::algebraically_smallest, below, sigma);
        if (p.n_modes > below)
          arpack(
            a, b, c, Arpack::algebraically_largest, p.n_modes - below, sigma);
      }

      void
      EigenSolve::shift_invert()
      {
        const bool              modal = p.type == EigenProblem::modal;
        const LA::SparseMatrix &K     = model.tangent_matrix();
        LA::SparseMatrix        shifted;
        const double sigma = modal ? std::pow(2. * M_PI * p.shift, 2) : p.shift;
        shifted.copy_from(K);
        if (modal)
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
        const ShiftedInverse inverse(comm,
                                     shifted,
                                     model.border_coupling(),
                                     border,
                                     owned,
                                     !non_symmetric);
        result.factorization_seconds = factorizing.wall_time();
        result.singular              = inverse.zero_pivots > 0;
        if (result.singular)
          throw std::runtime_error(
            "the tangent minus the shift is singular (an eigenvalue "
            "at the shift, or a free rigid motion): change Eigen "
            "analysis/Shift");
        result.below_shift = inverse.negative;
        const FreeIdentity I(constraints);
        // Non-symmetric: the eigenvalues nearest the shift (no count to
        // find those below it first).
        if (non_symmetric && modal)
          arpack(*K_c, M, inverse, Arpack::largest_magnitude, p.n_modes, sigma);
        else if (non_symmetric)
          arpack(*K_c, I, inverse, Arpack::largest_magnitude, p.n_modes, sigma);
        else if (modal)
          lowest(*K_c, M, inverse, sigma, inverse.negative);
        else
          lowest(*K_c, I, inverse, sigma, inverse.negative);
        result.values = mu;
        result.residual =
          modal ? relative_residual(
            *K_c, M, inverse, result.values, result.modes, false)
                : relative_residual(
                  *K_c, I, inverse, result.values, result.modes, false);
        result.substitutions = inverse.solves;
      }

      BorderedVector
      EigenSolve::load_rate(const double t0, const double h)
      {
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
        return v;
      }

      void
      EigenSolve::shifted_tangents(const BorderedVector &v,
                                   const double          ds,
                                   const double          dt,
                                   ShiftedTangents      &out) const
      {
        for (unsigned int k = 0; k < 2; ++k)
          {
            BorderedVector shifted_state(state);
            shifted_state.add((k + 1) * ds, v);
            out.K[k].copy_from(model.tangent_matrix());
            model.assemble_tangent(shifted_state,
                                   t + (k + 1) * dt,
                                   out.K[k],
                                   out.c[k]);
            out.e.push_back(energy_border(out.c[k]));
          }
        for (unsigned int k = 0; k < 2; ++k)
          out.K_c.emplace_back(out.K[k], out.c[k], out.e[k]);
      }

      double
      EigenSolve::relative_change(const CondensedTangent &K_1,
                                  const BorderedVector   &v) const
      {
        LA::Vector free(v.field), y0(v.field), y1(v.field);
        constraints.set_zero(free);
        K_c->vmult(y0, free);
        K_1.vmult(y1, free);
        constraints.set_zero(y0);
        constraints.set_zero(y1);
        y1 -= y0;
        const double norm = y0.l2_norm();
        return norm > 0. ? y1.l2_norm() / norm : 0.;
      }

      void
      EigenSolve::buckling()
      {
        // The base state must be stable: K_c is the metric.
        const LA::SparseMatrix &K = model.tangent_matrix();
        Timer                   factorizing;
        const ShiftedInverse    inverse(
          comm, K, model.border_coupling(), border, owned);
        result.factorization_seconds = factorizing.wall_time();
        if (inverse.negative > 0 || inverse.zero_pivots > 0)
          throw std::runtime_error(
            "linear buckling needs a stable state; this one has "
            + std::to_string(inverse.negative) + " negative eigenvalue(s) and "
            + std::to_string(inverse.zero_pivots) + " zero pivot(s)");
        result.below_shift = 0;
        // The state's rate du/dt under the loads' rate dR/dt (from the
        // left: the loads of the step that led here). h: 1e-3 of the
        // pseudo time (second order: the tangent of a nonlinear
        // prebuckling path to about 1e-6).
        const double         h = t > 0. ? -1e-3 * t : 1e-3;
        const BorderedVector v = load_rate(t, h);
        ShiftedTangents      along;
        shifted_tangents(v, h, h, along);
        // The tangent's change over the step must stand clear of the
        // round-off of the tangent itself (whose membrane stiffness E t
        // can exceed the load's stiffness by 1e6 and more under a
        // reference load far below the buckling load): where it changes
        // by less than 1e-6, the state's part of the derivative takes a
        // longer step (up to a tenth of the state), the loads' part keeps
        // h (at the same state their difference has no round-off).
        const double change = relative_change(along.K_c[0], v);
        const double longer =
          change > 0. ? std::min(1e-6 / change, 0.1 * std::abs(t / h)) : 1.;
        ShiftedTangents              state_part, load_part;
        std::unique_ptr<TangentRate> load_rate_part;
        std::unique_ptr<TangentRate> rate;
        if (longer <= 1.)
          rate = std::make_unique<TangentRate>(
            *K_c, along.K_c[0], along.K_c[1], h, constraints);
        else
          {
            shifted_tangents(v, longer * h, 0., state_part);
            shifted_tangents(v, 0., h, load_part);
            load_rate_part = std::make_unique<TangentRate>(
              *K_c, load_part.K_c[0], load_part.K_c[1], h, constraints);
            rate = std::make_unique<TangentRate>(*K_c,
                                                 state_part.K_c[0],
                                                 state_part.K_c[1],
                                                 longer * h,
                                                 constraints,
                                                 load_rate_part.get());
          }
        // The largest nu = 1/lambda.
        arpack(
          *rate, *K_c, inverse, Arpack::algebraically_largest, p.n_modes, 0.);
        for (const double nu : mu)
          {
            if (nu == 0.)
              throw std::runtime_error(
                "a buckling mode has no load factor (nu = 0)");
            result.values.push_back(1. / nu);
          }
        result.residual =
          relative_residual(*rate, *K_c, inverse, mu, result.modes, true);
        result.substitutions = inverse.solves;
      }

      void
      EigenSolve::effective_masses()
      {
        // The mass that moves with each mode under a base motion along
        // x, y, z.
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

      void
      EigenSolve::sort()
      {
        const bool                buckling = p.type == EigenProblem::buckling;
        std::vector<unsigned int> order(result.values.size());
        std::iota(order.begin(), order.end(), 0u);
        const auto key = [&](const unsigned int i) {
          const double v = result.values[i];
          return buckling && v < 0. ? std::numeric_limits<double>::max() / 2 - v
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
      result.type = p.type;
      result.time = t;
      try
        {
          EigenSolve solve(model, state, t, p, result);
          solve.prepare(assembled);
          if (p.type == EigenProblem::buckling)
            solve.buckling();
          else
            solve.shift_invert();
          if (p.type == EigenProblem::modal)
            solve.effective_masses();
          solve.sort();
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
