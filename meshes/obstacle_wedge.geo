// A rigid wedge for tests/obstacle_mesh: a prism along y whose lower edge
// (a sharp ridge at x = 0.1, z = 0.005 m, split into four segments) and
// sloping faces press on a membrane below it.
// gmsh -2 -format msh22 obstacle_wedge.geo -o obstacle_wedge.msh
Point(1) = {0.1, -0.6, 0.005, 0.3};
Point(2) = {0.5, -0.6, 0.4, 0.3};
Point(3) = {-0.3, -0.6, 0.4, 0.3};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Extrude {0, 1.2, 0} { Surface{1}; Layers{4}; }
