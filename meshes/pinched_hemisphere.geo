// The pinched hemisphere with an 18 degree hole of the shell obstacle
// course (MacNeal & Harder 1985): a quarter of the hemisphere of radius 10
// about the origin, x >= 0, y >= 0, from the equator z = 0 up to the hole's
// rim at 18 degrees from the pole. Physical surface 0 -> material id 0;
// the meridian in the plane y = 0 -> boundary id 1; the one in x = 0 ->
// boundary id 2; the equator -> 3; the hole's rim -> 4. Declare the region
// curved (Geometry/gmsh/Curved regions = 0: sphere 0,0,0).
// Regenerate: gmsh -2 -format msh22 pinched_hemisphere.geo
R = 10;
h = 18 * Pi / 180;
n = 5;
Point(1) = {0, 0, 0};
Point(2) = {R, 0, 0};
Point(3) = {0, R, 0};
Point(4) = {R*Sin(h), 0, R*Cos(h)};
Point(5) = {0, R*Sin(h), R*Cos(h)};
Point(6) = {0, 0, R*Cos(h)};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 5};
Circle(3) = {5, 6, 4};
Circle(4) = {4, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1} In Sphere {1};
Transfinite Curve{1, 2, 3, 4} = n;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(1) = {4};
Physical Curve(2) = {2};
Physical Curve(3) = {1};
Physical Curve(4) = {3};
Physical Surface(0) = {1};
