#include <pneuma/solvers/border.h>
#include <pneuma/solvers/linear_solver.h>

namespace pneuma
{
  namespace solvers
  {
    void
    BorderCoupling::reinit(const unsigned int n, const LA::Vector &field)
    {
      B.assign(n, field);
      C.assign(n, field);
      has_B.assign(n, false);
      has_C.assign(n, false);
      primal.assign(n, false);
      D.reinit(n, n);
      unknown_scale.assign(n, 1.);
      residual_scale.assign(n, 1.);
    }

    void
    BorderCoupling::clear()
    {
      has_B.assign(size(), false);
      has_C.assign(size(), false);
      D = 0.;
    }

    void
    BorderCoupling::solve(LinearSolver           &solver,
                          const LA::SparseMatrix &K,
                          const BorderedVector   &rhs,
                          BorderedVector         &dx) const
    {
      const unsigned int  m = size();
      std::vector<double> r_g(m), dl(m, 0.);
      for (unsigned int j = 0; j < m; ++j)
        r_g[j] = rhs.border[j] / residual_scale[j];

      // Unknowns whose row involves neither u nor another unknown.
      std::vector<bool> decoupled(m, false);
      for (unsigned int j = 0; j < m; ++j)
        {
          bool only_diagonal = !has_C[j] && D(j, j) != 0.;
          for (unsigned int k = 0; k < m; ++k)
            if (k != j && D(j, k) != 0.)
              only_diagonal = false;
          decoupled[j] = only_diagonal;
        }
      LA::Vector rhs_u(rhs.field);
      for (unsigned int j = 0; j < m; ++j)
        if (decoupled[j])
          {
            dl[j] = r_g[j] / D(j, j);
            if (has_B[j])
              rhs_u.add(-dl[j], B[j]);
          }

      std::vector<unsigned int> coupled;
      for (unsigned int j = 0; j < m; ++j)
        if (!decoupled[j])
          coupled.push_back(j);

      // y0 = K^-1 r_u and Y_a = K^-1 B_a in one solve with several
      // right-hand sides.
      const unsigned int      n_c = coupled.size();
      LA::Vector              y0(rhs.field);
      std::vector<LA::Vector> Y(n_c);
      y0                                 = 0.;
      std::vector<LA::Vector *>       xs = {&y0};
      std::vector<const LA::Vector *> bs = {&rhs_u};
      for (unsigned int a = 0; a < n_c; ++a)
        {
          Y[a].reinit(rhs.field);
          if (has_B[coupled[a]])
            {
              xs.push_back(&Y[a]);
              bs.push_back(&B[coupled[a]]);
            }
        }
      solver.solve(K, xs, bs);
      if (!coupled.empty())
        {
          // Schur complement S = D - C^T K^-1 B on the coupled unknowns.
          FullMatrix<double> S(n_c, n_c);
          Vector<double>     s_rhs(n_c), x(n_c);
          for (unsigned int a = 0; a < n_c; ++a)
            {
              const unsigned int i = coupled[a];
              s_rhs[a]             = r_g[i];
              for (unsigned int k = 0; k < m; ++k)
                if (decoupled[k])
                  s_rhs[a] -= D(i, k) * dl[k];
              if (has_C[i])
                s_rhs[a] -= C[i] * y0;
              for (unsigned int b = 0; b < n_c; ++b)
                {
                  S(a, b) = D(i, coupled[b]);
                  if (has_C[i])
                    S(a, b) -= C[i] * Y[b];
                }
            }
          S.gauss_jordan();
          S.vmult(x, s_rhs);
          for (unsigned int a = 0; a < n_c; ++a)
            {
              dl[coupled[a]] = x[a];
              y0.add(-x[a], Y[a]);
            }
        }
      dx.field = y0;
      dx.border.reinit(m);
      for (unsigned int j = 0; j < m; ++j)
        dx.border[j] = dl[j] / unknown_scale[j];
    }

    void
    BorderCoupling::vmult(const LA::SparseMatrix &K,
                          const BorderedVector   &x,
                          BorderedVector         &y) const
    {
      const unsigned int m = size();
      K.vmult(y.field, x.field);
      y.border.reinit(m);
      for (unsigned int j = 0; j < m; ++j)
        if (has_B[j])
          y.field.add(x.border[j] * unknown_scale[j], B[j]);
      for (unsigned int j = 0; j < m; ++j)
        {
          double v = has_C[j] ? C[j] * x.field : 0.;
          for (unsigned int k = 0; k < m; ++k)
            v += D(j, k) * x.border[k] * unknown_scale[k];
          y.border[j] = v * residual_scale[j];
        }
    }
  } // namespace solvers
} // namespace pneuma
