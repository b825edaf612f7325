// Conformance of every registered membrane law (membrane/constitutive_law.h,
// Registry<ConstitutiveLaw>), with its default constants, taken from the
// registry so that a new law is tested without naming it here:
// - the second Piola-Kirchhoff stress against central differences of the
//   strain energy (S = 2 dW/dC) and the tangent against central
//   differences of the stress (D = dS/dE), for the plain law and for the
//   law wrapped by tension field theory (membrane/tension_field.h, exact
//   and smoothed), at strains in its taut, wrinkled and slack states;
// - the wrinkling state of each strain as expected (taut biaxial stretch,
//   wrinkled stretch with lateral compression, slack biaxial compression);
// - the stress-free reference: S = 0, W = 0, thickness stretch 1 at C = I;
// - a positive initial shear modulus, a positive thickness stretch, and
//   a symmetric positive tangent at the reference;
// - the stress alone (ConstitutiveLaw::stress, an explicit step's) is
//   bit for bit the stress evaluated with the tangent.
// Each check prints the largest relative error and its tolerance.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/tension_field.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;
using namespace pneuma::membrane;

namespace
{
  /// Every registered law with its default constants.
  std::vector<std::pair<std::string, std::shared_ptr<ConstitutiveLaw>>>
  all_laws()
  {
    ParameterHandler prm;
    auto             all = LawRegistry::instance().declare_all(prm);
    std::vector<std::pair<std::string, std::shared_ptr<ConstitutiveLaw>>> laws;
    for (const auto &name :
         Utilities::split_string_list(LawRegistry::instance().names(), '|'))
      laws.emplace_back(name,
                        std::shared_ptr<ConstitutiveLaw>(
                          LawRegistry::instance()
                            .take(all, prm, name, "Law", "Materials/Region 0")
                            .release()));
    return laws;
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

  /// Largest relative differences of the tangent and of the stress from
  /// central differences (of S and of the energy) at C.
  std::pair<double, double>
  differences(const ConstitutiveLaw &law, const SymmetricTensor<2, 2> &C)
  {
    SymmetricTensor<2, 2> S;
    SymmetricTensor<4, 2> D;
    law.evaluate(C, S, D);
    const double h = 1e-6;
    const double D_scale =
      std::max(D.norm(), 1e-3 * law.initial_shear_modulus());
    const double S_scale =
      std::max(S.norm(), 1e-6 * law.initial_shear_modulus());
    double tangent = 0., stress = 0.;
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
          SymmetricTensor<2, 2> dE;
          dE[k][l] = 1.;
          tangent =
            std::max(tangent, ((Sp - Sm) / (2. * h) - D * dE).norm() / D_scale);
          // S_kl = 2 dW/dC_kl (dW = S : dC / 2 counts C_kl and C_lk).
          const double dW =
            (law.strain_energy(C + dC) - law.strain_energy(C - dC)) / (4. * h);
          stress =
            std::max(stress,
                     std::abs((k == l ? 2. * dW : dW) - S[k][l]) / S_scale);
        }
    return {tangent, stress};
  }

  bool
  check(const std::string &what, const double value, const double tolerance)
  {
    const bool ok = std::isfinite(value) && value <= tolerance;
    std::printf("  %-52s %s\n",
                what.c_str(),
                ok ? "below tolerance" : "ABOVE TOLERANCE (FAIL)");
    if (!ok)
      std::printf("    value %.3e, tolerance %.1e\n", value, tolerance);
    return ok;
  }
} // namespace

int
main()
{
  bool        ok       = true;
  const char *states[] = {"taut", "wrinkled", "slack"};
  const auto  laws     = all_laws();
  std::printf("%zu registered laws\n", laws.size());
  ok = laws.size() >= 5 && ok;
  struct Case
  {
    const char           *name;
    SymmetricTensor<2, 2> C;
    WrinklingState::Kind  state;
  };
  const std::vector<Case> cases = {
    {"biaxial stretch", metric(1.10, 1.05, 0.3), WrinklingState::taut},
    {"stretch, lateral compression",
     metric(1.12, 0.90, 0.5),
     WrinklingState::wrinkled},
    {"biaxial compression", metric(0.98, 0.95, 0.2), WrinklingState::slack}};
  for (const auto &[name, law] : laws)
    {
      std::printf("%s\n", name.c_str());
      // The stress-free reference.
      const SymmetricTensor<2, 2> I = unit_symmetric_tensor<2>();
      SymmetricTensor<2, 2>       S;
      SymmetricTensor<4, 2>       D;
      law->evaluate(I, S, D);
      const double mu = law->initial_shear_modulus();
      ok = check("initial shear modulus > 0", mu > 0. ? 0. : 1., 0.) && ok;
      ok = check("S = 0 at C = I", S.norm() / mu, 1e-12) && ok;
      ok = check("W = 0 at C = I", std::abs(law->strain_energy(I)) / mu, 1e-12)
           && ok;
      ok = check("thickness stretch 1 at C = I",
                 std::abs(law->thickness_stretch(I) - 1.),
                 1e-12)
           && ok;
      // D at the reference: symmetric (major) and positive on E.
      double asymmetry = 0., smallest = 1e300;
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int l = k; l < 2; ++l)
          {
            SymmetricTensor<2, 2> a;
            a[k][l]  = 1.;
            smallest = std::min(smallest, a * (D * a) / mu);
            for (unsigned int m = 0; m < 2; ++m)
              for (unsigned int n = m; n < 2; ++n)
                {
                  SymmetricTensor<2, 2> b;
                  b[m][n] = 1.;
                  asymmetry =
                    std::max(asymmetry,
                             std::abs(a * (D * b) - b * (D * a)) / D.norm());
                }
          }
      ok = check("tangent at C = I symmetric", asymmetry, 1e-12) && ok;
      ok =
        check("tangent at C = I positive", smallest > 0. ? 0. : 1., 0.) && ok;
      const auto            plain = std::shared_ptr<const ConstitutiveLaw>(law);
      const TensionFieldLaw smoothed(plain, 1e-6);
      const TensionFieldLaw pure(plain, 0.);
      for (const auto &c : cases)
        {
          const auto state = pure.state(c.C);
          std::printf(" %s: %s\n", c.name, states[state.kind]);
          if (state.kind != c.state)
            {
              std::printf("  expected %s (FAIL)\n", states[c.state]);
              ok = false;
            }
          ok = check("thickness stretch > 0",
                     law->thickness_stretch(c.C) > 0. ? 0. : 1.,
                     0.)
               && ok;
          const std::vector<std::pair<std::string, const ConstitutiveLaw *>>
            forms = {{"plain law", law.get()},
                     {"tension field, exact", &pure},
                     {"tension field, smoothed 1e-6", &smoothed}};
          for (const auto &[form, l] : forms)
            {
              const auto [tangent, stress] = differences(*l, c.C);
              ok =
                check(form + ": tangent vs differences", tangent, 2e-6) && ok;
              ok = check(form + ": stress vs energy differences", stress, 2e-6)
                   && ok;
              // The stress alone (an explicit step's) is the same number.
              SymmetricTensor<2, 2> S, S_alone;
              SymmetricTensor<4, 2> D;
              l->evaluate(c.C, S, D);
              l->stress(c.C, S_alone);
              ok = check(form + ": stress alone = with tangent",
                         (S_alone - S).norm(),
                         0.)
                   && ok;
            }
        }
    }
  std::printf("%s\n", ok ? "PASSED" : "FAILED");
  return ok ? 0 : 1;
}
