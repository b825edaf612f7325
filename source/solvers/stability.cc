#include <deal.II/lac/lapack_full_matrix.h>

#include <pneuma/core/model.h>
#include <pneuma/solvers/eigen_analysis.h>
#include <pneuma/solvers/stability.h>

#include <algorithm>
#include <cmath>

namespace pneuma
{
  namespace solvers
  {
    namespace
    {
      /// Relative size below which a border eigenvalue or a deviation from
      /// proportionality is round-off.
      constexpr double round_off = 1e-8;
      /// Newton's factorization counts for a converged state within this
      /// relative distance of its iterate (Model::newton_inertia()).
      constexpr double newton_reuse = 1e-5;
      /// Eigenvalues nearest zero whose real parts are counted for a
      /// non-symmetric tangent.
      constexpr unsigned int nearest_for_count = 6;
    } // namespace

    long long
    negative_eigenvalues(const FullMatrix<double> &S)
    {
      const unsigned int m = S.m();
      if (m == 0)
        return 0;
      // The unknowns have different units (a pressure, a level): the
      // congruence d S d with d_i = |S_ii|^(-1/2) keeps the inertia
      // (Sylvester) and brings the entries to one scale, so that the
      // round-off threshold below does not take a small eigenvalue of one
      // unit for zero.
      std::vector<double> d(m, 1.);
      for (unsigned int i = 0; i < m; ++i)
        if (S(i, i) != 0.)
          d[i] = 1. / std::sqrt(std::abs(S(i, i)));
      LAPACKFullMatrix<double> lapack(m, m);
      double                   scale = 0.;
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          {
            lapack(i, j) = 0.5 * (S(i, j) + S(j, i)) * d[i] * d[j];
            scale        = std::max(scale, std::abs(lapack(i, j)));
          }
      lapack.compute_eigenvalues();
      long long n = 0;
      for (unsigned int i = 0; i < m; ++i)
        if (lapack.eigenvalue(i).real() < -round_off * scale)
          ++n;
      return n;
    }

    double
    asymmetry(const LA::SparseMatrix &K, const IndexSet &owned)
    {
      LA::Vector x(owned, K.get_mpi_communicator()), y(x), Kx(x), Ky(x);
      for (const auto i : owned)
        {
          x[i] = std::sin(1.3 * i + 0.1);
          y[i] = std::cos(0.7 * i + 0.2);
        }
      x.compress(VectorOperation::insert);
      y.compress(VectorOperation::insert);
      K.vmult(Kx, x);
      K.vmult(Ky, y);
      return std::abs(y * Kx - x * Ky)
             / std::max(Kx.l2_norm() * y.l2_norm(), 1e-300);
    }

    EnergyBorder
    energy_border(const BorderCoupling &c)
    {
      EnergyBorder e;
      for (unsigned int j = 0; j < c.size(); ++j)
        if (c.has_B[j] && c.has_C[j] && c.B[j].l2_norm() > 0.
            && c.C[j].l2_norm() > 0.)
          e.kept.push_back(j);
      const unsigned int m = e.kept.size();
      for (const auto j : e.kept)
        e.n_dual += j < c.primal.size() && c.primal[j] ? 0 : 1;
      e.X.reinit(m, m);
      e.AD.reinit(m, m);
      if (m == 0)
        return e;
      // Each column its own row (gas, liquid level, volume constraint):
      // X = diag(alpha_j), alpha_j = B_j.C_j / |C_j|^2. Rows of chambers
      // whose only free wall is a shared one are parallel, so this comes
      // first.
      const auto off_span = [&](const FullMatrix<double> &X) {
        for (unsigned int j = 0; j < m; ++j)
          {
            LA::Vector d(c.B[e.kept[j]]);
            for (unsigned int i = 0; i < m; ++i)
              if (X(i, j) != 0.)
                d.add(-X(i, j), c.C[e.kept[i]]);
            if (!(d.l2_norm() <= round_off * c.B[e.kept[j]].l2_norm()))
              return true;
          }
        return false;
      };
      for (unsigned int j = 0; j < m; ++j)
        e.X(j, j) =
          (c.B[e.kept[j]] * c.C[e.kept[j]]) / (c.C[e.kept[j]] * c.C[e.kept[j]]);
      if (off_span(e.X))
        {
          // Coupled rows (liquid and gas in one chamber): X from the
          // normal equations (C C^T) X = C B, by the pseudo-inverse of the
          // Gram matrix.
          // Rows scaled to unit length: the Gram matrix then has a unit
          // diagonal and its condition measures only the angles between
          // the rows (a gas row is kappa times larger than a level row).
          std::vector<double> norm(m);
          for (unsigned int i = 0; i < m; ++i)
            norm[i] = c.C[e.kept[i]].l2_norm();
          LAPACKFullMatrix<double> gram(m, m);
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              gram(i, j) =
                (c.C[e.kept[i]] * c.C[e.kept[j]]) / (norm[i] * norm[j]);
          // Drops singular values below 1e-12 of the largest; the inverse
          // lives in the factors (vmult), not in the entries.
          gram.compute_inverse_svd(1e-12);
          Vector<double> CB_j(m), X_j(m);
          for (unsigned int j = 0; j < m; ++j)
            {
              for (unsigned int i = 0; i < m; ++i)
                CB_j[i] = (c.C[e.kept[i]] * c.B[e.kept[j]]) / norm[i];
              gram.vmult(X_j, CB_j);
              for (unsigned int i = 0; i < m; ++i)
                e.X(i, j) = X_j[i] / norm[i];
            }
          if (off_span(e.X))
            e.energy_form = false;
        }
      // A D = X^T D over the kept unknowns: symmetric and negative
      // semi-definite in the energy form.
      double scale = 0.;
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          {
            for (unsigned int k = 0; k < m; ++k)
              e.AD(i, j) += e.X(k, i) * c.D(e.kept[k], e.kept[j]);
            scale = std::max(scale, std::abs(e.AD(i, j)));
          }
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < i; ++j)
          {
            if (std::abs(e.AD(i, j) - e.AD(j, i)) > round_off * scale)
              e.energy_form = false;
            e.AD(i, j) = e.AD(j, i) = 0.5 * (e.AD(i, j) + e.AD(j, i));
          }
      // (Over the multipliers: a primal unknown's A D is its positive
      // stiffness.)
      std::vector<unsigned int> dual;
      for (unsigned int i = 0; i < m; ++i)
        if (!(e.kept[i] < c.primal.size() && c.primal[e.kept[i]]))
          dual.push_back(i);
      FullMatrix<double> minus_AD(dual.size(), dual.size());
      for (unsigned int i = 0; i < dual.size(); ++i)
        for (unsigned int j = 0; j < dual.size(); ++j)
          minus_AD(i, j) = -e.AD(dual[i], dual[j]);
      if (scale > 0. && negative_eigenvalues(minus_AD) > 0)
        e.energy_form = false;
      return e;
    }

    StabilityCheck::StabilityCheck(const MPI_Comm comm)
      : inertia(comm)
    {
    }

    StabilityReport
    StabilityCheck::check(Model                &model,
                          const BorderedVector &state,
                          const double          t,
                          const bool            exact)
    {
      TimerOutput::Scope scope(model.timer(), "stability");
      StabilityReport    report;
      // Newton's convergence test assembled the converged state already.
      if (!model.tangent_is_at(state, t))
        {
          BorderedVector residual;
          residual.field.reinit(state.field);
          model.assemble(state, t, residual);
        }
      const LA::SparseMatrix &K = model.tangent_matrix();

      report.asymmetry = asymmetry(K, model.locally_owned());
      // Not symmetric by construction (a smoothed contact normal, friction
      // in slip): the measure can miss a small, local asymmetric part.
      const bool non_symmetric =
        report.asymmetry > round_off || !model.symmetric_by_construction();

      // Newton's last factorization, the LDL^T of the tangent at the
      // iterate before the last (vanishing) update, counts at no cost;
      // else (an LU, a shifted or older factorization) factorize here.
      Inertia    k;
      const bool reuse = !exact && !non_symmetric
                         && model.newton_inertia(state, newton_reuse, k);
      if (!reuse)
        k = inertia.compute(K);
      report.from_newton    = reuse;
      report.negative_field = k.negative;
      report.zero           = k.zero;
      report.computed       = true;

      // The coupled chamber unknowns in energy form (see the header).
      const BorderCoupling &c = model.border_coupling();
      const EnergyBorder    e = energy_border(c);
      report.energy_form      = e.energy_form;
      const unsigned int m    = e.size();
      FullMatrix<double> S(m, m);
      if (m > 0)
        {
          if (k.zero > 0)
            report.note = "the field tangent is singular";
          // S = A D - B^T K^{-1} B: one substitution per unknown.
          if (reuse)
            {
              // On Newton's factorization all m in one pass over the
              // factors, and the products distributed (a copy of each
              // column on every rank cost 1.2 % of Figure 11's run).
              std::vector<LA::Vector>         Z;
              std::vector<LA::Vector *>       z_ptr;
              std::vector<const LA::Vector *> b_ptr;
              Z.reserve(m);
              for (unsigned int j = 0; j < m; ++j)
                {
                  Z.emplace_back(c.B[e.kept[j]]);
                  z_ptr.push_back(&Z.back());
                  b_ptr.push_back(&c.B[e.kept[j]]);
                }
              model.linear_solver().solve(K, z_ptr, b_ptr);
              for (unsigned int j = 0; j < m; ++j)
                for (unsigned int i = 0; i < m; ++i)
                  S(i, j) = e.AD(i, j) - c.B[e.kept[i]] * Z[j];
            }
          else
            {
              // This check's own factorization solves on whole vectors.
              std::vector<Vector<double>> B(m);
              for (unsigned int i = 0; i < m; ++i)
                B[i] = c.B[e.kept[i]];
              for (unsigned int j = 0; j < m; ++j)
                {
                  Vector<double> z(B[j].size());
                  inertia.solve(B[j], z);
                  for (unsigned int i = 0; i < m; ++i)
                    S(i, j) = e.AD(i, j) - B[i] * z;
                }
            }
        }
      report.negative = k.negative + negative_eigenvalues(S) - e.n_dual;
      if (!report.energy_form)
        {
          report.negative = -1;
          report.note     = "the chamber terms are not of energy form (their "
                            "columns are not in the span of their rows): only "
                            "the count under prescribed pressures is known";
        }
      // A non-symmetric tangent (friction in slip, follower pressure on
      // free edges): Sylvester's law does not apply; count the negative
      // real parts among the eigenvalues nearest zero (Arnoldi on the LU,
      // solvers/eigen_analysis.h).
      if (non_symmetric && report.note.empty())
        {
          EigenParameters p;
          p.type              = EigenProblem::tangent;
          p.n_modes           = nearest_for_count;
          p.solver            = EigenSolver::non_symmetric;
          const EigenResult e = EigenAnalysis::run(model, state, t, p, true);
          if (e.computed)
            {
              report.negative =
                std::count_if(e.values.begin(),
                              e.values.end(),
                              [](const double v) { return v < 0.; });
              report.note =
                "the tangent is not symmetric (friction, follower pressure "
                "on free edges, a smoothed contact normal): the count is "
                "that of the negative "
                "real parts among its "
                + std::to_string(nearest_for_count)
                + " eigenvalues nearest zero (Arnoldi)";
            }
          else
            report.note = "the tangent is not symmetric (friction, or "
                          "follower pressure on free edges) and its eigen "
                          "solve failed ("
                          + e.error
                          + "): the count is that of its upper triangle";
        }
      return report;
    }
  } // namespace solvers
} // namespace pneuma
