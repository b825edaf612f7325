// The pinched cylinder with rigid end diaphragms of the shell obstacle
// course (MacNeal & Harder 1985; Belytschko et al. 1985): radius 300,
// length 600, an eighth of it: the axis along x, x from 0 (the mid-plane)
// to 300 (a diaphragm), the arc from the top (y = 0, z = 300) to the side
// (y = 300, z = 0). Physical surface 0 -> material id 0; the mid-plane
// edge x = 0 -> boundary id 1; the edge in y = 0 -> 2; the edge in
// z = 0 -> 3; the diaphragm x = 300 -> 4. Declare the region curved
// (Geometry/gmsh/Curved regions = 0: cylinder 0,0,0, 1,0,0).
// Regenerate: gmsh -2 -format msh22 pinched_cylinder.geo
R = 300;
L = 600;
n = 5;
Point(1) = {0, 0, 0};
Point(2) = {L/2, 0, 0};
Point(3) = {0, 0, R};
Point(4) = {0, R, 0};
Point(5) = {L/2, 0, R};
Point(6) = {L/2, R, 0};
Circle(1) = {3, 1, 4};
Line(2) = {4, 6};
Circle(3) = {6, 2, 5};
Line(4) = {5, 3};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(1) = {1};
Physical Curve(2) = {4};
Physical Curve(3) = {2};
Physical Curve(4) = {3};
Physical Surface(0) = {1};
