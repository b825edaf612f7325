// A 1 m x 1 m flat membrane in the plane z = 0, meshed with quadrilaterals.
// Physical surface 0 -> material id 0; physical curve 1 (all edges) ->
// boundary id 1. Regenerate: gmsh -2 -format msh2 square_plate.geo; the MSH 4.1
// copy read by tests/gmsh_square_v41: gmsh -2 -format msh41 square_plate.geo
// -o square_plate_v41.msh
L = 1.0;
n = 9;
Point(1) = {-L/2, -L/2, 0};
Point(2) = { L/2, -L/2, 0};
Point(3) = { L/2,  L/2, 0};
Point(4) = {-L/2,  L/2, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(1) = {1, 2, 3, 4};
Physical Surface(0) = {1};
