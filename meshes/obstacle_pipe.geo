// A rigid pipe for tests/obstacle_mesh: a closed prism of N = 32 flat
// faces along x (from -0.1 to 0.5 m) whose vertices lie at the angles
// 2 pi k / 32 of the tube's nodes in the y-z plane, inscribed radius
// 0.2025 m; capped at both ends (closed: its normals are turned out).
// gmsh -2 -format msh22 obstacle_pipe.geo -o obstacle_pipe.msh
N = 32;
r = 0.2025 / Cos(Pi / N);
For k In {0 : N - 1}
  Point(k + 1) = {-0.1, r * Cos(2 * Pi * k / N), r * Sin(2 * Pi * k / N), 0.1};
EndFor
For k In {0 : N - 1}
  Line(k + 1) = {k + 1, (k + 1) % N + 1};
EndFor
Curve Loop(1) = {1 : N};
Plane Surface(1) = {1};
Extrude {0.6, 0, 0} { Surface{1}; Layers{1}; Recombine; }
