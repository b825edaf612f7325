// A sheet in shear, the tension-field core of Wong & Pellegrino's test
// (doc/verification.md "Shear panel"): a square membrane (side L = 1 m,
// H = 1 mm, E = 1 GPa, nu = 0.3) whose four edges follow the simple shear
// u = gamma (y + L/2) e_x (gamma = 1e-3), so the state is homogeneous and
// every reaction has a closed form.
// (a) tension field: the whole sheet wrinkles, the wrinkles' tension runs
//     at 45 degrees (atan of the top edge's reaction components), and the
//     top edge carries the diagonal-tension forces F_x = F_y = E H L
//     gamma / 4 (small strain), i.e. (1 + nu)/2 of the taut shear force;
//     the same forces exactly (to 1e-8) from the relaxed law at the
//     finite-strain metric C = F^T F of the simple shear;
// (b) without wrinkling: F_x = G H L shear and F_y = 0 (small strain).
// The per-boundary reactions are summary.json's boundary_<id>_reaction.

#include "test_tools.h"

#include <pneuma/membrane/tension_field.h>

#include <cmath>

namespace
{
  // shear: the engineering shear strain gamma.
  const double E = 1e9, nu = 0.3, H = 1e-3, L = 1., shear = 1e-3;

  pneuma_test::Settings
  panel(const bool wrinkling)
  {
    return {
      {"Geometry/Type", "square"},
      {"Geometry/square/Side length", "1"},
      {"Geometry/Global refinements", "3"},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Wrinkling", wrinkling ? "tension field" : "none"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"},
      {"Boundary conditions/Prescribed displacement boundaries", "0, 1, 2, 3"},
      {"Boundary conditions/Prescribed displacement/Function constants",
       "g=1e-3"},
      {"Boundary conditions/Prescribed displacement/Function expression",
       "g*(y+0.5)*t; 0; 0"},
      {"Load stepping/Stage end times", "1"},
      {"Load stepping/Initial increment", "0.5"}};
  }

  /// The top edge's force t L (S_12 a_1 + S_22 a_2) from the relaxed
  /// St. Venant-Kirchhoff law at the simple shear's metric.
  std::array<double, 2>
  exact_top_force()
  {
    dealii::ParameterHandler prm;
    auto all = pneuma::membrane::LawRegistry::instance().declare_all(prm);
    prm.enter_subsection("Saint Venant-Kirchhoff");
    prm.set("Young's modulus", "1e9");
    prm.set("Poisson's ratio", "0.3");
    prm.leave_subsection();
    const std::shared_ptr<const pneuma::membrane::ConstitutiveLaw> plain(
      pneuma::membrane::LawRegistry::instance()
        .take(all, prm, "Saint Venant-Kirchhoff", "Law", "Materials/Region 0")
        .release());
    const pneuma::membrane::TensionFieldLaw law(plain, 1e-6);
    dealii::SymmetricTensor<2, 2>           C, S;
    dealii::SymmetricTensor<4, 2>           D;
    C[0][0] = 1.;
    C[0][1] = shear;
    C[1][1] = 1. + shear * shear;
    law.evaluate(C, S, D);
    return {{H * L * (S[0][1] + shear * S[1][1]), H * L * S[1][1]}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  bool ok = true;

  // (a) tension field.
  {
    const auto   s     = pneuma_test::run(panel(true));
    const auto   top   = s.summary.get_vector("boundary_3_reaction");
    const double F     = E * H * L * shear / 4.;
    const double angle = std::atan2(top[1], top[0]) * 180. / M_PI;
    const auto   exact = exact_top_force();
    ok                 = pneuma_test::check("wrinkled area / L^2",
                            s.get("wrinkled_area") / (L * L),
                            1.,
                            1e-12)
         && ok;
    ok = pneuma_test::check("tension field: top edge F_x vs E H L gamma/4",
                            top[0],
                            F,
                            5e-3)
         && ok;
    ok = pneuma_test::check("tension field: top edge F_y vs E H L gamma/4",
                            top[1],
                            F,
                            5e-3)
         && ok;
    ok =
      pneuma_test::check("wrinkle tension angle [deg]", angle, 45., 1e-3) && ok;
    ok = pneuma_test::check("top edge F_x vs the relaxed law at C",
                            top[0],
                            exact[0],
                            1e-8)
         && ok;
    ok = pneuma_test::check("top edge F_y vs the relaxed law at C",
                            top[1],
                            exact[1],
                            1e-8)
         && ok;
  }

  // (b) taut: no wrinkling.
  {
    const auto   s   = pneuma_test::run(panel(false));
    const auto   top = s.summary.get_vector("boundary_3_reaction");
    const double G   = E / (2. * (1. + nu));
    ok               = pneuma_test::check("taut: top edge F_x vs G H L gamma",
                            top[0],
                            G * H * L * shear,
                            5e-3)
         && ok;
    const bool small = std::abs(top[1]) < 1e-2 * top[0];
    if (root)
      std::printf("taut: top edge |F_y| %s 1e-2 F_x %s\n",
                  small ? "<" : ">=",
                  small ? "PASS" : "FAIL");
    ok = ok && small;
  }

  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
