// The Scordelis-Lo roof of the shell obstacle course (MacNeal & Harder
// 1985): a cylindrical shell of radius 25 about the x axis, length 50
// (x from -25 to 25), spanning 40 degrees either side of the crown
// (z up). Physical surface 0 -> material id 0; the curved ends
// (diaphragms) -> boundary id 1; the straight free edges -> boundary id 2.
// Declare the region curved (Geometry/gmsh/Curved regions = 0: cylinder
// 0,0,0, 1,0,0). Regenerate: gmsh -2 -format msh22 scordelis_lo.geo
R = 25;
L = 50;
a = 40 * Pi / 180;
n = 5;
Point(1) = {-L/2, -R*Sin(a), R*Cos(a)};
Point(2) = {-L/2,  R*Sin(a), R*Cos(a)};
Point(3) = { L/2,  R*Sin(a), R*Cos(a)};
Point(4) = { L/2, -R*Sin(a), R*Cos(a)};
Point(5) = {-L/2, 0, 0};
Point(6) = { L/2, 0, 0};
Circle(1) = {1, 5, 2};
Line(2) = {2, 3};
Circle(3) = {3, 6, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(1) = {1, 3};
Physical Curve(2) = {2, 4};
Physical Surface(0) = {1};
