#!/usr/bin/env python3
"""Write a LAMMPS data file of deformable polyhedra (3d MESOPHYLL cells), standard library only.

Each cell is an icosphere: an icosahedron whose faces are split into four `--level` times, its
vertices pushed onto a sphere of radius `--radius` (12, 42, 162, 642 vertices at levels 0-3).
Cells sit on a simple cubic lattice in a periodic cubic box. The topology is LAMMPS's own:

* every edge is one bond (type 1, bond_style dpoly3d/edge),
* every face one angle a b c, counter-clockwise seen from outside (type 1, angle_style zero),
* every edge one dihedral a b c d with faces (a, b, c) and (c, b, d) (type 1, dihedral_style
  dpoly3d/hinge).

Per-vertex state goes into a "Vertices" section (id sigma v0), per-edge state into the sections
"Edges" (id, then K partner IDs), "EdgeLengths" (id, K preferred lengths) and "EdgeAngles" (id,
K preferred bending angles): each edge on its lower-ID vertex, unused columns 0. Read with

    fix Vertices all property/atom d_sigma d_v0 ghost yes
    fix Edges all property/atom i2_edge 6 ghost yes
    fix EdgeLengths all property/atom d2_edge_l0 6 ghost yes
    fix EdgeAngles all property/atom d2_edge_theta0 6 ghost yes
    read_data cells3d.data fix Vertices NULL Vertices fix Edges NULL Edges &
              fix EdgeLengths NULL EdgeLengths fix EdgeAngles NULL EdgeAngles

Preferred lengths and angles are those of the written geometry (after `--jitter`); v0 is the
cell's volume unless `--v0` gives one; sigma is the mean edge length unless `--sigma` gives one.
The bending angle of an edge is the signed angle between the outward normals of its two faces,
positive where the surface is convex (doc/Howto_polyhedra.rst).
"""
import argparse
import math
import random


def icosphere(level):
    """Unit-sphere vertices and outward counter-clockwise faces of a subdivided icosahedron."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    raw = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
           (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    points = [normalized(p) for p in raw]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        midpoint = {}

        def middle(u, v):
            key = (min(u, v), max(u, v))
            if key not in midpoint:
                points.append(normalized([(points[u][d] + points[v][d]) / 2 for d in range(3)]))
                midpoint[key] = len(points) - 1
            return midpoint[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    faces = [f if outward(points, f) else (f[0], f[2], f[1]) for f in faces]
    return points, faces


def normalized(p):
    n = math.sqrt(sum(v * v for v in p))
    return tuple(v / n for v in p)


def sub(p, q):
    return tuple(p[d] - q[d] for d in range(3))


def cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def dot(p, q):
    return sum(p[d] * q[d] for d in range(3))


def outward(points, face):
    a, b, c = (points[k] for k in face)
    centre = tuple((a[d] + b[d] + c[d]) / 3 for d in range(3))
    return dot(cross(sub(b, a), sub(c, a)), centre) > 0.0


def volume(points, faces):
    return sum(dot(points[a], cross(points[b], points[c])) for a, b, c in faces) / 6.0


def bending_angle(xa, xb, xc, xd):
    """Signed angle between the outward normals of faces (a, b, c) and (c, b, d)."""
    na = cross(sub(xb, xa), sub(xc, xa))
    nb = cross(sub(xb, xc), sub(xd, xc))
    e = sub(xc, xb)
    length = math.sqrt(dot(e, e))
    return math.atan2(dot(cross(na, nb), e) / length, dot(na, nb))


def hinges(faces):
    """(a, b, c, d) for every edge b-c (b < c): faces (a, b, c) and (c, b, d)."""
    opposite = {}
    for f in faces:
        for k in range(3):
            opposite[(f[k], f[(k + 1) % 3])] = f[(k + 2) % 3]
    return [(opposite[(b, c)], b, c, opposite[(c, b)]) for (b, c) in opposite if b < c]


def build(args):
    rng = random.Random(args.seed)
    unit, faces = icosphere(args.level)
    side = math.ceil(round(args.cells ** (1.0 / 3.0), 9))
    spacing = args.spacing * 2.0 * args.radius
    box = args.box if args.box else side * spacing
    n = len(unit)
    cells = []
    for c in range(args.cells):
        centre = [((c // side ** d) % side + 0.5) * spacing + args.shift * box for d in range(3)]
        edge_length = args.radius * math.sqrt(dot(sub(unit[faces[0][0]], unit[faces[0][1]]),
                                                  sub(unit[faces[0][0]], unit[faces[0][1]])))
        points = [tuple(centre[d] + args.radius * p[d] + args.jitter * edge_length *
                        rng.uniform(-1.0, 1.0) for d in range(3)) for p in unit]
        cells.append(points)

    atoms, vertex_state, bonds, angles, dihedrals, edges = [], [], [], [], [], {}
    cell_hinges = hinges(faces)
    for c, points in enumerate(cells):
        first = c * n + 1
        v0 = args.v0 if args.v0 else volume(points, faces)
        lengths = []
        for a, b, cc, d in cell_hinges:
            length = math.sqrt(dot(sub(points[b], points[cc]), sub(points[b], points[cc])))
            theta = bending_angle(points[a], points[b], points[cc], points[d])
            edges.setdefault(first + b, []).append((first + cc, length, theta))
            lengths.append(length)
            bonds.append((first + b, first + cc))
            dihedrals.append((first + a, first + b, first + cc, first + d))
        sigma = args.sigma if args.sigma else sum(lengths) / len(lengths)
        for k, p in enumerate(points):
            image = [math.floor(p[d] / box) for d in range(3)]
            atoms.append((first + k, c + 1, *[p[d] - image[d] * box for d in range(3)], *image))
            vertex_state.append((first + k, sigma, v0))
        angles += [tuple(first + k for k in f) for f in faces]
    slots = max(len(v) for v in edges.values())
    if slots > args.edge_slots:
        raise SystemExit(f"a vertex owns {slots} edges, more than --edge-slots {args.edge_slots}")
    return box, atoms, vertex_state, bonds, angles, dihedrals, edges


def write(path, args, box, atoms, vertex_state, bonds, angles, dihedrals, edges):
    k = args.edge_slots
    with open(path, "w") as out:
        out.write(f"MESOPHYLL deformable polyhedra: {args.cells} icospheres of level {args.level}, "
                  f"radius {args.radius} (tools/make_cells3d.py)\n\n")
        out.write(f"{len(atoms)} atoms\n1 atom types\n{len(bonds)} bonds\n1 bond types\n"
                  f"{len(angles)} angles\n1 angle types\n{len(dihedrals)} dihedrals\n"
                  f"1 dihedral types\n\n")
        for d in "xyz":
            out.write(f"0 {box!r} {d}lo {d}hi\n")
        out.write("\nMasses\n\n1 1\n\nAtoms # molecular\n\n")
        for a in atoms:
            out.write(f"{a[0]} {a[1]} 1 {a[2]!r} {a[3]!r} {a[4]!r} {a[5]} {a[6]} {a[7]}\n")
        out.write("\nBonds\n\n")
        for n, b in enumerate(bonds, 1):
            out.write(f"{n} 1 {b[0]} {b[1]}\n")
        out.write("\nAngles\n\n")
        for n, a in enumerate(angles, 1):
            out.write(f"{n} 1 {a[0]} {a[1]} {a[2]}\n")
        out.write("\nDihedrals\n\n")
        for n, d in enumerate(dihedrals, 1):
            out.write(f"{n} 1 {d[0]} {d[1]} {d[2]} {d[3]}\n")
        out.write("\nVertices\n\n")
        for tag, sigma, v0 in vertex_state:
            out.write(f"{tag} {sigma!r} {v0!r}\n")
        # three sections, one per fix: a line of all three would outgrow read_data's 255
        # characters at 6 columns of full-precision numbers and be cut short silently
        owned = {}
        for tag, *_ in vertex_state:
            row = sorted(edges.get(tag, []))
            owned[tag] = row + [(0, 0.0, 0.0)] * (k - len(row))
        for section, column in (("Edges", 0), ("EdgeLengths", 1), ("EdgeAngles", 2)):
            out.write(f"\n{section}\n\n")
            for tag, row in owned.items():
                values = [str(e[0]) if column == 0 else repr(e[column]) for e in row]
                line = f"{tag} {' '.join(values)}"
                if len(line) > 255:
                    raise SystemExit(f"{section} line of vertex {tag} is {len(line)} characters, "
                                     "more than read_data reads (255): use fewer --edge-slots")
                out.write(line + "\n")

def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("--cells", type=int, default=1, help="number of cells (default 1)")
    parser.add_argument("--level", type=int, default=1,
                        help="subdivisions of the icosahedron: 0, 1, 2, 3 give 12, 42, 162, 642 "
                             "vertices (default 1)")
    parser.add_argument("--radius", type=float, default=1.0, help="cell radius (default 1)")
    parser.add_argument("--sigma", type=float, default=0.0,
                        help="vertex diameter (default: the cell's mean edge length)")
    parser.add_argument("--v0", type=float, default=0.0,
                        help="preferred volume of every cell (default: its own volume)")
    parser.add_argument("--spacing", type=float, default=1.2,
                        help="lattice spacing in cell diameters (default 1.2)")
    parser.add_argument("--box", type=float, default=0.0,
                        help="box length (default: lattice cells per side times the spacing)")
    parser.add_argument("--shift", type=float, default=0.0,
                        help="shift of every cell by this fraction of the box, so cells cross "
                             "the periodic boundary (default 0)")
    parser.add_argument("--jitter", type=float, default=0.0,
                        help="random displacement of each vertex coordinate, in edge lengths "
                             "(default 0); preferred values follow the displaced shape")
    parser.add_argument("--seed", type=int, default=1, help="seed of the jitter (default 1)")
    parser.add_argument("--edge-slots", type=int, default=6,
                        help="i2_edge/d2_edge_* columns per vertex (default 6)")
    args = parser.parse_args()
    if args.cells < 1 or args.level < 0 or args.radius <= 0.0 or args.spacing <= 0.0 \
            or args.v0 < 0.0 or args.sigma < 0.0 or args.box < 0.0 or args.edge_slots < 1:
        parser.error("--cells >= 1, --level >= 0, --radius and --spacing > 0, --v0, --sigma, "
                     "--box >= 0 and --edge-slots >= 1")
    box, *rest = build(args)
    if 2.0 * args.radius * (1.0 + args.jitter) >= box:
        parser.error(f"a cell of diameter {2 * args.radius} does not fit in the box {box}: "
                     "raise --spacing or --box")
    write(args.output, args, box, *rest)
    print(f"wrote {args.output}: {len(rest[0])} vertices in {args.cells} cells, box {box:.6g}")


if __name__ == "__main__":
    main()
