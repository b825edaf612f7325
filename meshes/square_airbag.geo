// The square airbag of Contri & Schrefler (1988): two flat square sheets
// of diagonal 1.2 m (side 0.848528 m) seamed along their four edges; 4 x 4
// quadrilaterals per sheet. Physical surfaces 1 (top, normal +z) and 2
// (bottom, normal -z); the seam is physical curve 10.
// gmsh -2 -format msh22 square_airbag.geo -o square_airbag.msh
L = 0.848528;
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, L, 0}; Point(4) = {0, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {-4, -3, -2, -1};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4} = 5;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(10) = {1, 2, 3, 4};
