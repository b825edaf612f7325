// A slice of a tube of radius R = 0.2 m along x, L = 0.05 m long, its axis
// the x axis: structured quadrilaterals, 4 n around (n per quarter, default
// 24: 96 around, 3.75 degrees each), one along, for the plane-strain
// self-contact test (tests/surface_self_contact: the tube pinched between
// two rollers until its top meets its bottom). Physical surface (= material
// id) 0; physical curves (= boundary ids) 0 the end at x = 0, 1 the end at
// x = L.
// Regenerate: gmsh -2 -format msh22 tube_slice.geo -o tube_slice.msh
DefineConstant[ n = {24, Min 2, Max 200, Step 1, Name "cells per quarter"} ];
R = 0.2; L = 0.05;
Point(1) = {0, 0, 0};
Point(2) = {0, R, 0};
Point(3) = {0, 0, R};
Point(4) = {0, -R, 0};
Point(5) = {0, 0, -R};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Transfinite Curve{1:4} = n + 1;
surfaces[] = {}; ends1[] = {};
For i In {1:4}
  out[] = Extrude {L, 0, 0} { Curve{i}; Layers{1}; Recombine; };
  ends1[] += out[0];
  surfaces[] += out[1];
EndFor
Physical Surface(0) = {surfaces[]};
Physical Curve(0) = {1:4};
Physical Curve(1) = {ends1[]};
Mesh.MshFileVersion = 2.2;
