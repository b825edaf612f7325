// The contact point kernel (source paper eqs. 7-9): the penalty energy of
// one slave point on a curved master patch (Q1 and Q2 lattices on a
// perturbed cylinder), its gradient against central differences of the
// energy and its Hessian against central differences of the gradient
// (the variation of the normal and of the projection point included), the
// closest-point projection against a brute-force search, and the friction
// force's Jacobian (stick and slip) against central differences; and the
// elliptic solid-beam section in the gap. The same with a smoothed normal
// field (nodal normals as further variables): the projection along it,
// and the Jacobian of the force along it against central differences.

#include <deal.II/base/utilities.h>

#include <pneuma/contact/contact_point.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using namespace pneuma::contact;

int
main()
{
  bool ok = true;
  for (const bool smoothed : {false, true})
    for (const unsigned int degree : {1u, 2u})
      {
        // A patch of the cylinder of radius 0.5 about x, slightly perturbed.
        MasterPatch patch;
        patch.degree         = degree;
        const unsigned int n = degree + 1;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            {
              const double x  = 0.2 * i / degree;
              const double th = 0.3 * j / degree;
              Tensor<1, 3> y;
              y[0] = x + 0.003 * std::sin(7. * i + j);
              y[1] = 0.5 * std::sin(th) + 0.002 * std::cos(3. * i + 5. * j);
              y[2] = 0.5 * std::cos(th) + 0.002 * std::sin(i + 2. * j);
              patch.nodes.push_back(y);
            }
        // rho_1 x rho_2 = (0, sin, cos) points outward here.
        patch.sign = 1.;
        // Smoothed: nodal normals near the cylinder's, tilted a little.
        if (smoothed)
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int i = 0; i < n; ++i)
              {
                const double th = 0.3 * j / degree;
                Tensor<1, 3> nbar({0.04 * std::sin(3. * i + 2. * j),
                                   std::sin(th) + 0.03 * std::cos(i + j),
                                   std::cos(th)});
                patch.normals.push_back(nbar / nbar.norm());
              }
        const unsigned int n_nodes     = patch.nodes.size();
        const auto         set_normals = [&](MasterPatch               &pm,
                                     const std::vector<double> &w,
                                     const unsigned int         first) {
          for (unsigned int a = 0; a < pm.normals.size(); ++a)
            for (unsigned int c = 0; c < 3; ++c)
              pm.normals[a][c] = w[first + 3 * n_nodes + 3 * a + c];
        };
        const double                radius = 0.01, penalty = 1e6, weight = 0.05;
        std::array<Tensor<1, 3>, 2> slave;
        slave[0][0] = 0.05, slave[0][1] = 0.503 * std::sin(0.12),
        slave[0][2] = 0.503 * std::cos(0.12);
        slave[1][0] = 0.16, slave[1][1] = 0.503 * std::sin(0.2),
        slave[1][2]      = 0.503 * std::cos(0.2);
        const double eta = 0.37;

        const auto energy_at = [&](const std::vector<double> &v,
                                   Vector<double>            *g,
                                   FullMatrix<double>        *H) {
          MasterPatch                 p = patch;
          std::array<Tensor<1, 3>, 2> s;
          for (unsigned int c = 0; c < 3; ++c)
            {
              s[0][c] = v[c];
              s[1][c] = v[3 + c];
            }
          for (unsigned int a = 0; a < p.nodes.size(); ++a)
            for (unsigned int c = 0; c < 3; ++c)
              p.nodes[a][c] = v[6 + 3 * a + c];
          set_normals(p, v, 6);
          const Tensor<1, 3> x    = (1. - eta) * s[0] + eta * s[1];
          const Projection   proj = project(p, x, radius);
          return penalty_terms(
            p, s, eta, radius, penalty, weight, proj.xi, g, H);
        };
        std::vector<double> v;
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int c = 0; c < 3; ++c)
            v.push_back(slave[k][c]);
        for (const auto &y : patch.nodes)
          for (unsigned int c = 0; c < 3; ++c)
            v.push_back(y[c]);
        for (const auto &nbar : patch.normals)
          for (unsigned int c = 0; c < 3; ++c)
            v.push_back(nbar[c]);
        const unsigned int N = v.size();

        Vector<double>     g;
        FullMatrix<double> H;
        const double       e    = energy_at(v, &g, &H);
        const Tensor<1, 3> x    = (1. - eta) * slave[0] + eta * slave[1];
        const Projection   proj = project(patch, x, radius);
        std::printf("%s normal, degree %u: inside %s, xi = (%.4f, %.4f), "
                    "gap %.4e, energy %.4e\n",
                    smoothed ? "smoothed" : "facet",
                    degree,
                    proj.inside ? "yes" : "no",
                    proj.xi[0],
                    proj.xi[1],
                    proj.gap,
                    e);
        // The slave is outside the cylinder, closer than R: in contact.
        ok &= proj.inside && proj.gap < 0. && proj.gap > -radius && e > 0.;

        double best = 1e300;
        if (smoothed)
          {
            // x = rho(xi) + (gap + R) n.
            const double residual =
              (x - position(patch, proj.xi) - (proj.gap + radius) * proj.normal)
                .norm();
            const bool pass = residual < 1e-13;
            std::printf("  x - rho(xi) - g n(xi) = %s\n",
                        pass ? "0 (< 1e-13)" : "FAIL");
            ok &= pass;
          }
        else
          {
            // Sample the patch and compare the nearest sample with the result.
            MasterPatch p        = patch;
            const auto  position = [&](const double s, const double t) {
              Tensor<1, 3> r;
              const auto   l = [&](const unsigned int i, const double u) {
                if (degree == 1)
                  return i == 0 ? 1. - u : u;
                return i == 0   ? 2. * (u - 0.5) * (u - 1.)
                          : i == 1 ? -4. * u * (u - 1.)
                                   : 2. * u * (u - 0.5);
              };
              for (unsigned int j = 0; j < n; ++j)
                for (unsigned int i = 0; i < n; ++i)
                  r += l(i, s) * l(j, t) * p.nodes[i + n * j];
              return r;
            };
            for (unsigned int a = 0; a <= 400; ++a)
              for (unsigned int b = 0; b <= 400; ++b)
                best =
                  std::min(best, (x - position(a / 400., b / 400.)).norm());
            const bool pass =
              proj.distance <= best + 1e-12 && best - proj.distance < 1e-5;
            std::printf("  projection distance %.8f, nearest of 401^2 samples "
                        "%.8f: %s\n",
                        proj.distance,
                        best,
                        pass ? "PASS" : "FAIL");
            ok &= pass;
          }

        // Gradient vs central differences of the energy.
        const double h     = 1e-7;
        double       g_err = 0., g_max = 0., H_err = 0., H_max = 0.;
        for (unsigned int i = 0; i < N; ++i)
          {
            auto vp = v, vm = v;
            vp[i] += h;
            vm[i] -= h;
            Vector<double> gp, gm;
            const double   fd =
              (energy_at(vp, &gp, nullptr) - energy_at(vm, &gm, nullptr))
              / (2. * h);
            // Smoothed: the force is not an energy gradient (it acts
            // along the continuous normal); only its Jacobian is compared.
            if (!smoothed)
              {
                g_err = std::max(g_err, std::abs(fd - g[i]));
                g_max = std::max(g_max, std::abs(g[i]));
              }
            for (unsigned int j = 0; j < N; ++j)
              {
                const double fdH = (gp[j] - gm[j]) / (2. * h);
                H_err            = std::max(H_err, std::abs(fdH - H(j, i)));
                H_max            = std::max(H_max, std::abs(H(j, i)));
              }
          }
        const bool pass_g = smoothed || g_err / g_max < 1e-6;
        const bool pass_H = H_err / H_max < 1e-6;
        if (!smoothed)
          std::printf("  gradient vs finite differences: %s\n",
                      pass_g ? "relative error < 1e-6" : "FAIL");
        std::printf("  %s vs finite differences: %s\n",
                    smoothed ? "force Jacobian" : "Hessian",
                    pass_H ? "relative error < 1e-6" : "FAIL");
        if (!pass_g || !pass_H)
          std::printf("  errors %.3e %.3e\n", g_err / g_max, H_err / H_max);
        ok &= pass_g && pass_H;

        // Solid-beam slave: the elliptic section's extent along n,
        // h = sqrt((a1.n)^2 + (a2.n)^2), with the section unknowns as
        // variables (energy gradient and Hessian against finite differences).
        {
          SlaveSection section;
          section.a1[0]       = Tensor<1, 3>({0., 0.006, 0.0});
          section.a2[0]       = Tensor<1, 3>({0.001, 0., 0.009});
          section.a1[1]       = Tensor<1, 3>({0., 0.0062, 0.0005});
          section.a2[1]       = Tensor<1, 3>({0.0008, -0.0004, 0.0088});
          const auto energy_s = [&](const std::vector<double> &w,
                                    Vector<double>            *gs,
                                    FullMatrix<double>        *Hs) {
            MasterPatch                 pm = patch;
            std::array<Tensor<1, 3>, 2> sl;
            SlaveSection                sc;
            for (unsigned int c = 0; c < 3; ++c)
              {
                sl[0][c]    = w[c];
                sl[1][c]    = w[3 + c];
                sc.a1[0][c] = w[6 + c];
                sc.a2[0][c] = w[9 + c];
                sc.a1[1][c] = w[12 + c];
                sc.a2[1][c] = w[15 + c];
              }
            for (unsigned int a = 0; a < pm.nodes.size(); ++a)
              for (unsigned int c = 0; c < 3; ++c)
                pm.nodes[a][c] = w[18 + 3 * a + c];
            set_normals(pm, w, 18);
            const Tensor<1, 3> xs = (1. - eta) * sl[0] + eta * sl[1];
            const Projection   pr = project(pm, xs, radius);
            return penalty_terms(
              pm, sl, eta, radius, penalty, weight, pr.xi, gs, Hs, &sc);
          };
          std::vector<double> w(v.begin(), v.begin() + 6);
          for (const auto *vec :
               {&section.a1[0], &section.a2[0], &section.a1[1], &section.a2[1]})
            for (unsigned int c = 0; c < 3; ++c)
              w.push_back((*vec)[c]);
          w.insert(w.end(), v.begin() + 6, v.end());
          Vector<double>     gs;
          FullMatrix<double> Hs;
          const double       es = energy_s(w, &gs, &Hs);
          double             eg = 0., mg = 0., eH = 0., mH = 0.;
          for (unsigned int i = 0; i < w.size(); ++i)
            {
              auto wp = w, wm = w;
              wp[i] += h;
              wm[i] -= h;
              Vector<double> gp, gm;
              const double   fd =
                (energy_s(wp, &gp, nullptr) - energy_s(wm, &gm, nullptr))
                / (2. * h);
              if (!smoothed)
                {
                  eg = std::max(eg, std::abs(fd - gs[i]));
                  mg = std::max(mg, std::abs(gs[i]));
                }
              for (unsigned int j = 0; j < w.size(); ++j)
                {
                  eH =
                    std::max(eH,
                             std::abs((gp[j] - gm[j]) / (2. * h) - Hs(j, i)));
                  mH = std::max(mH, std::abs(Hs(j, i)));
                }
            }
          const bool pass =
            es > 0. && (smoothed || eg / mg < 1e-6) && eH / mH < 1e-6;
          std::printf("  elliptic solid-beam section: gradient and Hessian vs "
                      "finite differences: %s\n",
                      pass ? "relative error < 1e-6" : "FAIL");
          if (!pass)
            std::printf("  energy %.3e errors %.3e %.3e\n",
                        es,
                        eg / mg,
                        eH / mH);
          ok &= pass;
        }

        // Friction: the force and its (non-symmetric) Jacobian against
        // central differences, sticking (anchor 0.1 mm away) and slipping
        // (anchor 5 cm away), mu = 0.3, eps_T = eps_N.
        for (const double offset : {0.0005, 0.25})
          {
            const Point<2> xi_anchor(proj.xi[0] + offset, proj.xi[1] - offset);
            const auto     force_at = [&](const std::vector<double> &w,
                                      Vector<double>            &f,
                                      FullMatrix<double>        *J) {
              MasterPatch                 pm = patch;
              std::array<Tensor<1, 3>, 2> sl;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  sl[0][c] = w[c];
                  sl[1][c] = w[3 + c];
                }
              for (unsigned int a = 0; a < pm.nodes.size(); ++a)
                for (unsigned int c = 0; c < 3; ++c)
                  pm.nodes[a][c] = w[6 + 3 * a + c];
              set_normals(pm, w, 6);
              const Tensor<1, 3> xs = (1. - eta) * sl[0] + eta * sl[1];
              const Projection   pr = project(pm, xs, radius);
              return friction_terms(pm,
                                    xi_anchor,
                                    sl,
                                    eta,
                                    radius,
                                    penalty,
                                    penalty,
                                    0.3,
                                    weight,
                                    pr.xi,
                                    &f,
                                    J);
            };
            Vector<double>      f;
            FullMatrix<double>  J;
            const FrictionState st  = force_at(v, f, &J);
            double              err = 0., big = 0.;
            for (unsigned int i = 0; i < N; ++i)
              {
                auto vp = v, vm = v;
                vp[i] += h;
                vm[i] -= h;
                Vector<double> fp, fm;
                force_at(vp, fp, nullptr);
                force_at(vm, fm, nullptr);
                for (unsigned int j = 0; j < N; ++j)
                  {
                    err =
                      std::max(err,
                               std::abs((fp[j] - fm[j]) / (2. * h) - J(j, i)));
                    big = std::max(big, std::abs(J(j, i)));
                  }
              }
            const bool pass = err / big < 1e-6;
            std::printf("  friction, %s: Jacobian vs finite differences: %s\n",
                        st.slip ? "slip" : "stick",
                        pass ? "relative error < 1e-6" : "FAIL");
            if (!pass)
              std::printf("  error %.3e\n", err / big);
            ok &= pass && st.slip == (offset > 0.1);
          }
      }
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
