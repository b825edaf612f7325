// A slice of a tube of circumference 1 m (R = 1/(2 pi)) along x, 0.1 m
// long, lying on the ground z = 0: its axis at z = R + 0.5 mm, so that a
// 1 mm wall touches the ground along its bottom line.
// Structured quadrilaterals (32 around, 1 along), for the geotube test
// (tests/geotube): physical surface (= material id) 1; physical curves
// (= boundary ids) 0 the end at x = 0, 1 the end at x = 0.1.
// Regenerate: gmsh -2 geotube_slice.geo -o geotube_slice.msh
R = 1 / (2 * Pi); L = 0.1;
zc = R + 0.0005;
Point(1) = {0, 0, zc};
Point(2) = {0, R, zc};
Point(3) = {0, 0, zc + R};
Point(4) = {0, -R, zc};
Point(5) = {0, 0, zc - R};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Transfinite Curve{1:4} = 9;
surfaces[] = {}; ends1[] = {};
For i In {1:4}
  out[] = Extrude {L, 0, 0} { Curve{i}; Layers{1}; Recombine; };
  ends1[] += out[0];
  surfaces[] += out[1];
EndFor
Physical Surface(1) = {surfaces[]};
Physical Curve(0) = {1:4};
Physical Curve(1) = {ends1[]};
Mesh.MshFileVersion = 2.2;
