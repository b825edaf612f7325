// A cable for the Gmsh import test: the V of length 12 over the span 10
// (V7 catenary), 16 line elements, physical curve 1.
Point(1) = {0, 0, 0};
Point(2) = {5, 0, -3.3166247903554};
Point(3) = {10, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Transfinite Curve{1, 2} = 9;
Physical Curve(1) = {1, 2};
