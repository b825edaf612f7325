// Waterbeam of the paper: L = 2 m along x.
//   chamber 1: circular cylinder, radius 0.23 m, axis = x axis, split by a
//              flat vertical divider membrane in the plane y = 0
//              (z = -0.23 .. 0.23, full length) into halves 1a (y < 0) and
//              1b (y > 0);
//   chamber 2: small cylinder, radius 0.03 m, axis (x, 0, 0.26), touching
//              chamber 1 along the seam line y = 0, z = 0.23.
// Flat end plates at x = 0 and x = 2. Conforming 2D-in-3D mesh of
// quadrilaterals only (built-in kernel, transfinite + recombine; all surfaces
// are built from the shared points/curves of the cross sections at x = 0 and
// x = L and shared axial lines). Caps: half O-grids for 1a and 1b (half
// square on the divider + 3 curved patches), full O-grid for chamber 2.
//
// Physical surfaces (= material ids):
//   0  hull of 1a (y < 0)         chamber 1a = {0, 2, 4, 7}
//   1  hull of 1b (y > 0)         chamber 1b = {1, 2, 5, 8}
//   2  divider (y = 0)            chamber 2  = {3, 6, 9}
//   3  hull of chamber 2
//   4  cap of 1a at x = 0,  5  cap of 1b at x = 0,  6  cap of chamber 2 at x = 0
//   7  cap of 1a at x = 2,  8  cap of 1b at x = 2,  9  cap of chamber 2 at x = 2
// Non-manifold edges: the seam line (hulls 1a, 1b, 2 and divider: 4 cells),
// the divider's bottom line (hulls 1a, 1b and divider: 3 cells) and the
// divider's end lines at x = 0, 2 (divider and caps 1a, 1b: 3 cells).
//
// Regenerate (default n = 6: 48 cells around chamber 1, 16 around chamber 2,
// 24 along x, 2352 cells):
//   gmsh -2 -format msh22 waterbeam.geo -o waterbeam.msh
// Other densities: gmsh -2 -format msh22 -setnumber n 8 waterbeam.geo -o ...

DefineConstant[ n = {6, Min 2, Max 100, Step 1,
                     Name "Parameters/n (cells per 45 degrees of chamber 1)"} ];

L  = 2.0;            // length
R  = 0.23;           // radius of chamber 1
r  = 0.03;           // radius of chamber 2
zs = R + r;          // height of the axis of chamber 2
h  = 0.55 * R / Sqrt(2);  // half side of the inner square of the big O-grid
rs = 0.55 * r;       // corners of the inner diamond of the small disc
m  = Ceil(2 * n / 3);  // cells per quarter circle of chamber 2
mr = Ceil(m / 2);      // cells from the diamond to the small circle
nr = Ceil(n / 2);      // cells from the inner square to the big circle
nx = 4 * n;            // cells along x (all surfaces)

xs[] = {0, L};

// ---- cross sections s = 0 (x = 0) and s = 1 (x = L) --------------------
// Point, curve and cap surface ids 100s + k.
For s In {0 : 1}
  x = xs[s];
  P = 100 * s;
  Point(P + 1) = {x, 0, 0};     // O: centre of chamber 1
  Point(P + 2) = {x, 0, R};     // T: seam point (top of divider)
  Point(P + 3) = {x, 0, -R};    // B: bottom of divider
  Point(P + 4) = {x, 0, h};     // D1, D2: inner square corners on the divider
  Point(P + 5) = {x, 0, -h};
  // divider end lines B -> D2 -> D1 -> T
  Line(P + 1) = {P + 3, P + 5};
  Line(P + 2) = {P + 5, P + 4};
  Line(P + 3) = {P + 4, P + 2};

  // half O-grids: side 0 = half 1a (y < 0), side 1 = half 1b (y > 0)
  For side In {0 : 1}
    sg = 2 * side - 1;
    A = P + 6 + 4 * side;       // A: circle at 45 deg, A+1: at 135 deg from +z
    Point(A) = {x, sg * R * Sin(Pi / 4), R * Cos(Pi / 4)};
    Point(A + 1) = {x, sg * R * Sin(3 * Pi / 4), R * Cos(3 * Pi / 4)};
    Point(A + 2) = {x, sg * h, h};              // E1, E2: inner square corners
    Point(A + 3) = {x, sg * h, -h};
    Q = P + 10 * side;          // curves Q+4..Q+11 (side a: 4..11, b: 14..21)
    Circle(Q + 4) = {P + 2, P + 1, A};          // T  -> A1
    Circle(Q + 5) = {A, P + 1, A + 1};          // A1 -> A2
    Circle(Q + 6) = {A + 1, P + 1, P + 3};      // A2 -> B
    Line(Q + 7) = {P + 4, A + 2};               // D1 -> E1
    Line(Q + 8) = {P + 5, A + 3};               // D2 -> E2
    Line(Q + 9) = {A + 2, A + 3};               // E1 -> E2
    Line(Q + 10) = {A + 2, A};                  // E1 -> A1
    Line(Q + 11) = {A + 3, A + 1};              // E2 -> A2
    F = P + 4 * side;           // cap surfaces F+1..F+4 (side a: 1..4, b: 5..8)
    Curve Loop(F + 1) = {Q + 4, -(Q + 10), -(Q + 7), P + 3};
    Plane Surface(F + 1) = {F + 1};             // T, A1, E1, D1
    Curve Loop(F + 2) = {Q + 5, -(Q + 11), -(Q + 9), Q + 10};
    Plane Surface(F + 2) = {F + 2};             // A1, A2, E2, E1
    Curve Loop(F + 3) = {Q + 6, P + 1, Q + 8, Q + 11};
    Plane Surface(F + 3) = {F + 3};             // A2, B, D2, E2
    Curve Loop(F + 4) = {Q + 7, Q + 9, -(Q + 8), P + 2};
    Plane Surface(F + 4) = {F + 4};             // D1, E1, E2, D2
    Transfinite Curve{Q + 4, Q + 6, Q + 7, Q + 8} = n + 1;
    Transfinite Curve{Q + 5, Q + 9} = 2 * n + 1;
    Transfinite Curve{Q + 10, Q + 11} = nr + 1;
  EndFor
  Transfinite Curve{P + 1, P + 3} = nr + 1;
  Transfinite Curve{P + 2} = 2 * n + 1;

  // O-grid of chamber 2: circle points T, 21, 22, 23 (bottom, +y, top, -y),
  // diamond corners 24..27; arcs 30..33, spokes 34..37, diamond edges 38..41;
  // surfaces 9..12 (curved patches) and 13 (diamond).
  Point(P + 20) = {x, 0, zs};                   // S: centre of chamber 2
  Point(P + 21) = {x,  r, zs};
  Point(P + 22) = {x,  0, zs + r};
  Point(P + 23) = {x, -r, zs};
  Point(P + 24) = {x,  0, zs - rs};
  Point(P + 25) = {x,  rs, zs};
  Point(P + 26) = {x,  0, zs + rs};
  Point(P + 27) = {x, -rs, zs};
  sp[] = {P + 2, P + 21, P + 22, P + 23};
  For i In {0 : 3}
    j = (i + 1) % 4;
    Circle(P + 30 + i) = {sp[i], P + 20, sp[j]};
    Line(P + 34 + i) = {P + 24 + i, sp[i]};
    Line(P + 38 + i) = {P + 24 + i, P + 24 + j};
  EndFor
  For i In {0 : 3}
    j = (i + 1) % 4;
    Curve Loop(P + 9 + i) = {P + 38 + i, P + 34 + j, -(P + 30 + i), -(P + 34 + i)};
    Plane Surface(P + 9 + i) = {P + 9 + i};
  EndFor
  Curve Loop(P + 13) = {P + 38 : P + 41};
  Plane Surface(P + 13) = {P + 13};
  Transfinite Curve{P + 30 : P + 33, P + 38 : P + 41} = m + 1;
  Transfinite Curve{P + 34 : P + 37} = mr + 1;
EndFor

// ---- axial lines 1000 + k from point k (x = 0) to point 100 + k (x = L) -----
ax[] = {2, 3, 4, 5, 6, 7, 10, 11, 21, 22, 23};
For i In {0 : #ax[] - 1}
  Line(1000 + ax[i]) = {ax[i], 100 + ax[i]};
  Transfinite Curve{1000 + ax[i]} = nx + 1;
EndFor

// ---- surfaces along x: id 2000 + k for the section curve k ----------------
// (curve, start point, end point) of the section curves at x = 0
sc[] = {1, 3, 5,    2, 5, 4,    3, 4, 2,                      // divider
        4, 2, 6,    5, 6, 7,    6, 7, 3,                      // hull 1a
        14, 2, 10,  15, 10, 11, 16, 11, 3,                    // hull 1b
        30, 2, 21,  31, 21, 22, 32, 22, 23, 33, 23, 2};       // hull 2
For i In {0 : #sc[] / 3 - 1}
  k = sc[3 * i]; p = sc[3 * i + 1]; q = sc[3 * i + 2];
  Curve Loop(2000 + k) = {k, 1000 + q, -(100 + k), -(1000 + p)};
  If (k <= 3)
    Plane Surface(2000 + k) = {2000 + k};
  Else
    Surface(2000 + k) = {2000 + k};
  EndIf
EndFor

Transfinite Surface{:};
Recombine Surface{:};

Physical Surface(0) = {2004 : 2006};   // hull of 1a (y < 0)
Physical Surface(1) = {2014 : 2016};   // hull of 1b (y > 0)
Physical Surface(2) = {2001 : 2003};   // divider (y = 0)
Physical Surface(3) = {2030 : 2033};   // hull of chamber 2
Physical Surface(4) = {1 : 4};         // cap of 1a at x = 0
Physical Surface(5) = {5 : 8};         // cap of 1b at x = 0
Physical Surface(6) = {9 : 13};        // cap of chamber 2 at x = 0
Physical Surface(7) = {101 : 104};     // cap of 1a at x = L
Physical Surface(8) = {105 : 108};     // cap of 1b at x = L
Physical Surface(9) = {109 : 113};     // cap of chamber 2 at x = L
