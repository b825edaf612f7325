// A faceted rigid sphere for tests/obstacle_mesh: radius 0.3 m about the
// origin, triangles of about 4 cm.
// gmsh -2 -format msh22 obstacle_sphere.geo -o obstacle_sphere.msh
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 0.3};
Mesh.MeshSizeMax = 0.04;
