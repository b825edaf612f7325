#include <deal.II/base/config.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <pneuma/cables/solid_beam_section.h>

#ifndef DEAL_II_TRILINOS_WITH_SACADO
#error "pneuma's solid-beam section needs deal.II with Trilinos Sacado"
#endif

DEAL_II_DISABLE_EXTRA_DIAGNOSTICS
#include <Sacado.hpp>
DEAL_II_ENABLE_EXTRA_DIAGNOSTICS

#include <cmath>
#include <limits>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      // Forward-mode AD numbers over the 9 entries of F: once (gradient)
      // and twice (gradient and Hessian) differentiable, statically sized,
      // so that no memory is allocated inside the section loop.
      constexpr int n_F = 9;
      using AD1         = Sacado::Fad::SFad<double, n_F>;
      using AD2         = Sacado::Fad::SFad<AD1, n_F>;

      inline double
      scalar(const double x)
      {
        return x;
      }
      inline double
      scalar(const AD1 &x)
      {
        return x.val();
      }
      inline double
      scalar(const AD2 &x)
      {
        return x.val().val();
      }

      /**
       * Psi(F) per unit reference volume, F[3 i + J] = F_iJ. Quiet NaN for
       * the neo-Hookean law at J <= 0.
       */
      template <typename Number>
      Number
      psi(const std::array<Number, 9> &F,
          const BeamLaw                law,
          const double                 lambda,
          const double                 mu)
      {
        if (law == BeamLaw::saint_venant_kirchhoff)
          {
            // E = (F^T F - I)/2, C_IJ = sum_i F_iI F_iJ.
            const Number E00 =
              0.5 * (F[0] * F[0] + F[3] * F[3] + F[6] * F[6] - 1.);
            const Number E11 =
              0.5 * (F[1] * F[1] + F[4] * F[4] + F[7] * F[7] - 1.);
            const Number E22 =
              0.5 * (F[2] * F[2] + F[5] * F[5] + F[8] * F[8] - 1.);
            const Number E01 = 0.5 * (F[0] * F[1] + F[3] * F[4] + F[6] * F[7]);
            const Number E02 = 0.5 * (F[0] * F[2] + F[3] * F[5] + F[6] * F[8]);
            const Number E12 = 0.5 * (F[1] * F[2] + F[4] * F[5] + F[7] * F[8]);
            const Number trE = E00 + E11 + E22;
            return 0.5 * lambda * trE * trE
                   + mu
                       * (E00 * E00 + E11 * E11 + E22 * E22
                          + 2. * (E01 * E01 + E02 * E02 + E12 * E12));
          }
        else
          {
            Number trC = F[0] * F[0];
            for (unsigned int k = 1; k < 9; ++k)
              trC += F[k] * F[k];
            const Number J = F[0] * (F[4] * F[8] - F[5] * F[7])
                             - F[1] * (F[3] * F[8] - F[5] * F[6])
                             + F[2] * (F[3] * F[7] - F[4] * F[6]);
            if (!(scalar(J) > 0.))
              return Number(std::numeric_limits<double>::quiet_NaN());
            using std::log;
            const Number lnJ = log(J);
            return 0.5 * mu * (trC - 3.) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
          }
      }

      /// The covariant basis [v1 + z1 v3 + z2 v5, v2, v4] of a state
      /// (columns), for Q or q.
      inline Tensor<2, 3>
      basis(const SolidBeamSection::State &s, const double z1, const double z2)
      {
        Tensor<2, 3> B;
        for (unsigned int i = 0; i < 3; ++i)
          {
            B[i][0] = s[1][i] + z1 * s[3][i] + z2 * s[5][i];
            B[i][1] = s[2][i];
            B[i][2] = s[4][i];
          }
        return B;
      }

      /// Reference basis at a section point: G^{-1} and det G > 0.
      inline Tensor<2, 3>
      reference_inverse(const SolidBeamSection::State &Q,
                        const double                   z1,
                        const double                   z2,
                        double                        &detG)
      {
        const Tensor<2, 3> G = basis(Q, z1, z2);
        detG                 = determinant(G);
        AssertThrow(detG > 0. && std::isfinite(detG),
                    ExcMessage("Solid-beam section: the reference basis "
                               "[X0' + z1 A1' + z2 A2', A1, A2] is singular "
                               "or left-handed (det G = "
                               + std::to_string(detG)
                               + "): A1, A2 and the tangent must form a "
                                 "right-handed frame over the whole section."));
        return invert(G);
      }

      /// F = g G^{-1} as F[3 i + J].
      inline std::array<double, 9>
      deformation_gradient(const Tensor<2, 3> &g, const Tensor<2, 3> &Ginv)
      {
        std::array<double, 9> F;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int J = 0; J < 3; ++J)
            F[3 * i + J] = g[i][0] * Ginv[0][J] + g[i][1] * Ginv[1][J]
                           + g[i][2] * Ginv[2][J];
        return F;
      }

      /**
       * The blocks of q entering column a of g and their coefficients:
       * column 0 = x0' + z1 a1' + z2 a2', column 1 = a1, column 2 = a2.
       */
      struct ColumnTerms
      {
        unsigned int n;
        unsigned int block[3];
        double       coefficient[3];
      };

      inline std::array<ColumnTerms, 3>
      column_terms(const double z1, const double z2)
      {
        return {{{3, {1, 3, 5}, {1., z1, z2}},
                 {1, {2, 0, 0}, {1., 0., 0.}},
                 {1, {4, 0, 0}, {1., 0., 0.}}}};
      }

      /**
       * w, dw/dq and (if @p hessian) d2w/dq2 by the chain rule
       * q -> g (linear) -> F = g G^{-1} (linear) -> Psi (AD).
       */
      template <bool with_hessian>
      void
      evaluate_section(const std::vector<std::array<double, 3>> &points,
                       const BeamLaw                             law,
                       const double                              lambda,
                       const double                              mu,
                       const SolidBeamSection::State            &Q,
                       const SolidBeamSection::State            &q,
                       double                                   &w,
                       SolidBeamSection::Gradient               &gradient,
                       FullMatrix<double>                       *hessian)
      {
        constexpr unsigned int n = SolidBeamSection::n_variables;
        w                        = 0.;
        gradient.fill(0.);
        if constexpr (with_hessian)
          {
            if (hessian->m() != n || hessian->n() != n)
              hessian->reinit(n, n);
            else
              *hessian = 0.;
          }

        std::array<AD1, 9> F1;
        std::array<AD2, 9> F2;
        double             P[9], A[9][9], dg[9], T[9][9], Hg[9][9];

        for (const auto &point : points)
          {
            const double       z1 = point[0], z2 = point[1];
            double             detG;
            const Tensor<2, 3> Ginv = reference_inverse(Q, z1, z2, detG);
            const Tensor<2, 3> g    = basis(q, z1, z2);
            const auto         F    = deformation_gradient(g, Ginv);
            const double       c    = point[2] * detG;

            double value;
            if constexpr (with_hessian)
              {
                for (int k = 0; k < n_F; ++k)
                  F2[k] = AD2(n_F, k, AD1(n_F, k, F[k]));
                const AD2 p = psi(F2, law, lambda, mu);
                value       = p.val().val();
                for (int k = 0; k < n_F; ++k)
                  {
                    P[k] = p.dx(k).val();
                    for (int l = 0; l < n_F; ++l)
                      A[k][l] = p.dx(k).dx(l);
                  }
              }
            else
              {
                for (int k = 0; k < n_F; ++k)
                  F1[k] = AD1(n_F, k, F[k]);
                const AD1 p = psi(F1, law, lambda, mu);
                value       = p.val();
                for (int k = 0; k < n_F; ++k)
                  P[k] = p.dx(k);
              }
            if (!std::isfinite(value))
              {
                const double nan = std::numeric_limits<double>::quiet_NaN();
                w                = nan;
                gradient.fill(nan);
                if constexpr (with_hessian)
                  for (unsigned int k = 0; k < n; ++k)
                    for (unsigned int l = 0; l < n; ++l)
                      (*hessian)(k, l) = nan;
                return;
              }
            w += c * value;

            // dPsi/dg_ia = P_iJ Ginv_aJ, stored at 3 a + i.
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int i = 0; i < 3; ++i)
                dg[3 * a + i] = P[3 * i] * Ginv[a][0]
                                + P[3 * i + 1] * Ginv[a][1]
                                + P[3 * i + 2] * Ginv[a][2];

            const auto terms = column_terms(z1, z2);
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int t = 0; t < terms[a].n; ++t)
                {
                  const unsigned int b  = terms[a].block[t];
                  const double       cb = c * terms[a].coefficient[t];
                  for (unsigned int i = 0; i < 3; ++i)
                    gradient[3 * b + i] += cb * dg[3 * a + i];
                }

            if constexpr (with_hessian)
              {
                // T_{iJ, ke} = A_{iJ, kL} Ginv_eL; Hg_{ia, ke} = Ginv_aJ
                // T_{iJ, ke}.
                for (unsigned int iJ = 0; iJ < 9; ++iJ)
                  for (unsigned int e = 0; e < 3; ++e)
                    for (unsigned int k = 0; k < 3; ++k)
                      T[iJ][3 * e + k] = A[iJ][3 * k] * Ginv[e][0]
                                         + A[iJ][3 * k + 1] * Ginv[e][1]
                                         + A[iJ][3 * k + 2] * Ginv[e][2];
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int i = 0; i < 3; ++i)
                    for (unsigned int ke = 0; ke < 9; ++ke)
                      Hg[3 * a + i][ke] = Ginv[a][0] * T[3 * i][ke]
                                          + Ginv[a][1] * T[3 * i + 1][ke]
                                          + Ginv[a][2] * T[3 * i + 2][ke];

                FullMatrix<double> &H = *hessian;
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int s = 0; s < terms[a].n; ++s)
                    for (unsigned int e = 0; e < 3; ++e)
                      for (unsigned int t = 0; t < terms[e].n; ++t)
                        {
                          const unsigned int b   = terms[a].block[s];
                          const unsigned int d   = terms[e].block[t];
                          const double       cbd = c * terms[a].coefficient[s]
                                             * terms[e].coefficient[t];
                          for (unsigned int i = 0; i < 3; ++i)
                            for (unsigned int k = 0; k < 3; ++k)
                              H(3 * b + i, 3 * d + k) +=
                                cbd * Hg[3 * a + i][3 * e + k];
                        }
              }
          }
        if constexpr (with_hessian)
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int l = 0; l < k; ++l)
              (*hessian)(k, l) = (*hessian)(l, k) =
                0.5 * ((*hessian)(k, l) + (*hessian)(l, k));
      }
    } // namespace



    double
    BeamMaterial::lambda() const
    {
      return youngs_modulus * poisson_ratio
             / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    }



    double
    BeamMaterial::mu() const
    {
      return youngs_modulus / (2. * (1. + poisson_ratio));
    }



    SolidBeamSection::SolidBeamSection(const BeamMaterial &material,
                                       const unsigned int  n_r,
                                       const unsigned int  n_theta)
      : material(material)
      , lambda(material.lambda())
      , mu(material.mu())
    {
      AssertThrow(material.youngs_modulus > 0. && material.poisson_ratio > -1.
                    && material.poisson_ratio < 0.5,
                  ExcMessage("Solid-beam section: needs E > 0 and "
                             "-1 < nu < 0.5."));
      AssertThrow(n_r >= 1 && n_theta >= 1,
                  ExcMessage("Solid-beam section: the section rule needs "
                             "n_r >= 1 and n_theta >= 1."));
      // Gauss-Legendre on [0, 1] in r with the weight r dr, equally spaced
      // angles; the weights sum to the area pi of the unit disc.
      const QGauss<1> radial(n_r);
      points.reserve(n_r * n_theta);
      for (unsigned int i = 0; i < n_r; ++i)
        for (unsigned int k = 0; k < n_theta; ++k)
          {
            const double r     = radial.point(i)[0];
            const double theta = 2. * numbers::PI * k / n_theta;
            points.push_back(
              {{r * std::cos(theta),
                r * std::sin(theta),
                radial.weight(i) * r * 2. * numbers::PI / n_theta}});
          }
    }



    double
    SolidBeamSection::strain_energy_density(const Tensor<2, 3> &F) const
    {
      std::array<double, 9> f;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int J = 0; J < 3; ++J)
          f[3 * i + J] = F[i][J];
      return psi(f, material.law, lambda, mu);
    }



    double
    SolidBeamSection::energy(const State &Q, const State &q) const
    {
      double w = 0.;
      for (const auto &point : points)
        {
          double             detG;
          const Tensor<2, 3> Ginv =
            reference_inverse(Q, point[0], point[1], detG);
          const auto F =
            deformation_gradient(basis(q, point[0], point[1]), Ginv);
          w += point[2] * detG * psi(F, material.law, lambda, mu);
        }
      return w;
    }



    void
    SolidBeamSection::evaluate(const State        &Q,
                               const State        &q,
                               double             &w,
                               Gradient           &gradient,
                               FullMatrix<double> &hessian) const
    {
      evaluate_section<true>(
        points, material.law, lambda, mu, Q, q, w, gradient, &hessian);
    }



    void
    SolidBeamSection::evaluate(const State &Q,
                               const State &q,
                               double      &w,
                               Gradient    &gradient) const
    {
      evaluate_section<false>(
        points, material.law, lambda, mu, Q, q, w, gradient, nullptr);
    }



    SectionResultants
    SolidBeamSection::resultants(const State &Q, const State &q) const
    {
      SectionResultants  r;
      std::array<AD1, 9> F1;
      for (const auto &point : points)
        {
          const double       z1 = point[0], z2 = point[1];
          double             detG;
          const Tensor<2, 3> Ginv = reference_inverse(Q, z1, z2, detG);
          const auto         F = deformation_gradient(basis(q, z1, z2), Ginv);
          for (int k = 0; k < n_F; ++k)
            F1[k] = AD1(n_F, k, F[k]);
          const AD1 p = psi(F1, material.law, lambda, mu);
          // Traction on the section per dz1 dz2: P N dA = det G P G^1,
          // G^1 the first row of G^{-1}.
          Tensor<1, 3> traction;
          for (unsigned int i = 0; i < 3; ++i)
            traction[i] =
              point[2] * detG
              * (p.dx(3 * i) * Ginv[0][0] + p.dx(3 * i + 1) * Ginv[0][1]
                 + p.dx(3 * i + 2) * Ginv[0][2]);
          r.force += traction;
          r.moment += cross_product_3d(z1 * q[2] + z2 * q[4], traction);
        }
      const Tensor<1, 3> t  = q[1] / q[1].norm();
      Tensor<1, 3>       d1 = q[2] - (q[2] * t) * t;
      d1 /= d1.norm();
      const Tensor<1, 3> d2 = cross_product_3d(t, d1);
      r.axial_force         = r.force * t;
      r.bending_moment_1    = r.moment * d1;
      r.bending_moment_2    = r.moment * d2;
      r.torsion_moment      = r.moment * t;
      r.stretch_1           = q[2].norm() / Q[2].norm();
      r.stretch_2           = q[4].norm() / Q[4].norm();
      return r;
    }
  } // namespace cables
} // namespace pneuma
