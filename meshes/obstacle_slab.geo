// A rigid slab for tests/obstacle_mesh: the box [-0.5, 0.9] x [-0.5, 0.5]
// x [0, 0.1] m (a loading plate of finite thickness), triangles.
// gmsh -2 -format msh22 obstacle_slab.geo -o obstacle_slab.msh
SetFactory("OpenCASCADE");
Box(1) = {-0.5, -0.5, 0, 1.4, 1, 0.1};
Mesh.MeshSizeMax = 0.25;
