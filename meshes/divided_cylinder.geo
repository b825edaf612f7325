// Divided cylinder: closed circular cylinder along x (radius R = 0.25 m,
// 0 <= x <= 1 m) with an internal flat divider disc at x = 0.5 that splits
// the volume into two chambers. Conforming 2D-in-3D mesh of quadrilaterals
// only (built-in kernel, transfinite + recombine; every surface is built from
// shared points and curves, so the hull, divider and caps share their nodes
// along the circles). Discs are O-grids: a square in the middle and four
// curved patches.
//
// Physical surfaces (= material ids):
//   0  hull, 0 < x < 0.5        (chamber A = {0, 3, 2})
//   1  hull, 0.5 < x < 1        (chamber B = {1, 4, 2})
//   2  divider disc at x = 0.5  (shared by both chambers)
//   3  end cap disc at x = 0
//   4  end cap disc at x = 1
// The circle at x = 0.5 is a non-manifold edge (2 hull cells + 1 divider cell).
//
// Regenerate (default n = 10: 40 cells around, 13 per half length, 1940 cells):
//   gmsh -2 -format msh22 divided_cylinder.geo -o divided_cylinder.msh
// Other densities: gmsh -2 -format msh22 -setnumber n 8 divided_cylinder.geo -o ...

DefineConstant[ n = {10, Min 2, Max 200, Step 1,
                     Name "Parameters/n (cells per quarter circle)"} ];

R = 0.25;          // radius
L = 1.0;           // length
rs = 0.55 * R;     // distance of the O-grid square corners from the axis
nr = Ceil(n / 2);  // cells from the square to the circle (spokes)
// cells along each half length, chosen for roughly square hull cells
nx = Ceil((L / 2) / (2 * Pi * R / (4 * n)));

xs[] = {0, L / 2, L};

// ---- cross sections s = 0, 1, 2 at x = xs[s] -----------------------------
// points 10s+1: centre, 10s+2..5: circle at 45, 135, 225, 315 degrees (y-z
// plane), 10s+6..9: corners of the inner square in the same directions.
// curves 100s+1..4: arcs, 100s+5..8: spokes (square corner -> circle),
// 100s+9..12: square edges. Surfaces 100s+1..4: curved patches, 100s+5: square.
For s In {0 : 2}
  x = xs[s];
  Point(10 * s + 1) = {x, 0, 0};
  For i In {0 : 3}
    a = Pi / 4 + i * Pi / 2;
    Point(10 * s + 2 + i) = {x, R * Cos(a), R * Sin(a)};
    Point(10 * s + 6 + i) = {x, rs * Cos(a), rs * Sin(a)};
  EndFor
  For i In {0 : 3}
    j = (i + 1) % 4;
    Circle(100 * s + 1 + i) = {10 * s + 2 + i, 10 * s + 1, 10 * s + 2 + j};
    Line(100 * s + 5 + i) = {10 * s + 6 + i, 10 * s + 2 + i};
    Line(100 * s + 9 + i) = {10 * s + 6 + i, 10 * s + 6 + j};
  EndFor
  For i In {0 : 3}
    j = (i + 1) % 4;
    Curve Loop(100 * s + 1 + i) = {100 * s + 9 + i, 100 * s + 5 + j,
                                   -(100 * s + 1 + i), -(100 * s + 5 + i)};
    Plane Surface(100 * s + 1 + i) = {100 * s + 1 + i};
  EndFor
  Curve Loop(100 * s + 5) = {100 * s + 9 : 100 * s + 12};
  Plane Surface(100 * s + 5) = {100 * s + 5};
  Transfinite Curve{100 * s + 1 : 100 * s + 4, 100 * s + 9 : 100 * s + 12} = n + 1;
  Transfinite Curve{100 * s + 5 : 100 * s + 8} = nr + 1;
EndFor

// ---- hull between sections s and s + 1 -----------------------------------
// axial lines 1000 + 10s + 1..4 from circle point i of section s to section
// s + 1; hull patches 1000 + 10s + 1..4.
For s In {0 : 1}
  For i In {0 : 3}
    Line(1000 + 10 * s + 1 + i) = {10 * s + 2 + i, 10 * (s + 1) + 2 + i};
  EndFor
  Transfinite Curve{1000 + 10 * s + 1 : 1000 + 10 * s + 4} = nx + 1;
  For i In {0 : 3}
    j = (i + 1) % 4;
    Curve Loop(1000 + 10 * s + 1 + i) = {100 * s + 1 + i, 1000 + 10 * s + 1 + j,
                                         -(100 * (s + 1) + 1 + i),
                                         -(1000 + 10 * s + 1 + i)};
    Surface(1000 + 10 * s + 1 + i) = {1000 + 10 * s + 1 + i};
  EndFor
EndFor

Transfinite Surface{:};
Recombine Surface{:};

Physical Surface(0) = {1001 : 1004};  // hull_A
Physical Surface(1) = {1011 : 1014};  // hull_B
Physical Surface(2) = {101 : 105};  // divider
Physical Surface(3) = {1 : 5};  // cap_x0
Physical Surface(4) = {201 : 205};  // cap_x1
