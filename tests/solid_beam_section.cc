// The section kernel of the solid-beam element (source paper section 3.1,
// include/pneuma/cables/solid_beam_section.h): energy per unit length of an
// elliptic section (a = 0.02, b = 0.01, E = 2e11), for St. Venant-Kirchhoff
// and neo-Hookean:
// - gradient and Hessian against central finite differences, on a straight
//   and on a curved, twisted reference, at a moderate general state;
// - zero energy and gradient under a rigid rotation (70 degrees about a
//   skew axis) and translation;
// - uniform axial stretch: the analytic energy and axial force;
// - the section rule integrates the prismatic St. Venant-Kirchhoff energy
//   exactly (default rule against a much finer one);
// - pure bending about both axes (nu = 0): w = E I k^2 / 2 and M = E I k;
//   with nu = 0.3 the Poisson-locking factor (1-nu)/((1+nu)(1-2nu));
// - torsion of a circular section: w = G J theta^2 / 2, T = G J theta;
// - the resultants against the gradient: f = dw/dx0',
//   m = a1 x dw/da1' + a2 x dw/da2'.

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <pneuma/cables/solid_beam_section.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

using namespace dealii;
using pneuma::cables::BeamLaw;
using pneuma::cables::BeamMaterial;
using pneuma::cables::SolidBeamSection;
using State = SolidBeamSection::State;

namespace
{
  bool ok = true;

  const double a = 0.02, b = 0.01, E = 2e11;

  std::string
  law_name(const BeamLaw law)
  {
    return law == BeamLaw::saint_venant_kirchhoff ? "SVK" : "neo-Hookean";
  }

  /// "name: reference r value v relative error e (tolerance t) PASS".
  void
  check(const std::string &name,
        const double       value,
        const double       reference,
        const double       tolerance)
  {
    const double error = (value - reference) / std::abs(reference);
    const bool   pass  = std::abs(error) <= tolerance && std::isfinite(value);
    std::printf("%s: reference %.6e value %.6e relative error %.1e "
                "(tolerance %.0e) %s\n",
                name.c_str(),
                reference,
                value,
                std::abs(error),
                tolerance,
                pass ? "PASS" : "FAIL");
    ok = ok && pass;
  }

  /// "name: e (tolerance t) PASS" for an error measure that should vanish.
  void
  check_small(const std::string &name, const double error, const double tol)
  {
    const bool pass = std::abs(error) <= tol && std::isfinite(error);
    std::printf("%s: %.1e (tolerance %.0e) %s\n",
                name.c_str(),
                std::abs(error),
                tol,
                pass ? "PASS" : "FAIL");
    ok = ok && pass;
  }

  Tensor<1, 3>
  vec(const double x, const double y, const double z)
  {
    Tensor<1, 3> v;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return v;
  }

  /// Deterministic "random" vector with entries in [-1, 1].
  Tensor<1, 3>
  pseudo_random(const unsigned int k)
  {
    return vec(std::sin(1.3 + 2.1 * k),
               std::sin(0.7 + 3.7 * k),
               std::sin(2.9 + 5.3 * k));
  }

  // Reference frame of the straight beam: tangent t along a skew
  // direction, section axes d1, d2 with d2 = t x d1.
  const Tensor<1, 3> t  = vec(1., 2., 2.) / 3.;
  const Tensor<1, 3> d1 = vec(2., -1., 0.) / std::sqrt(5.);
  const Tensor<1, 3> d2 = cross_product_3d(t, d1);

  /// Straight reference with semi-axes sa (along d1) and sb (along d2).
  State
  straight_reference(const double sa, const double sb)
  {
    return {{vec(0.3, -0.2, 0.5),
             t,
             sa * d1,
             Tensor<1, 3>(),
             sb * d2,
             Tensor<1, 3>()}};
  }

  /// Curved and twisted reference: the section frame rotates along S with
  /// the rate omega (twist 2/m, curvatures 1.5/m and -1/m).
  State
  curved_reference()
  {
    const Tensor<1, 3> omega = 2. * t + 1.5 * d1 - 1. * d2;
    State              Q     = straight_reference(a, b);
    Q[3]                     = cross_product_3d(omega, Q[2]);
    Q[5]                     = cross_product_3d(omega, Q[4]);
    return Q;
  }

  /// A moderate general current state near Q: stretch, shear, section
  /// change and bending/twist of about 1-3 % strain.
  State
  general_state(const State &Q)
  {
    State q;
    q[0] = Q[0] + 0.01 * pseudo_random(0);
    q[1] = 1.03 * Q[1] + 0.02 * pseudo_random(1);
    q[2] = 0.98 * Q[2] + 0.03 * a * pseudo_random(2);
    q[3] = Q[3] + 0.8 * a * pseudo_random(3);
    q[4] = 1.01 * Q[4] + 0.03 * b * pseudo_random(4);
    q[5] = Q[5] + 0.8 * b * pseudo_random(5);
    return q;
  }

  /// Scale of each block of q, for the normalised error measures.
  double
  scale(const unsigned int index)
  {
    const unsigned int block = index / 3;
    return block < 2 ? 1. : (block < 4 ? a : b);
  }

  double &
  entry(State &s, const unsigned int index)
  {
    return s[index / 3][index % 3];
  }

  /// Gradient and Hessian against central differences of the energy and
  /// of the gradient, in the variables q_i / scale_i.
  void
  check_finite_differences(const SolidBeamSection &section,
                           const State            &Q,
                           const State            &q,
                           const std::string      &name)
  {
    constexpr unsigned int     n = SolidBeamSection::n_variables;
    double                     w;
    SolidBeamSection::Gradient gradient, gradient_only;
    FullMatrix<double>         hessian;
    section.evaluate(Q, q, w, gradient, hessian);

    const double h       = 1e-6;
    double       g_error = 0., g_max = 0., h_error = 0., h_max = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double hj = h * scale(j);
        State        qp = q, qm = q;
        entry(qp, j) += hj;
        entry(qm, j) -= hj;
        const double fd =
          (section.energy(Q, qp) - section.energy(Q, qm)) / (2. * hj);
        g_error = std::max(g_error, std::abs(fd - gradient[j]) * scale(j));
        g_max   = std::max(g_max, std::abs(gradient[j]) * scale(j));

        double                     wp, wm;
        SolidBeamSection::Gradient gp, gm;
        section.evaluate(Q, qp, wp, gp);
        section.evaluate(Q, qm, wm, gm);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double fd_ij = (gp[i] - gm[i]) / (2. * hj);
            const double s     = scale(i) * scale(j);
            h_error = std::max(h_error, std::abs(fd_ij - hessian(i, j)) * s);
            h_max   = std::max(h_max, std::abs(hessian(i, j)) * s);
          }
      }
    check_small("gradient vs central FD, " + name + ": relative error",
                g_error / g_max,
                1e-6);
    check_small("Hessian vs central FD, " + name + ": relative error",
                h_error / h_max,
                1e-6);

    // Consistency of the entry points.
    double asymmetry = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        asymmetry = std::max(asymmetry,
                             std::abs(hessian(i, j) - hessian(j, i)) * scale(i)
                               * scale(j));
    section.evaluate(Q, q, w, gradient_only);
    double gradient_difference = 0.;
    for (unsigned int i = 0; i < n; ++i)
      gradient_difference =
        std::max(gradient_difference,
                 std::abs(gradient_only[i] - gradient[i]) * scale(i));
    check_small("Hessian asymmetry, " + name, asymmetry / h_max, 1e-14);
    check_small("energy() vs evaluate(), gradient-only vs full, " + name,
                std::abs(section.energy(Q, q) - w) / std::abs(w)
                  + gradient_difference / g_max,
                1e-13);

    // Resultants against the gradient.
    const auto   r = section.resultants(Q, q);
    Tensor<1, 3> dw_dx0p, dw_da1p, dw_da2p;
    for (unsigned int i = 0; i < 3; ++i)
      {
        dw_dx0p[i] = gradient[3 + i];
        dw_da1p[i] = gradient[9 + i];
        dw_da2p[i] = gradient[15 + i];
      }
    const Tensor<1, 3> m =
      cross_product_3d(q[2], dw_da1p) + cross_product_3d(q[4], dw_da2p);
    check_small("resultants, " + name
                  + ": |f - dw/dx0'|/|f| + |m - a_k x dw/da_k'|/|m|",
                (r.force - dw_dx0p).norm() / r.force.norm()
                  + (r.moment - m).norm() / m.norm(),
                1e-12);
  }

  /// Rotation by @p angle about the unit axis @p n (Rodrigues).
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &n, const double angle)
  {
    Tensor<2, 3> R;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = (i == j ? std::cos(angle) : 0.)
                  + (1. - std::cos(angle)) * n[i] * n[j];
    R[0][1] -= std::sin(angle) * n[2];
    R[1][0] += std::sin(angle) * n[2];
    R[0][2] += std::sin(angle) * n[1];
    R[2][0] -= std::sin(angle) * n[1];
    R[1][2] -= std::sin(angle) * n[0];
    R[2][1] += std::sin(angle) * n[0];
    return R;
  }

  void
  check_rigid_motion(const SolidBeamSection &section,
                     const State            &Q,
                     const std::string      &name)
  {
    const Tensor<2, 3> R =
      rotation(vec(1., -2., 3.) / std::sqrt(14.), 70. * numbers::PI / 180.);
    State q;
    q[0] = R * Q[0] + vec(0.5, -1., 2.);
    for (unsigned int k = 1; k < 6; ++k)
      q[k] = R * Q[k];
    double                     w;
    SolidBeamSection::Gradient gradient;
    FullMatrix<double>         hessian;
    section.evaluate(Q, q, w, gradient, hessian);
    double g = 0.;
    for (unsigned int i = 0; i < SolidBeamSection::n_variables; ++i)
      g = std::max(g, std::abs(gradient[i]) * scale(i));
    const double unit = E * numbers::PI * a * b;
    check_small("rigid motion, " + name + ": |w| / (E pi a b)",
                w / unit,
                1e-12);
    check_small("rigid motion, " + name + ": max |dw/dq scale| / (E pi a b)",
                g / unit,
                1e-12);
  }
} // namespace

int
main()
{
  for (const BeamLaw law :
       {BeamLaw::saint_venant_kirchhoff, BeamLaw::neo_hookean})
    {
      const std::string      name = law_name(law);
      const BeamMaterial     material{law, E, 0.3};
      const SolidBeamSection section(material);
      const double           lambda_L = material.lambda(), mu = material.mu();

      check_finite_differences(section,
                               straight_reference(a, b),
                               general_state(straight_reference(a, b)),
                               name + ", straight");
      check_finite_differences(section,
                               curved_reference(),
                               general_state(curved_reference()),
                               name + ", curved and twisted");
      check_rigid_motion(section,
                         straight_reference(a, b),
                         name + ", straight");
      check_rigid_motion(section, curved_reference(), name + ", curved");

      // Uniform axial stretch, unchanged section: F = diag(l, 1, 1) in the
      // frame (t, d1, d2).
      const double l    = 1.05;
      const State  Q    = straight_reference(a, b);
      State        q    = Q;
      q[1]              = l * Q[1];
      const double E11  = 0.5 * (l * l - 1.);
      const double area = numbers::PI * a * b;
      const double psi  = law == BeamLaw::saint_venant_kirchhoff
                            ? (0.5 * lambda_L + mu) * E11 * E11
                            : 0.5 * mu * (l * l - 1.) - mu * std::log(l)
                               + 0.5 * lambda_L * std::log(l) * std::log(l);
      const double P11  = law == BeamLaw::saint_venant_kirchhoff
                            ? l * (lambda_L + 2. * mu) * E11
                            : mu * (l - 1. / l) + lambda_L * std::log(l) / l;
      check("uniform stretch 1.05, " + name + ": w",
            section.energy(Q, q),
            psi * area,
            1e-12);
      check("uniform stretch 1.05, " + name + ": axial force N",
            section.resultants(Q, q).axial_force,
            P11 * area,
            1e-12);
    }

  // The default rule integrates the prismatic St. Venant-Kirchhoff energy
  // (a polynomial of degree 4 in z1, z2) exactly.
  {
    const BeamMaterial     material{BeamLaw::saint_venant_kirchhoff, E, 0.3};
    const SolidBeamSection coarse(material), fine(material, 8, 16);
    const State            Q = straight_reference(a, b);
    const State            q = general_state(Q);
    std::printf("section rule: %u points by default\n",
                static_cast<unsigned int>(coarse.quadrature().size()));
    check("prismatic SVK energy, default rule (3 x 6) vs (8 x 16)",
          coarse.energy(Q, q),
          fine.energy(Q, q),
          1e-13);
    // (3 x 5) is the smallest exact rule; one point fewer in r or theta is
    // not exact (the check above would detect a wrong rule).
    check("prismatic SVK energy, rule (3 x 5) vs (8 x 16)",
          SolidBeamSection(material, 3, 5).energy(Q, q),
          fine.energy(Q, q),
          1e-13);
    for (const auto &[n_r, n_theta] :
         {std::pair<unsigned int, unsigned int>{2, 6}, {3, 4}})
      {
        const double error =
          std::abs(SolidBeamSection(material, n_r, n_theta).energy(Q, q)
                     / fine.energy(Q, q)
                   - 1.);
        const bool pass = error > 1e-9;
        std::printf("prismatic SVK energy, rule (%u x %u), not exact: "
                    "relative error %.1e (expected > 1e-09) %s\n",
                    n_r,
                    n_theta,
                    error,
                    pass ? "PASS" : "FAIL");
        ok = ok && pass;
      }
  }

  // Pure bending, small curvature k with k b = k a / 2 = 1e-4: the section
  // frame rotates along S with the curvature vector -k d1 (about the a1
  // axis; a2' = -k b t) or +k d2 (about the a2 axis; a1' = -k a t).
  for (const BeamLaw law :
       {BeamLaw::saint_venant_kirchhoff, BeamLaw::neo_hookean})
    for (const double nu : {0., 0.3})
      {
        const BeamMaterial     material{law, E, nu};
        const SolidBeamSection section(material);
        const double           k  = 1e-4 / b;
        const double           I1 = numbers::PI * a * b * b * b / 4.;
        const double           I2 = numbers::PI * a * a * a * b / 4.;
        const State            Q  = straight_reference(a, b);
        const double      locking = (1. - nu) / ((1. + nu) * (1. - 2. * nu));
        const std::string suffix =
          ", " + law_name(law) + ", nu = " + (nu == 0. ? "0" : "0.3");

        State q       = Q;
        q[5]          = -k * b * t;
        const auto r1 = section.resultants(Q, q);
        if (nu == 0.)
          {
            check("bending about a1" + suffix + ": w",
                  section.energy(Q, q),
                  0.5 * E * I1 * k * k,
                  1e-3);
            check("bending about a1" + suffix + ": M1",
                  r1.bending_moment_1,
                  -E * I1 * k,
                  1e-3);
          }
        else
          check("bending about a1" + suffix
                  + ", unchanged section: w / (E I k^2 / 2) = locking factor",
                section.energy(Q, q) / (0.5 * E * I1 * k * k),
                locking,
                1e-3);

        q             = Q;
        q[3]          = -k * a * t;
        const auto r2 = section.resultants(Q, q);
        if (nu == 0.)
          {
            check("bending about a2" + suffix + ": w",
                  section.energy(Q, q),
                  0.5 * E * I2 * k * k,
                  1e-3);
            check("bending about a2" + suffix + ": M2",
                  r2.bending_moment_2,
                  E * I2 * k,
                  1e-3);
          }
      }

  // Torsion of a circular section (a = b = R), twist rate theta with
  // theta R = 1e-4: a_k' = theta t x a_k.
  for (const BeamLaw law :
       {BeamLaw::saint_venant_kirchhoff, BeamLaw::neo_hookean})
    {
      const BeamMaterial     material{law, E, 0.3};
      const SolidBeamSection section(material);
      const double           R = 0.01, theta = 1e-4 / R;
      const double GJ = material.mu() * numbers::PI * R * R * R * R / 2.;
      const State  Q  = straight_reference(R, R);
      State        q  = Q;
      q[3]            = theta * cross_product_3d(t, Q[2]);
      q[5]            = theta * cross_product_3d(t, Q[4]);
      check("torsion, circular, " + law_name(law) + ", nu = 0.3: w",
            section.energy(Q, q),
            0.5 * GJ * theta * theta,
            1e-3);
      check("torsion, circular, " + law_name(law) + ", nu = 0.3: T",
            section.resultants(Q, q).torsion_moment,
            GJ * theta,
            1e-3);
    }

  std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
  return ok ? 0 : 1;
}
