#pragma once

// The shell strip of tests/shell_bending, shell_roll_up and
// shell_strip_buckling: 1 m x 0.1 m, t = 1 cm, E = 1 GPa, nu = 0 (EI =
// E b t^3/12 without anticlastic bending), clamped at x = -1/2 (boundary
// 0, held in xyz and in rotation), its tip x = 1/2 (boundary 1) monitored.

#include "test_tools.h"

#include <string>

namespace pneuma_test
{
  inline Settings
  shell_strip(const unsigned int degree, const unsigned int refinements)
  {
    return {{"Geometry/Type", "rectangle"},
            {"Geometry/rectangle/Length", "1"},
            {"Geometry/rectangle/Width", "0.1"},
            {"Geometry/Global refinements", std::to_string(refinements)},
            {"Discretisation/Polynomial degree", std::to_string(degree)},
            {"Materials/Region 0/Thickness", "0.01"},
            {"Materials/Region 0/Bending", "shell"},
            {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus",
             "1e9"},
            {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0"},
            {"Bending/Clamped boundaries", "0"},
            {"Boundary conditions/Fixed boundaries", "0: xyz"},
            {"Output/Monitor points", "0.5, 0, 0"}};
  }
} // namespace pneuma_test
