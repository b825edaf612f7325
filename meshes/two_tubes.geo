// Two open cylinders (tubes) of radius 0.2 m and length 0.4 m along x,
// axes at z = +0.2155 and z = -0.2155 (3.1 cm between the surfaces),
// structured quadrilaterals (32 around, 1 along), for the membrane-to-membrane
// contact test (tests/surface_contact): physical surfaces (= material
// ids) 1 upper tube, 2 lower tube; physical curves (= boundary ids) 0 the
// ends at x = 0, 1 the ends at x = 0.4.
// Regenerate: gmsh -2 two_tubes.geo -o two_tubes.msh
R = 0.2; L = 0.4;
ends0[] = {}; ends1[] = {};
For k In {0:1}
  zc = 0.2155 * (1 - 2 * k);
  p0 = newp; Point(p0) = {0, 0, zc};
  Point(p0 + 1) = {0, R, zc};
  Point(p0 + 2) = {0, 0, zc + R};
  Point(p0 + 3) = {0, -R, zc};
  Point(p0 + 4) = {0, 0, zc - R};
  c0 = newl;
  Circle(c0) = {p0 + 1, p0, p0 + 2};
  Circle(c0 + 1) = {p0 + 2, p0, p0 + 3};
  Circle(c0 + 2) = {p0 + 3, p0, p0 + 4};
  Circle(c0 + 3) = {p0 + 4, p0, p0 + 1};
  Transfinite Curve{c0:c0 + 3} = 9;
  surfaces[] = {};
  For i In {0:3}
    out[] = Extrude {L, 0, 0} { Curve{c0 + i}; Layers{1}; Recombine; };
    ends1[] += out[0];
    surfaces[] += out[1];
    ends0[] += c0 + i;
  EndFor
  Physical Surface(k + 1) = {surfaces[]};
EndFor
Physical Curve(0) = {ends0[]};
Physical Curve(1) = {ends1[]};
Mesh.MshFileVersion = 2.2;
