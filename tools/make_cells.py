#!/usr/bin/env python3
"""Write a LAMMPS data file of deformable-polygon cells (MESOPHYLL), standard library only.

Each cell is a regular n-gon of area a0 (vertices counter-clockwise), on a square lattice in a
periodic square box. Per-vertex state goes into a "Vertices" section (id sigma l0 theta0 a0),
read with:

    fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes
    read_data cells.data fix Vertices NULL Vertices

Preferred values follow the paper's initial cells (doc/Howto_mesophyll.rst, section "The initial
tissue"): perimeter p0 from the shape parameter calA0 = p0^2/(4 pi a0), given relative to the
regular n-gon's own value; l0 = p0/n; sigma = l0; theta0 = 2 pi/n (the regular polygon's turning
angle).
Vertices are wrapped into the box with image flags that keep every ring whole.
"""
import argparse
import math
import random


def polygon_state(n, a0, calA0_relative):
    regular = n * math.tan(math.pi / n) / math.pi
    p0 = math.sqrt(4.0 * math.pi * a0 * calA0_relative * regular)
    l0 = p0 / n
    return l0, l0, 2.0 * math.pi / n


def build(args):
    rng = random.Random(args.seed)
    side = math.ceil(math.sqrt(args.cells))
    radius = math.sqrt(2.0 * args.a0 / (args.vertices * math.sin(2.0 * math.pi / args.vertices)))
    spacing = args.spacing * 2.0 * radius
    box = side * spacing
    l0, sigma, theta0 = polygon_state(args.vertices, args.a0, args.calA0)

    atoms, bonds, angles, state = [], [], [], []
    for c in range(args.cells):
        cx = (c % side + 0.5) * spacing + args.shift * box
        cy = (c // side + 0.5) * spacing + args.shift * box
        phase = rng.uniform(0.0, 2.0 * math.pi) if args.seed else 0.0
        first = len(atoms) + 1
        n = args.vertices
        for k in range(n):
            phi = phase + 2.0 * math.pi * k / n
            jitter = 1.0 + args.jitter * rng.uniform(-1.0, 1.0)
            x = cx + jitter * radius * math.cos(phi)
            y = cy + jitter * radius * math.sin(phi)
            ix, iy = math.floor(x / box), math.floor(y / box)
            atoms.append((len(atoms) + 1, c + 1, x - ix * box, y - iy * box, ix, iy))
            state.append((sigma, l0, theta0, args.a0))
        for k in range(n):
            prev, here, nxt = first + (k - 1) % n, first + k, first + (k + 1) % n
            bonds.append((here, nxt))
            angles.append((prev, here, nxt))
    return box, atoms, bonds, angles, state


def write(path, box, atoms, bonds, angles, state, comment, bond_types=1, shuffle=0,
          stiffness=None):
    """stiffness: per atom (d_kl, d_kb), written as a Stiffness section (fix Stiffness)."""
    with open(path, "w") as out:
        out.write(f"LAMMPS data file: {comment}\n\n")
        out.write(f"{len(atoms)} atoms\n1 atom types\n{len(bonds)} bonds\n{bond_types} bond types\n")
        out.write(f"{len(angles)} angles\n1 angle types\n\n")
        out.write(f"0 {box:.16g} xlo xhi\n0 {box:.16g} ylo yhi\n-0.5 0.5 zlo zhi\n\n")
        out.write("Masses\n\n1 1.0\n\nAtoms # molecular\n\n")
        if shuffle:    # the same atoms in another order, to test order independence
            atoms = list(atoms)
            random.Random(shuffle).shuffle(atoms)
        for a in atoms:
            out.write(f"{a[0]} {a[1]} 1 {a[2]:.16g} {a[3]:.16g} 0 {a[4]} {a[5]} 0\n")
        out.write("\nBonds\n\n")
        for i, b in enumerate(bonds, 1):
            out.write(f"{i} 1 {b[0]} {b[1]}\n")
        out.write("\nAngles\n\n")
        for i, a in enumerate(angles, 1):
            out.write(f"{i} 1 {a[0]} {a[1]} {a[2]}\n")
        out.write("\nVertices\n\n")
        for i, s in enumerate(state, 1):
            out.write(f"{i} {s[0]:.16g} {s[1]:.16g} {s[2]:.16g} {s[3]:.16g}\n")
        if stiffness is not None:
            out.write("\nStiffness\n\n")
            for i, k in enumerate(stiffness, 1):
                out.write(f"{i} {k[0]:.16g} {k[1]:.16g}\n")


def write_molecule(path, n, a0, calA0_relative):
    """One regular n-gon of area a0 as a LAMMPS molecule template (for create_atoms ... mol)."""
    radius = math.sqrt(2.0 * a0 / (n * math.sin(2.0 * math.pi / n)))
    with open(path, "w") as out:
        l0, sigma, theta0 = polygon_state(n, a0, calA0_relative)
        out.write(f"# regular {n}-gon of area {a0} (MESOPHYLL tools/make_cells.py); after "
                  f"create_atoms set d_sigma {sigma:.16g} d_l0 {l0:.16g} d_theta0 {theta0:.16g} "
                  f"d_a0 {a0:.16g}\n\n")
        out.write(f"{n} atoms\n{n} bonds\n{n} angles\n\nCoords\n\n")
        for k in range(n):
            phi = 2.0 * math.pi * k / n
            out.write(f"{k + 1} {radius * math.cos(phi):.16g} {radius * math.sin(phi):.16g} 0\n")
        out.write("\nTypes\n\n" + "".join(f"{k + 1} 1\n" for k in range(n)))
        out.write("\nMolecules\n\n" + "".join(f"{k + 1} 1\n" for k in range(n)))
        out.write("\nBonds\n\n" + "".join(f"{k + 1} 1 {k + 1} {(k + 1) % n + 1}\n" for k in range(n)))
        out.write("\nAngles\n\n" + "".join(
            f"{k + 1} 1 {(k - 1) % n + 1} {k + 1} {(k + 1) % n + 1}\n" for k in range(n)))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output", help="data file to write (a molecule template with --molecule)")
    p.add_argument("--molecule", action="store_true",
                   help="write one regular polygon as a molecule template instead")
    p.add_argument("--cells", type=int, default=4, help="number of cells (default 4)")
    p.add_argument("--vertices", type=int, default=32,
                   help="vertices per cell (default 32, at least 3); fewer vertices make longer "
                        "segments (for area 1: 0.11 with 32, 1.52 with 3), and the "
                        "input's communication cutoff (comm_modify cutoff) must exceed the "
                        "longest")
    p.add_argument("--a0", type=float, default=1.0, help="preferred area (default 1)")
    p.add_argument("--calA0", type=float, default=1.14,
                   help="preferred shape parameter relative to the regular n-gon (default 1.14)")
    p.add_argument("--spacing", type=float, default=1.05,
                   help="lattice spacing in cell diameters (default 1.05)")
    p.add_argument("--shift", type=float, default=0.0,
                   help="shift of the lattice, in box lengths, so rings cross the boundary")
    p.add_argument("--jitter", type=float, default=0.0,
                   help="random radial displacement of vertices, relative (default 0)")
    p.add_argument("--seed", type=int, default=0, help="random seed; 0 = no random phase")
    p.add_argument("--bond-types", type=int, default=1,
                   help="bond types to declare (ring segments are type 1; default 1)")
    p.add_argument("--shuffle", type=int, default=0,
                   help="list the atoms in a random order drawn with this seed (0 = in order)")
    args = p.parse_args()
    if args.cells < 1 or args.vertices < 3 or args.a0 <= 0 or args.calA0 <= 0 or args.spacing <= 0:
        p.error("need cells >= 1, vertices >= 3 and positive a0, calA0, spacing")
    if args.bond_types < 1:
        p.error("need --bond-types >= 1")
    if args.molecule:
        write_molecule(args.output, args.vertices, args.a0, args.calA0)
        return
    box, atoms, bonds, angles, state = build(args)
    write(args.output, box, atoms, bonds, angles, state,
          f"{args.cells} cells of {args.vertices} vertices (MESOPHYLL tools/make_cells.py)",
          args.bond_types, args.shuffle)


if __name__ == "__main__":
    main()
