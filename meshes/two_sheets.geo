// Two parallel unit squares 0.5 mm apart, closer than their half
// thicknesses (they press on each other), 4 x 4 quadrilaterals each, for
// the tangent checks of the membrane-to-membrane contact
// (tests/surface_contact): physical surfaces (= material ids) 1 the sheet
// at z = 0, 2 the sheet at z = 0.0005 (self-contact: both as one side).
// Regenerate: gmsh -2 two_sheets.geo -o two_sheets.msh
For k In {0:1}
  z = 0.0005 * k;
  p = newp;
  Point(p) = {0, 0, z}; Point(p + 1) = {1, 0, z};
  Point(p + 2) = {1, 1, z}; Point(p + 3) = {0, 1, z};
  l = newl;
  Line(l) = {p, p + 1}; Line(l + 1) = {p + 1, p + 2};
  Line(l + 2) = {p + 2, p + 3}; Line(l + 3) = {p + 3, p};
  Curve Loop(l + 4) = {l, l + 1, l + 2, l + 3};
  s = news;
  Plane Surface(s) = {l + 4};
  Transfinite Curve{l:l + 3} = 5;
  Transfinite Surface{s};
  Recombine Surface{s};
  sheets[k] = s;
EndFor
Physical Surface(1) = {sheets[0]};
Physical Surface(2) = {sheets[1]};
Mesh.MshFileVersion = 2.2;
