// The V5 tank (doc/verification.md), shared by tests/v5_tank and
// tests/liquid_level: a rigid vertical cylinder, radius 0.5 m, with a
// clamped circular membrane bottom (E h = 1e6 N/m, nu = 0.3, St.
// Venant-Kirchhoff, Q2 on 3 refinements), an open chamber of water
// (rho = 1000 kg/m^3) under gravity along -z, monitor 0 at the centre.
// The caller adds how it is filled and where the output goes.
#pragma once

#include "test_tools.h"

namespace pneuma_test
{
  inline Settings
  v5_tank(const Settings &filling, const std::string &directory)
  {
    Settings s = {
      {"Geometry/Type", "disc"},
      {"Geometry/disc/Radius", "0.5"},
      {"Geometry/Global refinements", "3"},
      {"Discretisation/Polynomial degree", "2"},
      {"Materials/Region 0/Law", "Saint Venant-Kirchhoff"},
      {"Materials/Region 0/Thickness", "1e-3"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus", "1e9"},
      {"Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio", "0.3"},
      {"Boundary conditions/Fixed boundaries", "0: xyz"},
      {"Chambers/Number of chambers", "1"},
      {"Chambers/Chamber 1/Regions", "-0"},
      {"Chambers/Chamber 1/Open", "true"},
      {"Chambers/Chamber 1/Filling", "liquid"},
      {"Chambers/Chamber 1/Liquid/Density", "1000"},
      {"Chambers/Gravity", "0, 0, -9.81"},
      {"Load stepping/Initial increment", "0.25"},
      {"Output/Directory", directory},
      {"Output/Monitor points", "0,0,0"}};
    s.insert(s.end(), filling.begin(), filling.end());
    return s;
  }
} // namespace pneuma_test
