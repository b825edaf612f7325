#include <deal.II/base/quadrature_lib.h>

#include <pneuma/membrane/assumed_strains.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    namespace
    {
      const double a = 1. / std::sqrt(3.), b = std::sqrt(0.6);

      /// Linear Lagrange polynomial i of the nodes -a, a at x.
      double
      linear(const unsigned int i, const double x)
      {
        return i == 0 ? (a - x) / (2. * a) : (x + a) / (2. * a);
      }

      /// Quadratic Lagrange polynomial j of the nodes -b, 0, b at x.
      double
      quadratic(const unsigned int j, const double x)
      {
        if (j == 0)
          return x * (x - b) / (2. * b * b);
        if (j == 1)
          return (b - x) * (b + x) / (b * b);
        return x * (x + b) / (2. * b * b);
      }

      /// The tying points in natural coordinates (r, s) on [-1, 1]^2:
      /// E_rr (t = 3 i + j), E_ss (6 + 3 i + j), E_rs (12 + 2 i + k).
      std::vector<Point<2>>
      natural_tying_points()
      {
        const double          lin[2] = {-a, a}, quad[3] = {-b, 0., b};
        std::vector<Point<2>> p;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            p.emplace_back(lin[i], quad[j]);
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            p.emplace_back(quad[j], lin[i]);
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int k = 0; k < 2; ++k)
            p.emplace_back(lin[i], lin[k]);
        return p;
      }

      /// The interpolation weight of tying point t at (r, s).
      double
      tying_weight(const unsigned int t, const double r, const double s)
      {
        if (t < 6)
          return linear(t / 3, r) * quadratic(t % 3, s);
        if (t < 12)
          return quadratic((t - 6) % 3, r) * linear((t - 6) / 3, s);
        return linear((t - 12) / 2, r) * linear((t - 12) % 2, s);
      }
    } // namespace

    AssumedStrains::AssumedStrains(const FiniteElement<2, 3> &fe)
    {
      const auto &base = fe.base_element(0);
      AssertThrow(base.degree == 2 && base.n_dofs_per_cell() == n_node,
                  ExcMessage("assumed membrane strains need Q2 cells"));
      std::vector<Point<2>> unit;
      for (const auto &p : natural_tying_points())
        unit.emplace_back((p[0] + 1.) / 2., (p[1] + 1.) / 2.);
      tying = Quadrature<2>(unit, std::vector<double>(unit.size(), 1.));
      for (unsigned int t = 0; t < n_tying; ++t)
        for (unsigned int n = 0; n < n_node; ++n)
          {
            const Tensor<1, 2> grad = base.shape_grad(n, unit[t]);
            dN[t][n]                = {{grad[0], grad[1]}};
          }
      const QGauss<2> gauss(3);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const double r = 2. * gauss.point(q)[0] - 1.,
                       s = 2. * gauss.point(q)[1] - 1.;
          for (unsigned int t = 0; t < n_tying; ++t)
            L[q][t] = tying_weight(t, r, s);
        }
    }

    void
    AssumedStrains::reference(const FEValues<2, 3> &at_tying,
                              const FEValues<2, 3> &at_gauss,
                              const double (*frame)[2][3],
                              TyingGeometry &cell) const
    {
      for (unsigned int t = 0; t < n_tying; ++t)
        {
          const auto J = at_tying.jacobian(t);
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int d = 0; d < 3; ++d)
              cell.G[t][i][d] = J[d][i];
        }
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const auto K = at_gauss.inverse_jacobian(q);
          for (unsigned int al = 0; al < 2; ++al)
            for (unsigned int i = 0; i < 2; ++i)
              {
                double v = 0.;
                for (unsigned int d = 0; d < 3; ++d)
                  v += K[i][d] * frame[q][al][d];
                cell.c[q][al][i] = v;
              }
        }
    }

    void
    AssumedStrains::state(const TyingGeometry                      &cell,
                          const std::vector<std::array<double, 3>> &u_node,
                          TyingState                               &s) const
    {
      for (unsigned int t = 0; t < n_tying; ++t)
        {
          Tensor<1, 3> G[2], w[2];
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int d = 0; d < 3; ++d)
              G[i][d] = cell.G[t][i][d];
          for (unsigned int n = 0; n < n_node; ++n)
            for (unsigned int d = 0; d < 3; ++d)
              {
                w[0][d] += u_node[n][d] * dN[t][n][0];
                w[1][d] += u_node[n][d] * dN[t][n][1];
              }
          const unsigned int k = component(t);
          s.E[t]               = k < 2 ? G[k] * w[k] + 0.5 * (w[k] * w[k])
                                       : 0.5 * (G[0] * w[1] + w[0] * G[1] + w[0] * w[1]);
          s.g[t][0]            = G[0] + w[0];
          s.g[t][1]            = G[1] + w[1];
        }
    }

    SymmetricTensor<2, 2>
    AssumedStrains::strain(const TyingGeometry &cell,
                           const TyingState    &s,
                           const unsigned int   q) const
    {
      double E[3] = {0., 0., 0.};
      for (unsigned int t = 0; t < n_tying; ++t)
        E[component(t)] += L[q][t] * s.E[t];
      const auto           &c = cell.c[q];
      SymmetricTensor<2, 2> local;
      for (unsigned int al = 0; al < 2; ++al)
        for (unsigned int be = al; be < 2; ++be)
          local[al][be] = c[al][0] * c[be][0] * E[0]
                          + c[al][1] * c[be][1] * E[1]
                          + (c[al][0] * c[be][1] + c[al][1] * c[be][0]) * E[2];
      return local;
    }

    void
    AssumedStrains::strain_derivatives(const TyingState &s,
                                       double (*dE)[3 * n_node]) const
    {
      for (unsigned int t = 0; t < n_tying; ++t)
        {
          const unsigned int k = component(t);
          const auto        &g = s.g[t];
          for (unsigned int n = 0; n < n_node; ++n)
            for (unsigned int d = 0; d < 3; ++d)
              dE[t][3 * n + d] =
                k < 2 ? dN[t][n][k] * g[k][d]
                      : 0.5 * (dN[t][n][0] * g[1][d] + dN[t][n][1] * g[0][d]);
        }
    }

    void
    AssumedStrains::add_stress_weights(const TyingGeometry         &cell,
                                       const unsigned int           q,
                                       const SymmetricTensor<2, 2> &S,
                                       const double                 HdA,
                                       double                      *w) const
    {
      const auto &c = cell.c[q];
      double      Sc[3]; // S^00, S^11, 2 S^01
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int i = k == 1 ? 1 : 0, j = k == 0 ? 0 : 1;
          double             v = 0.;
          for (unsigned int al = 0; al < 2; ++al)
            for (unsigned int be = 0; be < 2; ++be)
              v += c[al][i] * c[be][j] * S[al][be];
          Sc[k] = k == 2 ? 2. * v : v;
        }
      for (unsigned int t = 0; t < n_tying; ++t)
        w[t] += HdA * L[q][t] * Sc[component(t)];
    }

    void
    AssumedStrains::add_forces(const double (*dE)[3 * n_node],
                               const double *w,
                               double       *f) const
    {
      for (unsigned int t = 0; t < n_tying; ++t)
        for (unsigned int j = 0; j < 3 * n_node; ++j)
          f[j] += w[t] * dE[t][j];
    }

    void
    AssumedStrains::add_material_stiffness(const TyingGeometry &cell,
                                           const unsigned int   q,
                                           const double (*dE)[3 * n_node],
                                           const double (*Dv)[3],
                                           const double HdA,
                                           double      *K) const
    {
      constexpr unsigned int n = 3 * n_node;
      // The covariant rows (E_rr, E_ss, E_rs), then the material frame's
      // (E_11, E_22, 2 E_12).
      double cov[3][n] = {}, B[3][n], DB[3][n];
      for (unsigned int t = 0; t < n_tying; ++t)
        if (L[q][t] != 0.)
          for (unsigned int j = 0; j < n; ++j)
            cov[component(t)][j] += L[q][t] * dE[t][j];
      const auto  &c       = cell.c[q];
      const double T[3][3] = {
        {c[0][0] * c[0][0], c[0][1] * c[0][1], 2. * c[0][0] * c[0][1]},
        {c[1][0] * c[1][0], c[1][1] * c[1][1], 2. * c[1][0] * c[1][1]},
        {2. * c[0][0] * c[1][0],
         2. * c[0][1] * c[1][1],
         2. * (c[0][0] * c[1][1] + c[0][1] * c[1][0])}};
      for (unsigned int r = 0; r < 3; ++r)
        for (unsigned int j = 0; j < n; ++j)
          B[r][j] =
            T[r][0] * cov[0][j] + T[r][1] * cov[1][j] + T[r][2] * cov[2][j];
      for (unsigned int r = 0; r < 3; ++r)
        for (unsigned int j = 0; j < n; ++j)
          DB[r][j] =
            HdA
            * (Dv[r][0] * B[0][j] + Dv[r][1] * B[1][j] + Dv[r][2] * B[2][j]);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 3 * (i / 3); j < n; ++j)
          K[i * n + j] +=
            B[0][i] * DB[0][j] + B[1][i] * DB[1][j] + B[2][i] * DB[2][j];
    }

    void
    AssumedStrains::add_geometric_stiffness(const double *w, double *K) const
    {
      constexpr unsigned int n = 3 * n_node;
      for (unsigned int a = 0; a < n_node; ++a)
        for (unsigned int b = a; b < n_node; ++b)
          {
            double k = 0.;
            for (unsigned int t = 0; t < n_tying; ++t)
              {
                const auto        &D = dN[t];
                const unsigned int c = component(t);
                k += w[t]
                     * (c < 2 ? D[a][c] * D[b][c]
                              : 0.5 * (D[a][0] * D[b][1] + D[a][1] * D[b][0]));
              }
            for (unsigned int d = 0; d < 3; ++d)
              K[(3 * a + d) * n + 3 * b + d] += k;
          }
    }
  } // namespace membrane
} // namespace pneuma
