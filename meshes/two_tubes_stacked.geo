// Two open cylinders (tubes) of radius 0.2 m and length 0.4 m along x,
// stacked: axes at z = +0.200498 and z = -0.200498, so that with walls of
// 1 mm the two faces overlap by 4 micrometres along the line where the
// tubes touch (the contact holds each tube from the first iteration on,
// no support needed). Structured quadrilaterals (32 around, 1 along), for
// the two tubes at different pressures (tests/surface_contact_pressures):
// physical surfaces (= material ids) 1 upper tube, 2 lower tube; physical
// curves (= boundary ids) 0 and 1 the upper tube's ends at x = 0 and
// x = 0.4, 2 and 3 the lower tube's (its axial reaction gives its hoop
// force in plane strain).
// Regenerate: gmsh -2 two_tubes_stacked.geo -o two_tubes_stacked.msh
R = 0.2; L = 0.4;
For k In {0:1}
  zc = 0.200498 * (1 - 2 * k);
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
  surfaces[] = {}; ends0[] = {}; ends1[] = {};
  For i In {0:3}
    out[] = Extrude {L, 0, 0} { Curve{c0 + i}; Layers{1}; Recombine; };
    ends1[] += out[0];
    surfaces[] += out[1];
    ends0[] += c0 + i;
  EndFor
  Physical Surface(k + 1) = {surfaces[]};
  Physical Curve(2 * k) = {ends0[]};
  Physical Curve(2 * k + 1) = {ends1[]};
EndFor
Mesh.MshFileVersion = 2.2;
