#include <deal.II/base/config.h>

#include <pneuma/contact/contact_point.h>

#ifndef DEAL_II_TRILINOS_WITH_SACADO
#error "pneuma's contact needs deal.II with Trilinos Sacado"
#endif

#include <Sacado.hpp>

#include <cmath>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      /// 1D Lagrange basis of degree 1 or 2 on the nodes i/degree: values,
      /// first and second derivatives.
      template <typename Number>
      void
      lagrange(const unsigned int degree,
               const Number      &t,
               Number             l[3],
               Number             dl[3],
               Number             ddl[3])
      {
        if (degree == 1)
          {
            l[0]   = 1. - t;
            l[1]   = t;
            dl[0]  = -1.;
            dl[1]  = 1.;
            ddl[0] = 0.;
            ddl[1] = 0.;
            return;
          }
        l[0]   = 2. * (t - 0.5) * (t - 1.);
        l[1]   = -4. * t * (t - 1.);
        l[2]   = 2. * t * (t - 0.5);
        dl[0]  = 4. * t - 3.;
        dl[1]  = -8. * t + 4.;
        dl[2]  = 4. * t - 1.;
        ddl[0] = 4.;
        ddl[1] = -8.;
        ddl[2] = 4.;
      }

      /// rho, rho_a, rho_ab at xi for node positions y (Number vectors).
      template <typename Number>
      void
      surface(const unsigned int                        degree,
              const std::vector<std::array<Number, 3>> &y,
              const Number                              xi[2],
              Number                                    rho[3],
              Number                                    d[2][3],
              Number                                    dd[2][2][3])
      {
        Number l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
        lagrange(degree, xi[0], l1, dl1, ddl1);
        lagrange(degree, xi[1], l2, dl2, ddl2);
        for (unsigned int c = 0; c < 3; ++c)
          {
            rho[c] = 0.;
            for (unsigned int a = 0; a < 2; ++a)
              {
                d[a][c] = 0.;
                for (unsigned int b = 0; b < 2; ++b)
                  dd[a][b][c] = 0.;
              }
          }
        // Each node's weights once (the products are the same as inline,
        // so the sums are bitwise unchanged); a bilinear patch has no
        // rho_11, rho_22. This is the inner loop of the contact's
        // automatic differentiation.
        const unsigned int n = degree + 1;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto  &p   = y[i + n * j];
              const Number w   = l1[i] * l2[j];
              const Number w1  = dl1[i] * l2[j];
              const Number w2  = l1[i] * dl2[j];
              const Number w12 = dl1[i] * dl2[j];
              for (unsigned int c = 0; c < 3; ++c)
                {
                  rho[c] += w * p[c];
                  d[0][c] += w1 * p[c];
                  d[1][c] += w2 * p[c];
                  dd[0][1][c] += w12 * p[c];
                }
              if (degree > 1)
                {
                  const Number w11 = ddl1[i] * l2[j];
                  const Number w22 = l1[i] * ddl2[j];
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      dd[0][0][c] += w11 * p[c];
                      dd[1][1][c] += w22 * p[c];
                    }
                }
            }
        for (unsigned int c = 0; c < 3; ++c)
          dd[1][0][c] = dd[0][1][c];
      }

      /// One Newton step of min |x - rho(xi)|^2 / 2 on xi.
      template <typename Number>
      void
      newton_step(const unsigned int                        degree,
                  const std::vector<std::array<Number, 3>> &y,
                  const Number                              x[3],
                  Number                                    xi[2])
      {
        Number rho[3], d[2][3], dd[2][2][3];
        surface(degree, y, xi, rho, d, dd);
        Number r[3];
        for (unsigned int c = 0; c < 3; ++c)
          r[c] = x[c] - rho[c];
        Number g[2], H[2][2];
        for (unsigned int a = 0; a < 2; ++a)
          {
            g[a] = 0.;
            for (unsigned int c = 0; c < 3; ++c)
              g[a] -= r[c] * d[a][c];
            for (unsigned int b = 0; b < 2; ++b)
              {
                H[a][b] = 0.;
                for (unsigned int c = 0; c < 3; ++c)
                  H[a][b] += d[a][c] * d[b][c] - r[c] * dd[a][b][c];
              }
          }
        const Number det = H[0][0] * H[1][1] - H[0][1] * H[1][0];
        const Number s0  = (H[1][1] * g[0] - H[0][1] * g[1]) / det;
        const Number s1  = (H[0][0] * g[1] - H[1][0] * g[0]) / det;
        xi[0] -= s0;
        xi[1] -= s1;
      }

      /// Gap (x - rho(xi)).n - h with n = sign rho_1 x rho_2 / |...| and
      /// h = R, or, for an elliptic section with semi-axis vectors a1, a2,
      /// its extent along n, h = sqrt((a1.n)^2 + (a2.n)^2).
      template <typename Number>
      Number
      gap(const unsigned int                        degree,
          const std::vector<std::array<Number, 3>> &y,
          const Number                              x[3],
          const Number                              xi[2],
          const double                              sign,
          const double                              radius,
          Number                                    normal[3],
          const Number                             *a1 = nullptr,
          const Number                             *a2 = nullptr)
      {
        Number rho[3], d[2][3], dd[2][2][3];
        surface(degree, y, xi, rho, d, dd);
        Number m[3] = {d[0][1] * d[1][2] - d[0][2] * d[1][1],
                       d[0][2] * d[1][0] - d[0][0] * d[1][2],
                       d[0][0] * d[1][1] - d[0][1] * d[1][0]};
        using std::sqrt;
        const Number length = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        Number       g      = 0.;
        for (unsigned int c = 0; c < 3; ++c)
          {
            normal[c] = sign * m[c] / length;
            g += (x[c] - rho[c]) * normal[c];
          }
        if (a1 == nullptr)
          return g - radius;
        Number p1 = 0., p2 = 0.;
        for (unsigned int c = 0; c < 3; ++c)
          {
            p1 += a1[c] * normal[c];
            p2 += a2[c] * normal[c];
          }
        return g - sqrt(p1 * p1 + p2 * p2);
      }

      /**
       * The smoothed normal field at (xi, g): the surface point rho, the
       * unit normal n = N/|N| with N = sum phi_a nbar_a, its derivatives
       * n_a = (I - n n) N_a / |N|, the offset tangents
       * t_a = rho_a + g n_a and the dual basis: dual[0], dual[1] = m^1,
       * m^2 and dual[2] = m (doc/theory.md §10.4).
       */
      template <typename Number>
      struct SmoothFrame
      {
        Number rho[3], n[3], dn[2][3], dual[3][3], length;
      };

      template <typename Number>
      void
      smooth_frame(const unsigned int                        degree,
                   const std::vector<std::array<Number, 3>> &y,
                   const std::vector<std::array<Number, 3>> &nbar,
                   const Number                              xi[2],
                   const Number                             &g,
                   SmoothFrame<Number>                      &f)
      {
        Number d[2][3], dd[2][2][3];
        surface(degree, y, xi, f.rho, d, dd);
        Number N[3], dN[2][3], ddN[2][2][3];
        surface(degree, nbar, xi, N, dN, ddN);
        using std::sqrt;
        f.length = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
        for (unsigned int c = 0; c < 3; ++c)
          f.n[c] = N[c] / f.length;
        Number t[2][3];
        for (unsigned int a = 0; a < 2; ++a)
          {
            const Number nd =
              f.n[0] * dN[a][0] + f.n[1] * dN[a][1] + f.n[2] * dN[a][2];
            for (unsigned int c = 0; c < 3; ++c)
              {
                f.dn[a][c] = (dN[a][c] - f.n[c] * nd) / f.length;
                t[a][c]    = d[a][c] + g * f.dn[a][c];
              }
          }
        const auto cross =
          [](const Number u[3], const Number v[3], Number w[3]) {
            w[0] = u[1] * v[2] - u[2] * v[1];
            w[1] = u[2] * v[0] - u[0] * v[2];
            w[2] = u[0] * v[1] - u[1] * v[0];
          };
        cross(t[0], t[1], f.dual[2]);
        cross(t[1], f.n, f.dual[0]);
        cross(f.n, t[0], f.dual[1]);
        const Number det =
          f.dual[2][0] * f.n[0] + f.dual[2][1] * f.n[1] + f.dual[2][2] * f.n[2];
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int c = 0; c < 3; ++c)
            f.dual[k][c] /= det;
      }

      /// One Newton step of x - rho(xi) - g n(xi) = 0 on (xi, g).
      template <typename Number>
      void
      smooth_newton_step(const unsigned int                        degree,
                         const std::vector<std::array<Number, 3>> &y,
                         const std::vector<std::array<Number, 3>> &nbar,
                         const Number                              x[3],
                         Number                                    xi[2],
                         Number                                   &g)
      {
        SmoothFrame<Number> f;
        smooth_frame(degree, y, nbar, xi, g, f);
        Number F[3];
        for (unsigned int c = 0; c < 3; ++c)
          F[c] = x[c] - f.rho[c] - g * f.n[c];
        Number step[3];
        for (unsigned int k = 0; k < 3; ++k)
          step[k] =
            f.dual[k][0] * F[0] + f.dual[k][1] * F[1] + f.dual[k][2] * F[2];
        xi[0] += step[0];
        xi[1] += step[1];
        g += step[2];
      }

      /// The patch's nodes and (smoothed) nodal normals as doubles.
      void
      patch_arrays(const MasterPatch                  &patch,
                   std::vector<std::array<double, 3>> &y,
                   std::vector<std::array<double, 3>> &nbar)
      {
        y.resize(patch.nodes.size());
        nbar.resize(patch.normals.size());
        for (unsigned int a = 0; a < y.size(); ++a)
          for (unsigned int c = 0; c < 3; ++c)
            y[a][c] = patch.nodes[a][c];
        for (unsigned int a = 0; a < nbar.size(); ++a)
          for (unsigned int c = 0; c < 3; ++c)
            nbar[a][c] = patch.normals[a][c];
      }

      /// Distance g along the smoothed normal of the converged projection
      /// xi: x - rho(xi) is parallel to n(xi) there.
      double
      smooth_distance(const MasterPatch &patch,
                      const double       x[3],
                      const Point<2>    &xi_converged)
      {
        std::vector<std::array<double, 3>> y, nbar;
        patch_arrays(patch, y, nbar);
        const double        xi[2] = {xi_converged[0], xi_converged[1]};
        SmoothFrame<double> f;
        smooth_frame(patch.degree, y, nbar, xi, 0., f);
        double g = 0.;
        for (unsigned int c = 0; c < 3; ++c)
          g += (x[c] - f.rho[c]) * f.n[c];
        return g;
      }
    } // namespace

    Tensor<1, 3>
    position(const MasterPatch &patch, const Point<2> &xi)
    {
      double l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
      lagrange(patch.degree, xi[0], l1, dl1, ddl1);
      lagrange(patch.degree, xi[1], l2, dl2, ddl2);
      const unsigned int k = patch.degree + 1;
      Tensor<1, 3>       rho;
      for (unsigned int a = 0; a < patch.nodes.size(); ++a)
        rho += l1[a % k] * l2[a / k] * patch.nodes[a];
      return rho;
    }

    std::vector<double>
    shape_values(const unsigned int degree, const Point<2> &xi)
    {
      double l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
      lagrange(degree, xi[0], l1, dl1, ddl1);
      lagrange(degree, xi[1], l2, dl2, ddl2);
      const unsigned int  k = degree + 1;
      std::vector<double> phi(k * k);
      for (unsigned int a = 0; a < phi.size(); ++a)
        phi[a] = l1[a % k] * l2[a / k];
      return phi;
    }

    double
    area_element(const MasterPatch &patch, const Point<2> &xi)
    {
      double l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
      lagrange(patch.degree, xi[0], l1, dl1, ddl1);
      lagrange(patch.degree, xi[1], l2, dl2, ddl2);
      const unsigned int k = patch.degree + 1;
      Tensor<1, 3>       d1, d2;
      for (unsigned int a = 0; a < patch.nodes.size(); ++a)
        {
          d1 += dl1[a % k] * l2[a / k] * patch.nodes[a];
          d2 += l1[a % k] * dl2[a / k] * patch.nodes[a];
        }
      return cross_product_3d(d1, d2).norm();
    }

    std::pair<Tensor<1, 3>, Tensor<1, 3>>
    bounding_box(const MasterPatch &patch)
    {
      std::pair<Tensor<1, 3>, Tensor<1, 3>> box(patch.nodes[0], patch.nodes[0]);
      for (const auto &y : patch.nodes)
        for (unsigned int c = 0; c < 3; ++c)
          {
            box.first[c]  = std::min(box.first[c], y[c]);
            box.second[c] = std::max(box.second[c], y[c]);
          }
      return box;
    }

    Projection
    project(const MasterPatch  &patch,
            const Tensor<1, 3> &x,
            const double        radius,
            const Point<2>     &xi_start)
    {
      std::vector<std::array<double, 3>> y(patch.nodes.size());
      for (unsigned int a = 0; a < y.size(); ++a)
        for (unsigned int c = 0; c < 3; ++c)
          y[a][c] = patch.nodes[a][c];
      const double xs[3] = {x[0], x[1], x[2]};
      double       xi[2] = {xi_start[0], xi_start[1]};
      Projection   p;
      bool         converged = false;
      const double tolerance = 1e-9;
      if (!patch.normals.empty())
        {
          // Along the smoothed normal: x = rho(xi) + g n(xi).
          std::vector<std::array<double, 3>> nbar;
          patch_arrays(patch, y, nbar);
          double g     = smooth_distance(patch, xs, xi_start);
          double scale = 0.;
          for (const auto &a : y)
            for (unsigned int c = 0; c < 3; ++c)
              scale = std::max(scale, std::abs(a[c] - y[0][c]));
          for (unsigned int k = 0; k < 30; ++k)
            {
              const double old[3] = {xi[0], xi[1], g};
              smooth_newton_step(patch.degree, y, nbar, xs, xi, g);
              if (!std::isfinite(xi[0]) || !std::isfinite(xi[1])
                  || !std::isfinite(g))
                return p;
              if (std::abs(xi[0] - 0.5) > 3. || std::abs(xi[1] - 0.5) > 3.)
                return p;
              if (std::abs(xi[0] - old[0]) + std::abs(xi[1] - old[1])
                    + std::abs(g - old[2]) / std::max(scale, 1e-300)
                  < 1e-13)
                {
                  converged = true;
                  break;
                }
            }
          SmoothFrame<double> f;
          smooth_frame(patch.degree, y, nbar, xi, g, f);
          p.xi     = Point<2>(xi[0], xi[1]);
          p.inside = converged && xi[0] >= -tolerance && xi[0] <= 1. + tolerance
                     && xi[1] >= -tolerance && xi[1] <= 1. + tolerance;
          p.gap      = g - radius;
          p.distance = std::abs(g);
          for (unsigned int c = 0; c < 3; ++c)
            p.normal[c] = f.n[c];
          return p;
        }
      for (unsigned int k = 0; k < 30; ++k)
        {
          const double old[2] = {xi[0], xi[1]};
          newton_step(patch.degree, y, xs, xi);
          if (!std::isfinite(xi[0]) || !std::isfinite(xi[1]))
            return p;
          // Far outside the cell: no projection here.
          if (std::abs(xi[0] - 0.5) > 3. || std::abs(xi[1] - 0.5) > 3.)
            return p;
          if (std::abs(xi[0] - old[0]) + std::abs(xi[1] - old[1]) < 1e-13)
            {
              converged = true;
              break;
            }
        }
      p.xi     = Point<2>(xi[0], xi[1]);
      p.inside = converged && xi[0] >= -tolerance && xi[0] <= 1. + tolerance
                 && xi[1] >= -tolerance && xi[1] <= 1. + tolerance;
      double normal[3];
      p.gap = gap(patch.degree, y, xs, xi, patch.sign, radius, normal);
      double rho[3], d[2][3], dd[2][2][3];
      surface(patch.degree, y, xi, rho, d, dd);
      p.distance = std::sqrt((xs[0] - rho[0]) * (xs[0] - rho[0])
                             + (xs[1] - rho[1]) * (xs[1] - rho[1])
                             + (xs[2] - rho[2]) * (xs[2] - rho[2]));
      for (unsigned int c = 0; c < 3; ++c)
        p.normal[c] = normal[c];
      return p;
    }

    namespace
    {
      /**
       * The penalty energy of one point. Its gradient is known in closed
       * form at
       * the closest point (envelope theorem: the projection is stationary
       * and (x - rho) is parallel to n, so dn does not enter),
       *   dPi/dx_b = w eps xi3 N_b(eta) n,  dPi/dy_a = -w eps xi3 phi_a(xi) n,
       * and the Hessian is its Jacobian, taken with first-order Sacado
       * numbers through two Newton steps of the projection (which carry
       * dxi/dv exactly).
       */
      template <int n>
      double
      penalty_terms_envelope(const MasterPatch                 &patch,
                             const std::array<Tensor<1, 3>, 2> &slave,
                             const double                       eta,
                             const double                       radius,
                             const double                       penalty,
                             const double                       weight,
                             const Point<2>                    &xi_converged,
                             Vector<double>                    *gradient,
                             FullMatrix<double>                *hessian)
      {
        using AD               = Sacado::Fad::SFad<double, n>;
        const unsigned int n_m = patch.nodes.size();
        AD                 x[3];
        for (unsigned int c = 0; c < 3; ++c)
          x[c] = (1. - eta) * AD(n, c, slave[0][c])
                 + eta * AD(n, 3 + c, slave[1][c]);
        std::vector<std::array<AD, 3>> y(n_m);
        for (unsigned int a = 0; a < n_m; ++a)
          for (unsigned int c = 0; c < 3; ++c)
            y[a][c] = AD(n, 6 + 3 * a + c, patch.nodes[a][c]);
        AD xi[2] = {AD(xi_converged[0]), AD(xi_converged[1])};
        newton_step(patch.degree, y, x, xi);
        newton_step(patch.degree, y, x, xi);
        AD       normal[3];
        const AD g = gap(patch.degree, y, x, xi, patch.sign, radius, normal);
        if (gradient)
          gradient->reinit(n);
        if (hessian)
          hessian->reinit(n, n);
        if (g.val() >= 0.)
          return 0.;
        // phi_a(xi) in lattice order.
        AD l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
        lagrange(patch.degree, xi[0], l1, dl1, ddl1);
        lagrange(patch.degree, xi[1], l2, dl2, ddl2);
        const unsigned int k = patch.degree + 1;
        const AD           s = weight * penalty * g;
        for (unsigned int var = 0; var < n; ++var)
          {
            AD gv;
            if (var < 6)
              gv = s * (var < 3 ? 1. - eta : eta) * normal[var % 3];
            else
              {
                const unsigned int a = (var - 6) / 3, c = (var - 6) % 3;
                gv = -s * l1[a % k] * l2[a / k] * normal[c];
              }
            if (gradient)
              (*gradient)(var) = gv.val();
            if (hessian)
              for (unsigned int j = 0; j < n; ++j)
                (*hessian)(var, j) = gv.dx(j);
          }
        if (hessian)
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < a; ++b)
              (*hessian)(a, b) = (*hessian)(b, a) =
                0.5 * ((*hessian)(a, b) + (*hessian)(b, a));
        return 0.5 * weight * penalty * g.val() * g.val();
      }
    } // namespace

    namespace
    {
      /**
       * The full variable i of the section case (slave axis at the nodes,
       * 0-5; a1, a2 at node 0, 6-11, and node 1, 12-17; the master nodes)
       * as the reduced variable r[i] (x, a1, a2, master) times w[i].
       */
      template <int n_full>
      void
      section_variables(const double                      eta,
                        std::array<unsigned int, n_full> &r,
                        std::array<double, n_full>       &w)
      {
        w.fill(1.);
        for (unsigned int i = 0; i < n_full; ++i)
          if (i < 6)
            {
              r[i] = i % 3;
              w[i] = i < 3 ? 1. - eta : eta;
            }
          else if (i < 18)
            {
              r[i] = 3 + (i - 6) % 6;
              w[i] = i < 12 ? 1. - eta : eta;
            }
          else
            r[i] = i - 9;
      }

      /**
       * The reduced variables of an elliptic-section point
       * (section_variables()): the axis x (0-2), the section a1 (3-5) and a2
       * (6-8) at the point, linear in the slave's nodal values, and the master
       * nodes (9 on), each made by @p variable(index, value).
       */
      template <typename Number, typename Variable>
      void
      seed_section_point(const MasterPatch                  &patch,
                         const SlaveSection                 &section,
                         const std::array<Tensor<1, 3>, 2>  &slave,
                         const double                        eta,
                         const Variable                     &variable,
                         Number                              x[3],
                         Number                              a1[3],
                         Number                              a2[3],
                         std::vector<std::array<Number, 3>> &y)
      {
        for (unsigned int c = 0; c < 3; ++c)
          {
            x[c] = variable(c, (1. - eta) * slave[0][c] + eta * slave[1][c]);
            a1[c] =
              variable(3 + c,
                       (1. - eta) * section.a1[0][c] + eta * section.a1[1][c]);
            a2[c] =
              variable(6 + c,
                       (1. - eta) * section.a2[0][c] + eta * section.a2[1][c]);
          }
        y.resize(patch.nodes.size());
        for (unsigned int a = 0; a < patch.nodes.size(); ++a)
          for (unsigned int c = 0; c < 3; ++c)
            y[a][c] = variable(9 + 3 * a + c, patch.nodes[a][c]);
      }

    } // namespace

    namespace
    {
      /**
       * The gradient of the gap g = (x - rho).n - h(n) of an elliptic
       * section in closed form, in the reduced variables (x, a1, a2,
       * master nodes; section_variables()), as Sacado numbers whose
       * derivatives are then the gap's Hessian (doc/theory.md §10.1).
       * At fixed xi, with d = x - rho, p_i = a_i.n, h = |(p1, p2)|,
       * q = (p1 a1 + p2 a2)/h (the gradient of h in n), m = rho_1 x rho_2
       * and s = sign (I - n n)(d - q)/|m| (so that (d - q).dn = s.dm):
       *   G_x = n, G_ai = -(p_i/h) n,
       *   G_ya = -phi_a n + phi_a,1 rho_2 x s + phi_a,2 s x rho_1,
       *   G_xi_b = s.(rho_1b x rho_2 + rho_1 x rho_2b).
       * The projection's stationarity F_a = rho_a.d = 0 moves xi by
       * xi_v = -A^{-1} F_v, A_ab = rho_ab.d - rho_a.rho_b (symmetric),
       * F_a,x = rho_a, F_a,ya = phi_a,a d - phi_a rho_a, so with
       * c = A^{-1} G_xi the total gradient is G_v - c_a F_a,v. Evaluated
       * at xi carrying dxi/dv (one Newton step from the converged xi),
       * the numbers' derivatives are exact.
       */
      template <typename Number>
      void
      section_gap_gradient(const unsigned int                        degree,
                           const std::vector<std::array<Number, 3>> &y,
                           const Number                              x[3],
                           const Number                              a1[3],
                           const Number                              a2[3],
                           const Number                              xi[2],
                           const double                              sign,
                           Number                                   &g,
                           std::vector<Number>                      &grad)
      {
        Number rho[3], t[2][3], tt[2][2][3];
        surface(degree, y, xi, rho, t, tt);
        const auto cross =
          [](const Number u[3], const Number v[3], Number w[3]) {
            w[0] = u[1] * v[2] - u[2] * v[1];
            w[1] = u[2] * v[0] - u[0] * v[2];
            w[2] = u[0] * v[1] - u[1] * v[0];
          };
        // Returns a Number: Sacado's expression templates must not
        // outlive the operands.
        const auto dot = [](const Number u[3], const Number v[3]) -> Number {
          return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        };
        using std::sqrt;
        Number m[3];
        cross(t[0], t[1], m);
        const Number length = sqrt(dot(m, m));
        Number       n[3], d[3];
        for (unsigned int c = 0; c < 3; ++c)
          {
            n[c] = sign * m[c] / length;
            d[c] = x[c] - rho[c];
          }
        const Number p1 = dot(a1, n), p2 = dot(a2, n);
        const Number h = sqrt(p1 * p1 + p2 * p2);
        g              = dot(d, n) - h;
        Number u[3];
        for (unsigned int c = 0; c < 3; ++c)
          u[c] = d[c] - (p1 * a1[c] + p2 * a2[c]) / h;
        const Number un = dot(u, n);
        Number       s[3];
        for (unsigned int c = 0; c < 3; ++c)
          s[c] = sign * (u[c] - un * n[c]) / length;
        // G_xi and A.
        Number G_xi[2], A[2][2];
        for (unsigned int b = 0; b < 2; ++b)
          {
            Number w1[3], w2[3];
            cross(tt[0][b], t[1], w1);
            cross(t[0], tt[1][b], w2);
            G_xi[b] = dot(s, w1) + dot(s, w2);
            for (unsigned int a = 0; a < 2; ++a)
              A[a][b] = dot(tt[a][b], d) - dot(t[a], t[b]);
          }
        const Number det  = A[0][0] * A[1][1] - A[0][1] * A[1][0];
        const Number c[2] = {(A[1][1] * G_xi[0] - A[0][1] * G_xi[1]) / det,
                             (A[0][0] * G_xi[1] - A[1][0] * G_xi[0]) / det};
        Number       t2s[3], st1[3];
        cross(t[1], s, t2s);
        cross(s, t[0], st1);
        const unsigned int n_m = y.size();
        grad.resize(9 + 3 * n_m);
        for (unsigned int k = 0; k < 3; ++k)
          {
            grad[k]     = n[k] - c[0] * t[0][k] - c[1] * t[1][k];
            grad[3 + k] = -p1 / h * n[k];
            grad[6 + k] = -p2 / h * n[k];
          }
        Number l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
        lagrange(degree, xi[0], l1, dl1, ddl1);
        lagrange(degree, xi[1], l2, dl2, ddl2);
        const unsigned int k1 = degree + 1;
        for (unsigned int a = 0; a < n_m; ++a)
          {
            const Number phi  = l1[a % k1] * l2[a / k1];
            const Number phi1 = dl1[a % k1] * l2[a / k1];
            const Number phi2 = l1[a % k1] * dl2[a / k1];
            const Number cphi = c[0] * phi1 + c[1] * phi2;
            for (unsigned int k = 0; k < 3; ++k)
              grad[9 + 3 * a + k] = -phi * n[k] + phi1 * t2s[k] + phi2 * st1[k]
                                    - cphi * d[k]
                                    + phi * (c[0] * t[0][k] + c[1] * t[1][k]);
          }
      }

      /**
       * An elliptic-section point in numbers made by @p variable (doubles,
       * or first-order Sacado numbers seeded in the reduced variables of
       * section_variables()): one Newton step of the projection from the
       * converged xi (it carries dxi/dv exactly), then the gap and its
       * closed-form gradient (section_gap_gradient()).
       */
      template <typename Number, typename Variable>
      void
      section_point(const MasterPatch                 &patch,
                    const SlaveSection                &section,
                    const std::array<Tensor<1, 3>, 2> &slave,
                    const double                       eta,
                    const Point<2>                    &xi_converged,
                    const Variable                    &variable,
                    Number                            &g,
                    std::vector<Number>               &grad)
      {
        Number                             x[3], a1[3], a2[3];
        std::vector<std::array<Number, 3>> y;
        seed_section_point(patch, section, slave, eta, variable, x, a1, a2, y);
        Number xi[2] = {Number(xi_converged[0]), Number(xi_converged[1])};
        newton_step(patch.degree, y, x, xi);
        section_gap_gradient(
          patch.degree, y, x, a1, a2, xi, patch.sign, g, grad);
      }
    } // namespace

    namespace
    {
      /**
       * The penalty energy with an elliptic slave section: h(n) depends on
       * n, so the closed-form gradient of the circular case does not hold.
       * The point's axis x and section a1, a2 are linear in the slave's
       * nodal values ((1 - eta) at node 0, eta at node 1), so the Sacado
       * numbers carry the reduced variables x, a1, a2 (9) and the master
       * nodes (@p n = 9 + 3 n_m) and the result is expanded to the slave's
       * 18 nodal variables after. The gap's gradient is a closed form
       * (section_gap_gradient()): for a residual alone it is evaluated in
       * doubles, with the tangent in first-order Sacado numbers. Variables
       * of the result: slave (6), section a1, a2 at both nodes (12),
       * master.
       */
      template <int n>
      double
      penalty_terms_section(const MasterPatch                 &patch,
                            const SlaveSection                &section,
                            const std::array<Tensor<1, 3>, 2> &slave,
                            const double                       eta,
                            const double                       penalty,
                            const double                       weight,
                            const Point<2>                    &xi_converged,
                            Vector<double>                    *gradient,
                            FullMatrix<double>                *hessian)
      {
        constexpr unsigned int           n_full = n + 9;
        std::array<unsigned int, n_full> r;
        std::array<double, n_full>       w;
        section_variables<n_full>(eta, r, w);
        if (gradient)
          gradient->reinit(n_full);
        if (hessian)
          hessian->reinit(n_full, n_full);
        if (!hessian)
          {
            // The residual alone: the closed form in doubles.
            double              g;
            std::vector<double> grad;
            section_point(
              patch,
              section,
              slave,
              eta,
              xi_converged,
              [](const unsigned int, const double v) { return v; },
              g,
              grad);
            if (g >= 0.)
              return 0.;
            if (gradient)
              for (unsigned int i = 0; i < n_full; ++i)
                (*gradient)(i) = w[i] * weight * penalty * g * grad[r[i]];
            return 0.5 * weight * penalty * g * g;
          }
        // With the tangent: the Hessian of Pi = w eps/2 g^2 is the
        // Jacobian of w eps g grad g, read from first-order numbers.
        using AD = Sacado::Fad::SFad<double, n>;
        AD              g;
        std::vector<AD> grad;
        section_point(
          patch,
          section,
          slave,
          eta,
          xi_converged,
          [](const unsigned int k, const double v) { return AD(n, k, v); },
          g,
          grad);
        if (g.val() >= 0.)
          return 0.;
        const AD s = weight * penalty * g;
        for (unsigned int i = 0; i < n_full; ++i)
          {
            const AD gi = s * grad[r[i]];
            if (gradient)
              (*gradient)(i) = w[i] * gi.val();
            for (unsigned int j = 0; j < n_full; ++j)
              (*hessian)(i, j) = w[i] * w[j] * gi.dx(r[j]);
          }
        for (unsigned int i = 0; i < n_full; ++i)
          for (unsigned int j = 0; j < i; ++j)
            (*hessian)(i, j) = (*hessian)(j, i) =
              0.5 * ((*hessian)(i, j) + (*hessian)(j, i));
        return 0.5 * weight * penalty * g.val() * g.val();
      }
    } // namespace

    namespace
    {
      /**
       * The Sacado variables of one point (slave, with a section a1, a2
       * at both nodes, master nodes, with a smoothed field the nodal
       * normals) and its projection taken in them from the converged
       * xi: two Newton steps of the closest point (facet) or of
       * x = rho + g n (smoothed), then the gap g - h along the normal.
       */
      template <int n>
      struct PointVariables
      {
        using AD = Sacado::Fad::SFad<double, n>;
        AD                             x[3], a1[3], a2[3];
        std::vector<std::array<AD, 3>> y, nbar;
        /// First master variable; variables in use.
        unsigned int m0 = 0, n_used = 0;
        /// Projection, gap and normal; smoothed with a section also the
        /// section's extent h = sqrt(p1^2 + p2^2), p_i = a_i . n.
        AD xi[2], gap, normal[3], p1, p2, h;

        PointVariables(const MasterPatch                 &patch,
                       const SlaveSection                *section,
                       const std::array<Tensor<1, 3>, 2> &slave,
                       const double                       eta,
                       const double                       radius,
                       const Point<2>                    &xi_converged)
        {
          const unsigned int n_m      = patch.nodes.size();
          const bool         smoothed = !patch.normals.empty();
          m0                          = section ? 18 : 6;
          n_used                      = m0 + (smoothed ? 6 : 3) * n_m;
          for (unsigned int c = 0; c < 3; ++c)
            x[c] = (1. - eta) * AD(n, c, slave[0][c])
                   + eta * AD(n, 3 + c, slave[1][c]);
          if (section)
            for (unsigned int c = 0; c < 3; ++c)
              {
                a1[c] = (1. - eta) * AD(n, 6 + c, section->a1[0][c])
                        + eta * AD(n, 12 + c, section->a1[1][c]);
                a2[c] = (1. - eta) * AD(n, 9 + c, section->a2[0][c])
                        + eta * AD(n, 15 + c, section->a2[1][c]);
              }
          y.resize(n_m);
          nbar.resize(smoothed ? n_m : 0);
          for (unsigned int a = 0; a < n_m; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              y[a][c] = AD(n, m0 + 3 * a + c, patch.nodes[a][c]);
          for (unsigned int a = 0; a < nbar.size(); ++a)
            for (unsigned int c = 0; c < 3; ++c)
              nbar[a][c] = AD(n, m0 + 3 * n_m + 3 * a + c, patch.normals[a][c]);
          xi[0] = xi_converged[0];
          xi[1] = xi_converged[1];
          if (!smoothed)
            {
              newton_step(patch.degree, y, x, xi);
              newton_step(patch.degree, y, x, xi);
              gap = contact::gap(patch.degree,
                                 y,
                                 x,
                                 xi,
                                 patch.sign,
                                 radius,
                                 normal,
                                 section ? a1 : nullptr,
                                 section ? a2 : nullptr);
              return;
            }
          const double xs[3] = {x[0].val(), x[1].val(), x[2].val()};
          AD           g(smooth_distance(patch, xs, xi_converged));
          smooth_newton_step(patch.degree, y, nbar, x, xi, g);
          smooth_newton_step(patch.degree, y, nbar, x, xi, g);
          SmoothFrame<AD> f;
          smooth_frame(patch.degree, y, nbar, xi, g, f);
          p1 = 0.;
          p2 = 0.;
          h  = radius;
          for (unsigned int c = 0; c < 3; ++c)
            {
              normal[c] = f.n[c];
              if (section)
                {
                  p1 += a1[c] * f.n[c];
                  p2 += a2[c] * f.n[c];
                }
            }
          using std::sqrt;
          if (section)
            h = sqrt(p1 * p1 + p2 * p2);
          gap = g - h;
        }
      };
    } // namespace

    namespace
    {
      /**
       * The penalty force along the smoothed normal field. Variables:
       * slave (6), with a section a1, a2 at both nodes (12), the master
       * nodes, the nodal normals. The force w N n(xi), N = -eps (g - h),
       * acts on the cable point (and on the section's extreme point
       * towards the master) and -w N n on the master at rho(xi), along the
       * continuous normal: not the gradient of an energy (that would be
       * dg/dx_s = m, the normal of the kinked offset surface). Its
       * Jacobian, non-symmetric, by first-order Sacado numbers through two
       * Newton steps of the projection.
       */
      template <int n>
      double
      penalty_terms_smoothed(const MasterPatch                 &patch,
                             const SlaveSection                *section,
                             const std::array<Tensor<1, 3>, 2> &slave,
                             const double                       eta,
                             const double                       radius,
                             const double                       penalty,
                             const double                       weight,
                             const Point<2>                    &xi_converged,
                             Vector<double>                    *gradient,
                             FullMatrix<double>                *hessian)
      {
        using AD = Sacado::Fad::SFad<double, n>;
        const PointVariables<n> v(
          patch, section, slave, eta, radius, xi_converged);
        const unsigned int n_m = patch.nodes.size(), m0 = v.m0,
                           n_used = v.n_used;
        const AD &gap = v.gap, &p1 = v.p1, &p2 = v.p2, &h = v.h;
        const AD *normal = v.normal;
        if (gradient)
          gradient->reinit(n_used);
        if (hessian)
          hessian->reinit(n_used, n_used);
        if (gap.val() >= 0.)
          return 0.;
        AD l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
        lagrange(patch.degree, v.xi[0], l1, dl1, ddl1);
        lagrange(patch.degree, v.xi[1], l2, dl2, ddl2);
        const unsigned int k = patch.degree + 1;
        // The contact force w N n on the cable (and its section) and
        // -w N n on the master at rho(xi): residual r = f_int - f_ext.
        const AD        wN = -weight * penalty * gap; // w N >= 0
        std::vector<AD> r(n_used, AD(0.));
        for (unsigned int c = 0; c < 3; ++c)
          {
            r[c]     = -(1. - eta) * wN * normal[c];
            r[3 + c] = -eta * wN * normal[c];
            if (section)
              {
                // The section's extreme point towards the master,
                // x_s - (p1 a1 + p2 a2)/h, takes the force too.
                r[6 + c]  = (1. - eta) * wN * p1 / h * normal[c];
                r[9 + c]  = (1. - eta) * wN * p2 / h * normal[c];
                r[12 + c] = eta * wN * p1 / h * normal[c];
                r[15 + c] = eta * wN * p2 / h * normal[c];
              }
          }
        for (unsigned int a = 0; a < n_m; ++a)
          for (unsigned int c = 0; c < 3; ++c)
            r[m0 + 3 * a + c] = wN * l1[a % k] * l2[a / k] * normal[c];
        for (unsigned int i = 0; i < n_used; ++i)
          {
            if (gradient)
              (*gradient)(i) = r[i].val();
            if (hessian)
              for (unsigned int j = 0; j < n_used; ++j)
                (*hessian)(i, j) = r[i].dx(j);
          }
        return 0.5 * weight * penalty * gap.val() * gap.val();
      }
    } // namespace

    double
    penalty_terms(const MasterPatch                 &patch,
                  const std::array<Tensor<1, 3>, 2> &slave,
                  const double                       eta,
                  const double                       radius,
                  const double                       penalty,
                  const double                       weight,
                  const Point<2>                    &xi,
                  Vector<double>                    *gradient,
                  FullMatrix<double>                *hessian,
                  const SlaveSection                *section)
    {
      if (!patch.normals.empty())
        {
#define PNEUMA_SMOOTHED(n)            \
  penalty_terms_smoothed<n>(patch,    \
                            section,  \
                            slave,    \
                            eta,      \
                            radius,   \
                            penalty,  \
                            weight,   \
                            xi,       \
                            gradient, \
                            hessian)
          if (patch.degree == 1)
            return section ? PNEUMA_SMOOTHED(42) : PNEUMA_SMOOTHED(30);
          return section ? PNEUMA_SMOOTHED(72) : PNEUMA_SMOOTHED(60);
#undef PNEUMA_SMOOTHED
        }
      if (section)
        return patch.degree == 1 ? penalty_terms_section<21>(patch,
                                                             *section,
                                                             slave,
                                                             eta,
                                                             penalty,
                                                             weight,
                                                             xi,
                                                             gradient,
                                                             hessian)
                                 : penalty_terms_section<36>(patch,
                                                             *section,
                                                             slave,
                                                             eta,
                                                             penalty,
                                                             weight,
                                                             xi,
                                                             gradient,
                                                             hessian);
      if (patch.degree == 1)
        return penalty_terms_envelope<18>(
          patch, slave, eta, radius, penalty, weight, xi, gradient, hessian);
      return penalty_terms_envelope<33>(
        patch, slave, eta, radius, penalty, weight, xi, gradient, hessian);
    }
    namespace
    {
      template <int n>
      FrictionState
      friction_sized(const MasterPatch                 &patch,
                     const SlaveSection                *section,
                     const Point<2>                    &xi_anchor,
                     const std::array<Tensor<1, 3>, 2> &slave,
                     const double                       eta,
                     const double                       radius,
                     const double                       eps_N,
                     const double                       eps_T,
                     const double                       mu,
                     const double                       weight,
                     const Point<2>                    &xi_converged,
                     Vector<double>                    *residual,
                     FullMatrix<double>                *jacobian)
      {
        using AD = Sacado::Fad::SFad<double, n>;
        const PointVariables<n> v(
          patch, section, slave, eta, radius, xi_converged);
        const unsigned int n_m = patch.nodes.size(), m0 = v.m0,
                           n_used = v.n_used;
        const AD     &g = v.gap, *normal = v.normal, *x = v.x, *xi = v.xi;
        const auto   &z = v.y;
        FrictionState state;
        if (residual)
          residual->reinit(n_used);
        if (jacobian)
          jacobian->reinit(n_used, n_used);
        if (g.val() >= 0.)
          return state;
        const AD N = -eps_N * g;
        // Anchor point and the trial traction.
        AD l1[3], dl1[3], ddl1[3], l2[3], dl2[3], ddl2[3];
        lagrange(patch.degree, AD(xi_anchor[0]), l1, dl1, ddl1);
        lagrange(patch.degree, AD(xi_anchor[1]), l2, dl2, ddl2);
        const unsigned int k     = patch.degree + 1;
        AD                 ya[3] = {0., 0., 0.};
        for (unsigned int a = 0; a < n_m; ++a)
          for (unsigned int c = 0; c < 3; ++c)
            ya[c] += l1[a % k] * l2[a / k] * z[a][c];
        AD d[3], dn = 0.;
        for (unsigned int c = 0; c < 3; ++c)
          {
            d[c] = x[c] - ya[c];
            dn += d[c] * normal[c];
          }
        AD t[3], t_norm2 = 0.;
        for (unsigned int c = 0; c < 3; ++c)
          {
            t[c] = -eps_T * (d[c] - dn * normal[c]);
            t_norm2 += t[c] * t[c];
          }
        using std::sqrt;
        const AD t_norm = sqrt(t_norm2 + 1e-300);
        if (t_norm.val() > mu * N.val())
          {
            state.slip = true;
            for (unsigned int c = 0; c < 3; ++c)
              t[c] = mu * N * t[c] / t_norm;
          }
        // Master shape functions at the contact point.
        AD m1[3], dm1[3], ddm1[3], m2[3], dm2[3], ddm2[3];
        lagrange(patch.degree, xi[0], m1, dm1, ddm1);
        lagrange(patch.degree, xi[1], m2, dm2, ddm2);
        std::vector<AD> r(n_used);
        for (unsigned int c = 0; c < 3; ++c)
          {
            r[c]     = -weight * (1. - eta) * t[c];
            r[3 + c] = -weight * eta * t[c];
          }
        for (unsigned int a = 0; a < n_m; ++a)
          for (unsigned int c = 0; c < 3; ++c)
            r[m0 + 3 * a + c] = weight * m1[a % k] * m2[a / k] * t[c];
        for (unsigned int i = 0; i < n_used; ++i)
          {
            if (residual)
              (*residual)(i) = r[i].val();
            if (jacobian)
              for (unsigned int j = 0; j < n_used; ++j)
                (*jacobian)(i, j) = r[i].dx(j);
          }
        // State for the update of the anchor.
        const Tensor<1, 3> rho =
          position(patch, Point<2>(xi[0].val(), xi[1].val()));
        for (unsigned int c = 0; c < 3; ++c)
          {
            state.traction[c]      = t[c].val();
            state.anchor_target[c] = ya[c].val();
          }
        if (state.slip)
          // Dragged so that the elastic tangential offset is mu N / eps_T.
          state.anchor_target = rho + state.traction / eps_T;
        return state;
      }
    } // namespace

    FrictionState
    friction_terms(const MasterPatch                 &patch,
                   const Point<2>                    &xi_anchor,
                   const std::array<Tensor<1, 3>, 2> &slave,
                   const double                       eta,
                   const double                       radius,
                   const double                       penalty,
                   const double                       tangential_penalty,
                   const double                       mu,
                   const double                       weight,
                   const Point<2>                    &xi,
                   Vector<double>                    *residual,
                   FullMatrix<double>                *jacobian,
                   const SlaveSection                *section)
    {
#define PNEUMA_FRICTION(n)              \
  friction_sized<n>(patch,              \
                    section,            \
                    xi_anchor,          \
                    slave,              \
                    eta,                \
                    radius,             \
                    penalty,            \
                    tangential_penalty, \
                    mu,                 \
                    weight,             \
                    xi,                 \
                    residual,           \
                    jacobian)
      if (!patch.normals.empty())
        {
          if (patch.degree == 1)
            return section ? PNEUMA_FRICTION(42) : PNEUMA_FRICTION(30);
          return section ? PNEUMA_FRICTION(72) : PNEUMA_FRICTION(60);
        }
      if (patch.degree == 1)
        return section ? PNEUMA_FRICTION(30) : PNEUMA_FRICTION(18);
      return section ? PNEUMA_FRICTION(45) : PNEUMA_FRICTION(33);
#undef PNEUMA_FRICTION
    }
  } // namespace contact
} // namespace pneuma
