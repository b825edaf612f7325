#include <pneuma/core/input_error.h>
#include <pneuma/membrane/tension_field.h>

#include <cmath>
#include <limits>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    namespace
    {
      /// The symmetric dyad sym(a x b) of two 2-vectors.
      SymmetricTensor<2, 2>
      sym_dyad(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        SymmetricTensor<2, 2> t;
        t[0][0] = a[0] * b[0];
        t[1][1] = a[1] * b[1];
        t[0][1] = 0.5 * (a[0] * b[1] + a[1] * b[0]);
        return t;
      }

      /// Smallest eigenvalue of a symmetric 2x2 tensor (no discriminant of
      /// round-off sign).
      double
      min_eigenvalue(const SymmetricTensor<2, 2> &A)
      {
        return 0.5 * (A[0][0] + A[1][1])
               - std::hypot(0.5 * (A[0][0] - A[1][1]), A[0][1]);
      }

      /// The map X -> A X A on symmetric tensors, as a rank-4 tensor.
      SymmetricTensor<4, 2>
      sandwich(const SymmetricTensor<2, 2> &A)
      {
        SymmetricTensor<4, 2> K;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = i; j < 2; ++j)
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int l = k; l < 2; ++l)
                K[i][j][k][l] = 0.5 * (A[i][k] * A[j][l] + A[i][l] * A[j][k]);
        return K;
      }

      Tensor<1, 2>
      unit(const double angle)
      {
        Tensor<1, 2> m;
        m[0] = std::cos(angle);
        m[1] = std::sin(angle);
        return m;
      }
    } // namespace

    TensionFieldLaw::TensionFieldLaw(std::shared_ptr<const ConstitutiveLaw> law,
                                     const double residual_stiffness,
                                     const double smoothing)
      : law(std::move(law))
      , residual_stiffness(residual_stiffness)
      , C_free(unit_symmetric_tensor<2>())
    {
      // The stress-free metric: Newton on S(C_0) = 0 from I (one step or
      // none for the laws without prestress, whose S(I) = 0).
      SymmetricTensor<2, 2> S;
      SymmetricTensor<4, 2> D;
      for (unsigned int it = 0; it < 50; ++it)
        {
          this->law->evaluate(C_free, S, D);
          if (S.norm() <= 1e-14 * this->law->initial_shear_modulus())
            break;
          // dS = D : dE = D : dC/2.
          C_free -= 2. * (invert(D) * S);
        }
      // The barrier weight: a uniaxial strain e against the stiffest
      // direct modulus d of the law at C_0 is smoothed over |e| of about
      // zeta, delta = d zeta^2 / 4 (the scalar problem s = d (e + b/2) =
      // 2 delta / b has b = zeta at e = 0).
      this->law->evaluate(C_free, S, D);
      delta =
        std::max(D[0][0][0][0], D[1][1][1][1]) * smoothing * smoothing / 4.;
      if (delta > 0.)
        {
          SymmetricTensor<2, 2> S_r, B;
          SymmetricTensor<4, 2> D_r;
          smoothed(C_free, S, D, S_r, D_r, B);
          energy_offset = this->law->strain_energy(C_free + B)
                          - delta * std::log(determinant(B));
        }
    }

    bool
    TensionFieldLaw::smoothed(const SymmetricTensor<2, 2> &C,
                              SymmetricTensor<2, 2>       &S_plain,
                              SymmetricTensor<4, 2>       &D_plain,
                              SymmetricTensor<2, 2>       &S,
                              SymmetricTensor<4, 2>       &D,
                              SymmetricTensor<2, 2>       &B) const
    {
      // Start: the exact relaxed state, each of its directions with the
      // scalar barrier problem s + d b/2 = 2 delta/b (d = v.v:D:v.v):
      // - taut: b along each principal direction v of S(C);
      // - wrinkled: about beta m x m, and b along the tension direction p;
      // - slack: C_0 - C, and the barrier's width zeta = 2 sqrt(delta/d)
      //   added (its border has a zero eigenvalue).
      // (Estimating a wrinkled point from S(C) alone starts from a B of
      // full rank where the solution's is nearly of rank one, far outside
      // the barrier Newton's region of fast convergence.)
      const auto scalar = [&](const double s, const double d) {
        const double q = std::sqrt(s * s + 4. * d * delta);
        return s > 0. ? 4. * delta / (s + q) : (q - s) / d;
      };
      SymmetricTensor<2, 2> S_exact;
      SymmetricTensor<4, 2> D_exact;
      double                beta = 0.;
      Tensor<1, 2>          m;
      const WrinklingState  exact =
        solve(C, S_plain, D_plain, S_exact, D_exact, beta, m);
      B = SymmetricTensor<2, 2>();
      if (exact.kind == WrinklingState::wrinkled && beta > 0.
          && std::isfinite(S_exact.norm()))
        {
          // Along m the plain stress at C is about -d_m beta/2, so the
          // scalar problem gives (beta + sqrt(beta^2 + 16 delta/d_m))/2:
          // beta where the wrinkles are deep, the barrier's width zeta
          // where beta is far below it (near the reference state, where
          // beta m x m alone left B nearly singular).
          const Tensor<1, 2>         &p   = exact.tension_direction;
          const SymmetricTensor<2, 2> P   = sym_dyad(p, p);
          const SymmetricTensor<2, 2> M   = sym_dyad(m, m);
          const double                d_m = std::max(M * (D_plain * M), 1e-300);
          B                               = scalar(-0.5 * d_m * beta, d_m) * M
              + scalar(p * (S_exact * p), std::max(P * (D_exact * P), 1e-300))
                  * P;
        }
      else if (exact.kind == WrinklingState::slack)
        {
          const double d = std::max(D_plain[0][0][0][0], D_plain[1][1][1][1]);
          B =
            C_free - C + 2. * std::sqrt(delta / d) * unit_symmetric_tensor<2>();
        }
      else
        for (const auto &[s, v] : eigenvectors(S_plain))
          {
            const SymmetricTensor<2, 2> V = sym_dyad(v, v);
            B += scalar(s, std::max(V * (D_plain * V), 1e-300)) * V;
          }
      // Newton on g(B) = S(C + B)/2 - delta B^-1 = 0, the stationarity of
      // the convex f(B) = W(C + B) - delta ln det B, inside B > 0: a full
      // step that lowers |g| is taken (near the solution f no longer
      // resolves the decrease), else backtracking on f (Armijo).
      const auto f = [&](const SymmetricTensor<2, 2> &X) {
        return law->strain_energy(C + X) - delta * std::log(determinant(X));
      };
      const auto gradient = [&](const SymmetricTensor<2, 2> &X) {
        law->evaluate(C + X, S, D);
        return SymmetricTensor<2, 2>(0.5 * S - delta * invert(X));
      };
      // Inside the barrier with a margin that B^-1 resolves.
      const auto inside = [](const SymmetricTensor<2, 2> &X) {
        return min_eigenvalue(X) > 1e-12 * X.norm();
      };
      const double          floor = 1e-14 * law->initial_shear_modulus();
      SymmetricTensor<2, 2> g     = gradient(B);
      // The tangent at the converged B: dS/dE = D - D (D + 4 delta K)^-1 D
      // = (D^-1 + (B.B)/(4 delta))^-1, K: X -> B^-1 X B^-1 (doc/theory.md).
      const auto converged = [&]() {
        D = invert(invert(D) + sandwich(B) / (4. * delta));
        return std::isfinite(D.norm());
      };
      // The round-off of g grows with the condition of B (a wrinkled
      // point's B is nearly of rank one; beta t / (2 delta) is 1e8 at 10 %
      // compression with zeta = 1e-5): a full step that no longer lowers
      // |g|, or leaves B > 0, ends the iteration if |g| is below 1e-9 of
      // its terms or the step would change the stress by less than 1e-7
      // of it.
      for (unsigned int it = 0; it < 50; ++it)
        {
          const SymmetricTensor<2, 2> B_inv = invert(B);
          const double scale = 0.5 * S.norm() + delta * B_inv.norm();
          if (g.norm() <= 1e-13 * scale + floor)
            return converged();
          const SymmetricTensor<4, 2> H  = 0.25 * D + delta * sandwich(B_inv);
          const SymmetricTensor<2, 2> dB = -(invert(H) * g);
          if (!std::isfinite(dB.norm()))
            break;
          // The step's change of the stress: where it is below round-off
          // nothing more can be gained.
          const double change = 0.5 * (D * dB).norm();
          if (change <= 1e-14 * S.norm() + floor)
            return converged();
          SymmetricTensor<2, 2> trial = B + dB;
          if (inside(trial))
            {
              const SymmetricTensor<2, 2> g_trial = gradient(trial);
              if (g_trial.norm() < g.norm())
                {
                  B = trial;
                  g = g_trial;
                  continue;
                }
              g = gradient(B); // S and D at B again
            }
          if (g.norm() <= 1e-9 * scale || change <= 1e-7 * S.norm())
            return converged();
          const double f_B   = f(B);
          const double slope = g * dB;
          bool         taken = false;
          for (double alpha = 0.5; alpha > 1e-12; alpha *= 0.5)
            {
              trial = B + alpha * dB;
              if (inside(trial) && f(trial) <= f_B + 1e-4 * alpha * slope)
                {
                  taken = true;
                  break;
                }
            }
          if (!taken)
            break;
          B = trial;
          g = gradient(B);
        }
      return false;
    }

    WrinklingState
    TensionFieldLaw::solve(const SymmetricTensor<2, 2> &C,
                           SymmetricTensor<2, 2>       &S_plain,
                           SymmetricTensor<4, 2>       &D_plain,
                           SymmetricTensor<2, 2>       &S_star,
                           SymmetricTensor<4, 2>       &D_star,
                           double                      &beta,
                           Tensor<1, 2>                &m) const
    {
      WrinklingState state;
      law->evaluate(C, S_plain, D_plain);
      S_star                   = S_plain;
      D_star                   = D_plain;
      beta                     = 0.;
      state.C_star             = C;
      const double s_min       = min_eigenvalue(S_star);
      state.plain_minor_stress = s_min;
      // Taut down to round-off (the reference state's S(I) is zero to a
      // few ulps of the modulus, of either sign).
      if (s_min >= -1e-13 * law->initial_shear_modulus())
        return state;

      if (min_eigenvalue(C_free - C) >= 0.)
        {
          state.kind   = WrinklingState::slack;
          state.C_star = C_free;
          S_star       = SymmetricTensor<2, 2>();
          D_star       = SymmetricTensor<4, 2>();
          return state;
        }

      // Wrinkled: beta and the angle of m with S(C + beta m x m) m = 0.
      const double scale      = S_star.norm();
      const double mu         = law->initial_shear_modulus();
      const double tol        = 1e-13 * scale + 1e-15 * mu;
      const auto   eig        = eigenvectors(S_star);
      double       angle      = std::atan2(eig[1].second[1], eig[1].second[0]);
      m                       = unit(angle);
      SymmetricTensor<2, 2> M = sym_dyad(m, m);

      // Beta along the fixed direction first: f(beta) = M : S* increases
      // with beta (f' = M:D:M/2 > 0) from f(0) = s_min < 0.
      for (unsigned int it = 0; it < 50; ++it)
        {
          law->evaluate(C + beta * M, S_star, D_star);
          const double f  = M * S_star;
          const double df = 0.5 * (M * (D_star * M));
          if (std::abs(f) <= tol || !(df > 0.))
            break;
          beta = std::max(beta - f / df, 0.5 * beta);
        }

      // Both unknowns: r = (m.S*m, p.S*m) = (M:S*, P:S*).
      bool converged = false;
      for (unsigned int it = 0; it < 50; ++it)
        {
          m                             = unit(angle);
          const Tensor<1, 2> p          = unit(angle + 0.5 * numbers::PI);
          M                             = sym_dyad(m, m);
          const SymmetricTensor<2, 2> P = sym_dyad(m, p);
          law->evaluate(C + beta * M, S_star, D_star);
          const double r0 = M * S_star, r1 = P * S_star;
          if (std::hypot(r0, r1) <= tol)
            {
              converged = true;
              break;
            }
          const SymmetricTensor<2, 2> DM = D_star * M, DP = D_star * P;
          const double                J00 = 0.5 * (M * DM);
          const double                J01 = 2. * r1 + beta * (M * DP);
          const double                J10 = 0.5 * (P * DM);
          const double J11 = (sym_dyad(p, p) - M) * S_star + beta * (P * DP);
          const double det = J00 * J11 - J01 * J10;
          if (!(std::abs(det) > 0.))
            break;
          double d_beta  = -(J11 * r0 - J01 * r1) / det;
          double d_angle = -(-J10 * r0 + J00 * r1) / det;
          // Stay on beta >= 0.
          if (beta + d_beta < 0.)
            {
              const double f = 0.5 * beta / -d_beta;
              d_beta *= f;
              d_angle *= f;
            }
          beta += d_beta;
          angle += d_angle;
        }
      const Tensor<1, 2> p = unit(angle + 0.5 * numbers::PI);
      const double       t = p * (S_star * p);
      if (!converged || !(beta >= 0.) || !(t > 0.))
        {
          // Not a wrinkled state of this law: report failure through the
          // residual (not finite), which cuts the load step back.
          S_star = std::numeric_limits<double>::quiet_NaN()
                   * unit_symmetric_tensor<2>();
          state.kind = WrinklingState::wrinkled;
          return state;
        }
      state.kind              = WrinklingState::wrinkled;
      state.C_star            = C + beta * M;
      state.tension_direction = p;
      return state;
    }

    WrinklingState
    TensionFieldLaw::state(const SymmetricTensor<2, 2> &C) const
    {
      SymmetricTensor<2, 2> S0, S;
      SymmetricTensor<4, 2> D0, D;
      double                beta;
      Tensor<1, 2>          m;
      return solve(C, S0, D0, S, D, beta, m);
    }

    void
    TensionFieldLaw::evaluate(const SymmetricTensor<2, 2> &C,
                              SymmetricTensor<2, 2>       &S,
                              SymmetricTensor<4, 2>       &D) const
    {
      SymmetricTensor<2, 2> S0;
      SymmetricTensor<4, 2> D0;
      if (delta > 0.)
        {
          SymmetricTensor<2, 2> B;
          if (!smoothed(C, S0, D0, S, D, B))
            S = std::numeric_limits<double>::quiet_NaN()
                * unit_symmetric_tensor<2>();
          S += residual_stiffness * S0;
          D += residual_stiffness * D0;
          return;
        }
      double               beta;
      Tensor<1, 2>         m;
      const WrinklingState state = solve(C, S0, D0, S, D, beta, m);
      // beta > 0 at every wrinkled state that solve() accepts (beta = 0
      // only where it failed and S is not finite).
      if (state.kind == WrinklingState::wrinkled && beta > 0.)
        {
          // dS_r/dE = D* - [a_M/2, beta a_P] J^-1 [a_M; a_P], with
          // a_M = D*:M, a_P = D*:P, at r = 0 (doc/theory.md): symmetric.
          const Tensor<1, 2>         &p  = state.tension_direction;
          const SymmetricTensor<2, 2> M  = sym_dyad(m, m);
          const SymmetricTensor<2, 2> P  = sym_dyad(m, p);
          const SymmetricTensor<2, 2> aM = D * M, aP = D * P;
          const double                J00 = 0.5 * (M * aM);
          const double                J01 = beta * (M * aP);
          const double                J10 = 0.5 * (P * aM);
          const double                J11 = p * (S * p) + beta * (P * aP);
          const double                det = J00 * J11 - J01 * J10;
          const SymmetricTensor<2, 2> b0  = (J11 * aM - J01 * aP) / det;
          const SymmetricTensor<2, 2> b1  = (-J10 * aM + J00 * aP) / det;
          D -= 0.25 * (outer_product(aM, b0) + outer_product(b0, aM))
               + 0.5 * beta * (outer_product(aP, b1) + outer_product(b1, aP));
        }
      // The residual fraction of the plain law, evaluated once in solve().
      S += residual_stiffness * S0;
      D += residual_stiffness * D0;
    }

    double
    TensionFieldLaw::strain_energy(const SymmetricTensor<2, 2> &C) const
    {
      if (delta > 0.)
        {
          SymmetricTensor<2, 2> S0, S, B;
          SymmetricTensor<4, 2> D0, D;
          smoothed(C, S0, D0, S, D, B);
          return law->strain_energy(C + B) - delta * std::log(determinant(B))
                 - energy_offset + residual_stiffness * law->strain_energy(C);
        }
      return law->strain_energy(state(C).C_star)
             + residual_stiffness * law->strain_energy(C);
    }

    double
    TensionFieldLaw::thickness_stretch(const SymmetricTensor<2, 2> &C) const
    {
      return law->thickness_stretch(state(C).C_star);
    }
  } // namespace membrane
} // namespace pneuma
