// Post-buckling of a column by arc length (Load stepping/Control =
// arc-length; doc/verification.md "Elastica"): a cantilever (solid beam,
// radius 5 mm, E = 200 GPa, nu = 0, L = 1 m, clamped at x = 0; Euler load
// P_cr = pi^2 E I/(4 L^2) = 242.2 N) under an end force that grows with
// the load factor t to P = 1.1 P_cr along the axis, with a lateral
// imperfection Q = P/100, on 64 elements (the bending strain stays below
// 0.8 %, where the element's hyperelastic section bends linearly; 32
// elements are 2.9e-3 and 6.8e-3 off). The path rises through the buckling
// load, every state stable, and the tip follows the elastica of an
// inextensible, shear-rigid rod under the inclined end load: EI theta'' = -Q
// cos(theta) - P sin(theta), theta(0) = 0, theta'(L) = 0, solved here by
// shooting (RK4, 2000 steps) for every converged state. Checked: the tip
// displacements within 0.5 % of the largest (the state at P = 1.1 P_cr:
// tip rotation 52 degrees, lateral deflection 0.53 L), the load factor
// rising along the path, no unstable state.

#include "elastica.h"
#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  const double E = 2e11, a = 0.005, L = 1., I = M_PI * a * a * a * a / 4.;
  const double P_cr = M_PI * M_PI * E * I / (4. * L * L), P_end = 1.1 * P_cr;

  const pneuma_test::Elastica elastica{E * I, L};
  using Tip = pneuma_test::Elastica::Tip;
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                               r = pneuma_test::run({
                                  {"Geometry/Type", "none"},
                                  {"Cables/Number of cables", "1"},
                                  {"Cables/Cable 1/Element", "solid beam"},
                                  {"Cables/Cable 1/polyline/Points", "0, 0, 0; 1, 0, 0"},
                                  {"Cables/Cable 1/Number of elements", "64"},
                                  {"Cables/Cable 1/Section semi-axes",
                                   pneuma_test::number(a) + ", " + pneuma_test::number(a)},
                                  {"Cables/Cable 1/solid beam/Section axis", "0, 0, 1"},
                                  {"Cables/Cable 1/Young's modulus", pneuma_test::number(E)},
                                  {"Cables/Cable 1/solid beam/Poisson's ratio", "0"},
                                  {"Cables/Cable 1/Start support", "fixed"},
                                  {"Cables/Cable 1/End forces", "true"},
                                  {"Cables/Cable 1/End force/Function expression",
                                   pneuma_test::number(-P_end) + " * t; " + pneuma_test::number(P_end / 100.)
                                     + " * t; 0"},
                                  {"Load stepping/Control", "arc-length"},
                                  {"Load stepping/Initial increment", "0.02"},
                                  {"Load stepping/Maximum increment", "0.05"},
                                  {"Stability/Check inertia", "true"},
  });
  const bool ok                              = pneuma_test::check_elastica_path(
    r, elastica, P_end, "cable1_end_u_x", "cable1_end_u_y");
  return ok ? 0 : 1;
}
