// Two unit spheres (OpenCASCADE), centres (0,0,0) and (3,0,0), meshed with
// quadrilaterals only (Frontal-Delaunay, recombined and subdivided), for
// the connected-balloons stability test (tests/stability_two_balloons).
// Physical surfaces (= material ids): 0 sphere A, 1 sphere B.
// Regenerate: gmsh -2 two_spheres.geo -o two_spheres.msh
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Sphere(2) = {3, 0, 0, 1};
Physical Surface(0) = {1};
Physical Surface(1) = {2};
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.SubdivisionAlgorithm = 1;
Mesh.MeshSizeMax = 0.35;
Mesh.MshFileVersion = 2.2;
