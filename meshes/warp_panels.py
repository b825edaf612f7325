#!/usr/bin/env python3
"""Write meshes/warp_panels.msh: a flat strip [0, 1] x [0, 0.25] m of 8 x 2
quadrilaterals (Gmsh 2.2 ASCII, physical surface 1, left edge physical
line 1, right edge 2) whose "warp" $ElementData view runs along x in the
left half and along y in the right half: two fabric panels seamed across
the strip (tests/gmsh_warp)."""
import os

nx, ny, lx, ly = 8, 2, 1.0, 0.25
nodes = [(j * (nx + 1) + i + 1, lx * i / nx, ly * j / ny)
         for j in range(ny + 1) for i in range(nx + 1)]
n = lambda i, j: j * (nx + 1) + i + 1
elements, warp = [], []
tag = 1
for j in range(ny):                       # left and right edges
    elements.append((tag, 1, 1, [n(0, j), n(0, j + 1)])); tag += 1
    elements.append((tag, 1, 2, [n(nx, j), n(nx, j + 1)])); tag += 1
for j in range(ny):
    for i in range(nx):
        elements.append((tag, 3, 1, [n(i, j), n(i + 1, j), n(i + 1, j + 1),
                                     n(i, j + 1)]))
        warp.append((tag, (1, 0, 0) if i < nx // 2 else (0, 1, 0)))
        tag += 1
out = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                   'warp_panels.msh')
with open(out, 'w') as f:
    f.write('$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n' % len(nodes))
    for t, x, y in nodes:
        f.write('%d %.17g %.17g 0\n' % (t, x, y))
    f.write('$EndNodes\n$Elements\n%d\n' % len(elements))
    for t, typ, phys, vs in elements:
        f.write('%d %d 2 %d %d %s\n' % (t, typ, phys, phys,
                                        ' '.join(map(str, vs))))
    f.write('$EndElements\n$ElementData\n1\n"warp"\n1\n0\n3\n0\n3\n%d\n'
            % len(warp))
    for t, v in warp:
        f.write('%d %g %g %g\n' % (t, *v))
    f.write('$EndElementData\n')
