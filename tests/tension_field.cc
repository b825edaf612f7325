// The tension field law (membrane/tension_field.h) at the level of one
// point, for every membrane law:
// - the state (taut, wrinkled, slack) of strains chosen in each;
// - the tangent dS/dE against central differences of the stress, and the
//   stress against central differences of the relaxed energy (S = 2
//   dW/dC), in every state;
// - exact uniaxial tension where wrinkled: St. Venant-Kirchhoff
//   S = E E_pp p x p along the major principal stretch, neo-Hookean
//   S_pp = mu (1 - lambda^-3), and for every isotropic law a tension
//   direction along the major eigenvector of C (a rotated strain and a
//   simple shear);
// - the smoothed relaxed energy ("Wrinkling smoothing" zeta): in every
//   state its tangent and stress against differences, its stress within
//   O(zeta^2) of the exact relaxed stress (the error falls fourfold when
//   zeta is halved), and a tangent that is continuous across the
//   taut-wrinkled and wrinkled-slack borders, where the exact one jumps.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/tension_field.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

using namespace dealii;
using namespace pneuma::membrane;

namespace
{
  std::shared_ptr<ConstitutiveLaw>
  make_law(const std::string &name, const std::string &young = "1e6")
  {
    ParameterHandler prm;
    auto             all = LawRegistry::instance().declare_all(prm);
    prm.enter_subsection("Saint Venant-Kirchhoff");
    prm.set("Young's modulus", young);
    prm.set("Poisson's ratio", "0.3");
    prm.leave_subsection();
    prm.enter_subsection("neo-Hookean");
    prm.set("Shear modulus", "4e5");
    prm.leave_subsection();
    prm.enter_subsection("Mooney-Rivlin");
    prm.set("C10", "1.5e5");
    prm.set("C01", "5e4");
    prm.leave_subsection();
    prm.enter_subsection("orthotropic");
    prm.set("Warp modulus", "1e6");
    prm.set("Fill modulus", "5e5");
    prm.set("Poisson's ratio", "0.3");
    prm.set("Shear modulus", "1e4");
    prm.leave_subsection();
    prm.enter_subsection("Gent");
    prm.set("Shear modulus", "4e5");
    prm.set("Limiting extensibility", "20");
    prm.leave_subsection();
    return std::shared_ptr<ConstitutiveLaw>(
      LawRegistry::instance()
        .take(all, prm, name, "Law", "Materials/Region 0")
        .release());
  }

  /// R diag(l1^2, l2^2) R^T with R the rotation by @p angle.
  SymmetricTensor<2, 2>
  metric(const double l1, const double l2, const double angle)
  {
    const double          c = std::cos(angle), s = std::sin(angle);
    SymmetricTensor<2, 2> C;
    C[0][0] = l1 * l1 * c * c + l2 * l2 * s * s;
    C[1][1] = l1 * l1 * s * s + l2 * l2 * c * c;
    C[0][1] = (l1 * l1 - l2 * l2) * c * s;
    return C;
  }

  /// Largest relative difference of the tangent and of the stress from
  /// central differences (of S and of the energy) at C.
  std::pair<double, double>
  finite_difference_errors(const TensionFieldLaw       &law,
                           const SymmetricTensor<2, 2> &C)
  {
    SymmetricTensor<2, 2> S;
    SymmetricTensor<4, 2> D;
    law.evaluate(C, S, D);
    const double h             = 1e-6;
    double       tangent_error = 0., stress_error = 0.;
    const double D_scale =
      std::max(D.norm(), 1e-3 * law.initial_shear_modulus());
    const double S_scale =
      std::max(S.norm(), 1e-6 * law.initial_shear_modulus());
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int l = k; l < 2; ++l)
        {
          // dE_kl = h (both off-diagonal entries), i.e. dC_kl = 2h.
          SymmetricTensor<2, 2> dC;
          dC[k][l] = 2. * h;
          SymmetricTensor<2, 2> Sp, Sm;
          SymmetricTensor<4, 2> Dp, Dm;
          law.evaluate(C + dC, Sp, Dp);
          law.evaluate(C - dC, Sm, Dm);
          const SymmetricTensor<2, 2> fd = (Sp - Sm) / (2. * h);
          SymmetricTensor<2, 2>       dE;
          dE[k][l] = 1.;
          tangent_error =
            std::max(tangent_error, (fd - D * dE).norm() / D_scale);
          // S_kl = 2 dW/dC_kl (dW = S : dC / 2 counts C_kl and C_lk).
          const double dW =
            (law.strain_energy(C + dC) - law.strain_energy(C - dC)) / (4. * h);
          const double S_fd = (k == l) ? 2. * dW : dW;
          stress_error =
            std::max(stress_error, std::abs(S_fd - S[k][l]) / S_scale);
        }
    return {tangent_error, stress_error};
  }

  bool
  report(const char *what, const double value, const double tolerance)
  {
    const bool ok = std::isfinite(value) && value <= tolerance;
    std::printf("  %-46s %s\n",
                what,
                ok ? "below tolerance" : "ABOVE TOLERANCE (FAIL)");
    if (!ok)
      std::printf("    value %.3e, tolerance %.1e\n", value, tolerance);
    return ok;
  }
} // namespace

int
main()
{
  bool        ok           = true;
  const char *state_name[] = {"taut", "wrinkled", "slack"};

  struct Case
  {
    const char           *name;
    SymmetricTensor<2, 2> C;
    WrinklingState::Kind  expected;
  };
  SymmetricTensor<2, 2> shear;
  shear[0][0]        = 1.;
  shear[0][1]        = 0.08;
  shear[1][1]        = 1. + 0.08 * 0.08;
  const Case cases[] = {
    {"biaxial stretch", metric(1.10, 1.05, 0.3), WrinklingState::taut},
    {"stretch, lateral compression",
     metric(1.10, 0.93, 0.5),
     WrinklingState::wrinkled},
    {"small stretch, strong compression",
     metric(1.02, 0.8, -0.4),
     WrinklingState::wrinkled},
    {"simple shear 0.08", shear, WrinklingState::wrinkled},
    {"biaxial compression", metric(0.98, 0.95, 0.2), WrinklingState::slack}};

  for (const std::string name : {"Saint Venant-Kirchhoff",
                                 "neo-Hookean",
                                 "Mooney-Rivlin",
                                 "Gent",
                                 "orthotropic"})
    {
      std::printf("%s\n", name.c_str());
      const auto            plain = make_law(name);
      const TensionFieldLaw relaxed(plain, 1e-6);
      const TensionFieldLaw pure(plain, 0.);
      for (const auto &c : cases)
        {
          const auto state = pure.state(c.C);
          std::printf(" %s: %s\n", c.name, state_name[state.kind]);
          // The fabric's low shear modulus keeps a simple shear taut: the
          // fill stretch (C_22 = 1 + 0.08^2) outweighs the shear stress.
          const auto expected = (name == "orthotropic" && c.C == shear)
                                  ? WrinklingState::taut
                                  : c.expected;
          if (state.kind != expected)
            {
              std::printf("  expected %s (FAIL)\n", state_name[expected]);
              ok = false;
            }
          for (const TensionFieldLaw *law : {&relaxed, &pure})
            {
              const auto [t, s] = finite_difference_errors(*law, c.C);
              const std::string eps =
                law == &pure ? " (eps = 0)" : " (eps = 1e-6)";
              ok =
                report(("tangent vs differences" + eps).c_str(), t, 2e-6) && ok;
              ok =
                report(("stress vs energy differences" + eps).c_str(), s, 2e-6)
                && ok;
            }
          if (state.kind != WrinklingState::wrinkled)
            continue;
          // Uniaxial tension: S = t p x p, no stress across the wrinkles.
          {
            SymmetricTensor<2, 2> S;
            SymmetricTensor<4, 2> D;
            pure.evaluate(c.C, S, D);
            const Tensor<1, 2>   &p = state.tension_direction;
            SymmetricTensor<2, 2> uni;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = i; j < 2; ++j)
                uni[i][j] = (p * (S * p)) * p[i] * p[j];
            ok = report("stress uniaxial along p, |S - (p.S p) p x p|/|S|",
                        (S - uni).norm() / S.norm(),
                        1e-12)
                 && ok;
          }
          if (name == "orthotropic")
            continue;
          // Isotropic law: the tension along the major eigenvector of C.
          const auto   eig = eigenvectors(c.C);
          const double align =
            std::abs(eig[0].second * state.tension_direction);
          ok = report("tension along the major stretch (1 - |cos|)",
                      1. - align,
                      1e-12)
               && ok;
          // Uniaxial: S = s p x p with the closed form of s.
          SymmetricTensor<2, 2> S;
          SymmetricTensor<4, 2> D;
          pure.evaluate(c.C, S, D);
          const Tensor<1, 2> p   = state.tension_direction;
          const double       l2  = eig[0].first; // lambda^2
          double             s   = p * (S * p);
          double             ref = s;
          if (name == "Saint Venant-Kirchhoff")
            ref = 1e6 * 0.5 * (l2 - 1.);
          else if (name == "neo-Hookean")
            ref = 4e5 * (1. - std::pow(l2, -1.5));
          SymmetricTensor<2, 2> uniaxial;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = i; j < 2; ++j)
              uniaxial[i][j] = ref * p[i] * p[j];
          if (name == "Saint Venant-Kirchhoff" || name == "neo-Hookean")
            {
              std::printf("  uniaxial stress: reference %.10e, value %.10e\n",
                          ref,
                          s);
              ok = report("relative error of S (closed form)",
                          (S - uniaxial).norm() / std::abs(ref),
                          1e-12)
                   && ok;
            }
        }
    }

  // The smoothed relaxed energy: every law, every state.
  std::printf(
    "smoothed relaxed energy (zeta = 1e-3; orders from 1e-4, 5e-5)\n");
  for (const std::string name : {"Saint Venant-Kirchhoff",
                                 "neo-Hookean",
                                 "Mooney-Rivlin",
                                 "Gent",
                                 "orthotropic"})
    {
      const auto            plain = make_law(name);
      const TensionFieldLaw pure(plain, 0.);
      const TensionFieldLaw coarse(plain, 0., 1e-3), fine(plain, 0., 5e-4);
      const TensionFieldLaw small(plain, 0., 1e-4), smaller(plain, 0., 5e-5);
      double                tangent = 0., stress = 0., order = 10.;
      for (const auto &c : cases)
        {
          const auto [t, s] = finite_difference_errors(coarse, c.C);
          tangent           = std::max(tangent, t);
          stress            = std::max(stress, s);
          SymmetricTensor<2, 2> S, S1, S2;
          SymmetricTensor<4, 2> D;
          pure.evaluate(c.C, S, D);
          small.evaluate(c.C, S1, D);
          smaller.evaluate(c.C, S2, D);
          const double e1 = (S1 - S).norm(), e2 = (S2 - S).norm();
          order = std::min(order, std::log2(e1 / e2));
        }
      std::printf(" %s: smallest order of the stress error in zeta %.3f\n",
                  name.c_str(),
                  order);
      // Differences of step 1e-6 across a smoothing width of 1e-3 carry a
      // truncation error of about (1e-6/1e-3)^2 relative.
      ok = report("tangent vs differences, every state", tangent, 5e-6) && ok;
      ok =
        report("stress vs energy differences, every state", stress, 5e-6) && ok;
      // The fabric's shear modulus (a hundredth of its warp modulus)
      // delays the asymptotic range: 1.6 from (2e-4, 1e-4), 1.84 here.
      ok = report("order of the stress error in zeta (2 - order)",
                  std::max(2. - order, 0.),
                  name == "orthotropic" ? 0.2 : 0.02)
           && ok;
      // Across the borders, in steps of 1e-6 in a stretch over +-2e-3: the
      // taut-wrinkled one along lambda_2 at lambda_1 = 1.05 (found by
      // bisection on the exact state), and the wrinkled-slack one along
      // lambda_1 at lambda_2 = 0.97 (at lambda_1 = 1). The largest change
      // of the tangent per step, relative to the modulus.
      double taut = 1.05, wrinkled = 0.8;
      for (unsigned int i = 0; i < 60; ++i)
        {
          const double mid = 0.5 * (taut + wrinkled);
          (pure.state(metric(1.05, mid, 0.2)).kind == WrinklingState::taut
             ? taut
             : wrinkled)   = mid;
        }
      const auto largest_jump = [&](const TensionFieldLaw &law,
                                    const bool             slack_border) {
        double                jump = 0.;
        SymmetricTensor<4, 2> D_last;
        SymmetricTensor<2, 2> S;
        for (unsigned int i = 0; i <= 4000; ++i)
          {
            const double          x = 2e-3 - 1e-6 * i;
            SymmetricTensor<4, 2> D;
            law.evaluate(slack_border ? metric(1. + x, 0.97, 0.2)
                                      : metric(1.05, taut + x, 0.2),
                         S,
                         D);
            if (i > 0)
              jump = std::max(jump, (D - D_last).norm());
            D_last = D;
          }
        // Relative to the stiffest direct modulus at C = I.
        SymmetricTensor<4, 2> D0;
        plain->evaluate(unit_symmetric_tensor<2>(), S, D0);
        return jump / std::max(D0[0][0][0][0], D0[1][1][1][1]);
      };
      for (const bool slack_border : {false, true})
        {
          const double exact  = largest_jump(pure, slack_border),
                       smooth = largest_jump(fine, slack_border);
          std::printf("  %s border: largest tangent change per 1e-6 step, "
                      "exact %.3e, smoothed %.3e (of the stiffest "
                      "modulus)\n",
                      slack_border ? "wrinkled-slack" : "taut-wrinkled",
                      exact,
                      smooth);
          ok =
            report("smoothed tangent continuous (change < 3e-3)", smooth, 3e-3)
            && ok;
        }
    }

  // The inner Newton of the smoothing at the airbeam's wall (E = 7.6 GPa,
  // zeta = 1e-5) on a grid of stretches 0.9..1.1 and eight angles: taut,
  // wrinkled (nearly rank-one B, condition up to 1e8) and slack states
  // all give finite stresses and tangents.
  {
    const auto            wall = make_law("Saint Venant-Kirchhoff", "7.6e9");
    const TensionFieldLaw smoothed(wall, 1e-6, 1e-5);
    unsigned int          failures = 0, states = 0;
    for (int i = -10; i <= 10; ++i)
      for (int j = -10; j <= 10; ++j)
        for (unsigned int k = 0; k < 8; ++k, ++states)
          {
            SymmetricTensor<2, 2> S;
            SymmetricTensor<4, 2> D;
            smoothed.evaluate(metric(1. + 0.01 * i, 1. + 0.01 * j, 0.4 * k),
                              S,
                              D);
            if (!std::isfinite(S.norm()) || !std::isfinite(D.norm()))
              ++failures;
          }
    std::printf("smoothed wall law on %u states of +-10 %% stretch: %u "
                "failures\n",
                states,
                failures);
    ok = ok && failures == 0;
  }

  // The same law within 1e-12 .. 1e-4 of its reference state (the first
  // steps of a dynamic relaxation from the unstressed mesh): wrinkled
  // states with a wrinkle strain beta far below zeta, whose barrier start
  // once had a nearly singular B and no finite stress.
  {
    const auto            wall = make_law("Saint Venant-Kirchhoff", "7.6e9");
    const TensionFieldLaw smoothed(wall, 1e-6, 1e-5);
    unsigned int          failures = 0, states = 0;
    for (const double e : {1e-12, 1e-10, 1e-8, 1e-6, 1e-4})
      for (int i = -2; i <= 2; ++i)
        for (int j = -2; j <= 2; ++j)
          for (unsigned int k = 0; k < 8; ++k, ++states)
            {
              SymmetricTensor<2, 2> C = metric(1. + e * i, 1. + e * j, 0.4 * k);
              C[0][1] += e * (k % 3);
              SymmetricTensor<2, 2> S;
              SymmetricTensor<4, 2> D;
              smoothed.evaluate(C, S, D);
              if (!std::isfinite(S.norm()) || !std::isfinite(D.norm()))
                ++failures;
            }
    std::printf("smoothed wall law on %u states within 1e-12..1e-4 of "
                "its reference: %u failures\n",
                states,
                failures);
    ok = ok && failures == 0;
  }
  return ok ? 0 : 1;
}
