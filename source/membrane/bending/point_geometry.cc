#include <pneuma/membrane/bending/point_geometry.h>

#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      NodePositions::NodePositions(const Mapping<2, 3>       &mapping,
                                   const FiniteElement<2, 3> &base)
        : values(mapping,
                 base,
                 Quadrature<2>(base.get_unit_support_points()),
                 update_quadrature_points)
        , x(base.n_dofs_per_cell())
      {
      }

      const std::vector<Vec<double>> &
      NodePositions::of(const Triangulation<2, 3>::cell_iterator &cell)
      {
        values.reinit(cell);
        for (unsigned int a = 0; a < x.size(); ++a)
          for (unsigned int c = 0; c < 3; ++c)
            x[a][c] = values.quadrature_point(a)[c];
        return x;
      }

      Point<2>
      locate_on_face(const FiniteElement<2, 3>      &base,
                     const std::vector<Vec<double>> &x,
                     const unsigned int              face,
                     const Vec<double>              &p)
      {
        // Newton on the edge's parameter: the edge is a polynomial curve
        // through p, so it converges from the middle.
        const auto t = face_direction(face);
        double     s = 0.5;
        for (unsigned int it = 0; it < 30; ++it)
          {
            const Point<2> xi = face_point(face, s);
            double         g[15];
            point_derivatives(x, shape_derivatives(base, xi), g);
            const Vec<double> y = position(base, x, xi);
            Vec<double>       d, r;
            for (unsigned int c = 0; c < 3; ++c)
              {
                d[c] = t[0] * g[c] + t[1] * g[3 + c];
                r[c] = y[c] - p[c];
              }
            const double ds = dot(r, d) / dot(d, d);
            s -= ds;
            if (std::abs(ds) < 1e-15)
              break;
          }
        return face_point(face, s);
      }

      ShapeDerivatives
      shape_derivatives(const FiniteElement<2, 3> &base, const Point<2> &xi)
      {
        ShapeDerivatives s;
        s.n_nodes = base.n_dofs_per_cell();
        for (unsigned int a = 0; a < s.n_nodes; ++a)
          {
            const Tensor<1, 2> d  = base.shape_grad(a, xi);
            const Tensor<2, 2> dd = base.shape_grad_grad(a, xi);
            s.d[a] = {{d[0], d[1], dd[0][0], dd[0][1], dd[1][1]}};
          }
        return s;
      }

      void
      point_derivatives(const std::vector<Vec<double>> &x,
                        const ShapeDerivatives         &shape,
                        double                          g[15])
      {
        for (unsigned int k = 0; k < 15; ++k)
          g[k] = 0.;
        for (unsigned int a = 0; a < shape.n_nodes; ++a)
          for (unsigned int s = 0; s < 5; ++s)
            for (unsigned int c = 0; c < 3; ++c)
              g[3 * s + c] += shape.d[a][s] * x[a][c];
      }

      Vec<double>
      position(const FiniteElement<2, 3>      &base,
               const std::vector<Vec<double>> &x,
               const Point<2>                 &xi)
      {
        Vec<double> p{{0., 0., 0.}};
        for (unsigned int a = 0; a < base.n_dofs_per_cell(); ++a)
          {
            const double N = base.shape_value(a, xi);
            for (unsigned int c = 0; c < 3; ++c)
              p[c] += N * x[a][c];
          }
        return p;
      }

      ReferencePoint
      reference_point(const double       G[15],
                      const Vec<double> &warp,
                      const double       D[2][2][2][2],
                      const double       sign)
      {
        ReferencePoint    r;
        const Vec<double> A1 = part(G, 0), A2 = part(G, 1);
        const Vec<double> M = cross(A1, A2);
        r.area              = std::sqrt(dot(M, M));
        for (unsigned int d = 0; d < 3; ++d)
          r.N[d] = M[d] / r.area;
        // The material frame: E_1 along the warp's projection, else X_,1.
        Vec<double>  w  = warp;
        const double wn = dot(w, r.N);
        for (unsigned int d = 0; d < 3; ++d)
          w[d] -= wn * r.N[d];
        if (dot(w, w) <= 1e-24 * std::max(dot(warp, warp), 1e-300))
          w = A1;
        r.E1 = normalized(w);
        r.E2 = cross(r.N, r.E1);
        // G = J^-1, J_ia = E_i . X_,a.
        const double J[2][2] = {{dot(r.E1, A1), dot(r.E1, A2)},
                                {dot(r.E2, A1), dot(r.E2, A2)}};
        const double det     = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        auto        &f       = r.frame;
        f.G[0][0]            = J[1][1] / det;
        f.G[0][1]            = -J[0][1] / det;
        f.G[1][0]            = -J[1][0] / det;
        f.G[1][1]            = J[0][0] / det;
        f.sign               = sign;
        double b[2][2];
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int c = 0; c < 2; ++c)
            b[a][c] = sign * dot(part(G, slot(a, c)), r.N);
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            {
              f.B[i][j] = 0.;
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int c = 0; c < 2; ++c)
                  f.B[i][j] += f.G[a][i] * f.G[c][j] * b[a][c];
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int l = 0; l < 2; ++l)
                  f.D[i][j][k][l] = D[i][j][k][l];
            }
        return r;
      }

      Point<2>
      face_point(const unsigned int face, const double s)
      {
        switch (face)
          {
            case 0:
              return Point<2>(0., s);
            case 1:
              return Point<2>(1., s);
            case 2:
              return Point<2>(s, 0.);
            default:
              return Point<2>(s, 1.);
          }
      }

      std::array<double, 2>
      face_direction(const unsigned int face)
      {
        return face < 2 ? std::array<double, 2>{{0., 1.}}
                        : std::array<double, 2>{{1., 0.}};
      }

      std::array<double, 2>
      face_outward(const unsigned int face)
      {
        const double s = face % 2 == 0 ? -1. : 1.;
        return face < 2 ? std::array<double, 2>{{s, 0.}}
                        : std::array<double, 2>{{0., s}};
      }

      void
      add_point_terms(const unsigned int                                n_sides,
                      const ShapeDerivatives                           *shape,
                      const std::array<std::array<unsigned int, 3>, 9> *index,
                      const double       *gradient,
                      const double       *hessian,
                      Vector<double>     *residual,
                      FullMatrix<double> *matrix)
      {
        const unsigned int M = 15 * n_sides;
        if (residual)
          for (unsigned int s = 0; s < n_sides; ++s)
            for (unsigned int a = 0; a < shape[s].n_nodes; ++a)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  double r = 0.;
                  for (unsigned int k = 0; k < 5; ++k)
                    r += gradient[15 * s + 3 * k + c] * shape[s].d[a][k];
                  (*residual)[index[s][a][c]] += r;
                }
        if (!matrix || !hessian)
          return;
        // T[row][column dof] = sum_l H[row][slot l of the dof] d[l].
        const unsigned int        n_cols = 3 * shape[0].n_nodes * n_sides;
        std::vector<double>       T(M * n_cols);
        std::vector<unsigned int> col_index(n_cols);
        for (unsigned int row = 0; row < M; ++row)
          {
            unsigned int j = 0;
            for (unsigned int t = 0; t < n_sides; ++t)
              for (unsigned int b = 0; b < shape[t].n_nodes; ++b)
                for (unsigned int e = 0; e < 3; ++e, ++j)
                  {
                    double v = 0.;
                    for (unsigned int l = 0; l < 5; ++l)
                      v += hessian[row * M + 15 * t + 3 * l + e]
                           * shape[t].d[b][l];
                    T[row * n_cols + j] = v;
                    col_index[j]        = index[t][b][e];
                  }
          }
        for (unsigned int s = 0; s < n_sides; ++s)
          for (unsigned int a = 0; a < shape[s].n_nodes; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              {
                const unsigned int i = index[s][a][c];
                for (unsigned int j = 0; j < n_cols; ++j)
                  {
                    double v = 0.;
                    for (unsigned int k = 0; k < 5; ++k)
                      v +=
                        shape[s].d[a][k] * T[(15 * s + 3 * k + c) * n_cols + j];
                    (*matrix)(i, col_index[j]) += v;
                  }
              }
      }
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
