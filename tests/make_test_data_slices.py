#!/usr/bin/env python3
"""Hand-made 3d cells whose volumes, surfaces and cross-sections are known exactly, for the tests
of compute dpoly3d/tissue and compute dpoly3d/slice; written by tools/make_cells3d.py's writer.

    make_test_data_slices.py MAKE_CELLS3D OUTDIR

cube.data          a cube of side 2 (12 triangles), centre (5, 5, 5), box 10
cube_tilted.data   the same cube turned by 30 degrees about x
octahedron.data    a regular octahedron of circumradius 1.5 (its equator at z = 5)
two_cubes.data     two cubes of side 2, 0.3 apart along x, vertex diameter 0.4
cup.data           a 4 x 4 x 2 block with a 2 x 2 well 1 deep in its top (centre (5, 5, 5)):
                   cut at z = 5.5 it is a 4 x 4 square with a 2 x 2 hole
"""
import importlib.util
import math
import sys
import types

spec = importlib.util.spec_from_file_location("make_cells3d", sys.argv[1])
cells3d = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cells3d)
outdir = sys.argv[2]
BOX = 10.0


def cube():
    points = [(x, y, z) for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)]
    index = {p: k for k, p in enumerate(points)}
    faces = []
    for axis in range(3):
        for side in (-1.0, 1.0):
            square = []
            for u, v in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3] = side, u, v
                square.append(index[tuple(p)])
            faces += [(square[0], square[1], square[2]), (square[0], square[2], square[3])]
    return points, faces


def octahedron(radius):
    points = [(radius, 0, 0), (-radius, 0, 0), (0, radius, 0), (0, -radius, 0), (0, 0, radius),
              (0, 0, -radius)]
    faces = [(a, b, c) for a in (0, 1) for b in (2, 3) for c in (4, 5)]
    return points, faces


def cup():
    """A 4 x 4 x 2 block (z from -1 to 1) with a 2 x 2 well from its top down to z = 0, faces
    ordered counter-clockwise from outside (not convex, so written out by hand below)."""
    def square(h, z):
        return [(-h, -h, z), (h, -h, z), (h, h, z), (-h, h, z)]
    points = square(2.0, -1.0) + square(2.0, 1.0) + square(1.0, 1.0) + square(1.0, 0.0)
    ob, ot, it, ib = (list(range(k, k + 4)) for k in (0, 4, 8, 12))
    quads = [ob[::-1], ib]                                    # bottom, bottom of the well
    for k in range(4):
        n = (k + 1) % 4
        quads += [(ob[k], ob[n], ot[n], ot[k]),              # outer wall
                  (ot[k], ot[n], it[n], it[k]),              # rim
                  (it[k], it[n], ib[n], ib[k])]              # wall of the well
    faces = []
    for q in quads:
        faces += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    return points, faces


def turned_about_x(points, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [(x, c * y - s * z, s * y + c * z) for x, y, z in points]


def write(name, shapes, sigma, convex=True):
    """shapes: (points around the origin, faces, centre) per cell; faces of a convex shape are
    turned outward here, others must come oriented"""
    atoms, vertex_state, bonds, angles, dihedrals, edges = [], [], [], [], [], {}
    first = 1
    for mol, (unit, faces, centre) in enumerate(shapes, 1):
        if convex:
            faces = [f if cells3d.outward(unit, f) else (f[0], f[2], f[1]) for f in faces]
        points = [tuple(p[d] + centre[d] for d in range(3)) for p in unit]
        v0 = cells3d.volume(points, faces)
        for a, b, c, d in cells3d.hinges(faces):
            length = math.dist(points[b], points[c])
            theta = cells3d.bending_angle(points[a], points[b], points[c], points[d])
            lo, hi = min(first + b, first + c), max(first + b, first + c)
            edges.setdefault(lo, []).append((hi, length, theta))
            bonds.append((first + b, first + c))
            dihedrals.append((first + a, first + b, first + c, first + d))
        for k, p in enumerate(points):
            image = [math.floor(p[d] / BOX) for d in range(3)]
            atoms.append((first + k, mol, *[p[d] - image[d] * BOX for d in range(3)], *image))
            vertex_state.append((first + k, sigma, v0))
        angles += [tuple(first + k for k in f) for f in faces]
        first += len(points)
    args = types.SimpleNamespace(cells=len(shapes), level=-1, radius=0.0, edge_slots=6)
    path = f"{outdir}/{name}"
    cells3d.write(path, args, BOX, atoms, vertex_state, bonds, angles, dihedrals, edges)
    with open(path) as f:
        lines = f.readlines()
    lines[0] = f"MESOPHYLL hand-made 3d cells: {name} (tests/make_test_data_slices.py)\n"
    with open(path, "w") as f:
        f.writelines(lines)


centre = (5.0, 5.0, 5.0)
write("cube.data", [(*cube(), centre)], 0.4)
write("cube_tilted.data", [(turned_about_x(cube()[0], 30.0), cube()[1], centre)], 0.4)
write("octahedron.data", [(*octahedron(1.5), centre)], 0.4)
write("two_cubes.data", [(*cube(), (3.85, 5.0, 5.0)), (*cube(), (6.15, 5.0, 5.0))], 0.4)
write("cup.data", [(*cup(), centre)], 0.4, convex=False)
print(f"wrote 5 data files to {outdir}")
