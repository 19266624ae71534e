#!/usr/bin/env python3
"""Replicate a MESOPHYLL tissue nx x ny times in its periodic box, standard library only.

    tools/replicate_tissue.py tissue_N64.data tissue_N256.data --copies 2 2

LAMMPS's replicate command refuses systems whose per-vertex state lives in fix property/atom
("Cannot replicate with fixes that store per-atom quantities"), so this works on data files (from
write_data or tools/make_cells.py, atom style molecular, orthogonal box). Every cell is copied
whole: copy (a, b) of a cell is the cell shifted by (a Lx, b Ly), its ring bonds and angles join
the copies of their own vertices, and an adhesive bond (any bond between two cells) joins the copy
of the partner that is the nearest image in the original box, so a bond across the periodic
boundary becomes one between neighbouring copies (or across the new boundary). Atom IDs of copy k
are the originals plus k x (largest ID), molecule IDs plus k x (largest molecule ID). Vertices are
wrapped into the new box with image flags that keep every ring whole. Every per-atom section
other than Atoms (Velocities, and the sections of fix property/atom: Vertices, Stiffness, ...) is
copied with the IDs. The copy's energy per cell and pressure equal the original's (ctest
mesophyll.replicate_tissue). Limits: cells narrower than half the box (a cell's bond to its own
image stays in its copy), no Type Labels sections.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lammps_data import DataFile  # noqa: E402  (next to this script)

TOPOLOGY = {"Bonds": 2, "Angles": 3, "Dihedrals": 4, "Impropers": 4}    # atoms per entry
COPIED = ("Masses", "Pair Coeffs", "PairIJ Coeffs", "Bond Coeffs", "Angle Coeffs")


def nearest_copy(shift, copies):
    """Copy index (mod copies) and the image flag that a copy shift lands on."""
    return shift % copies, shift // copies


def replicate(data, nx, ny):
    if any(len(w) > 3 and w[3] in ("xy", "xz", "yz") for w in data.header):
        raise SystemExit("replicate_tissue: triclinic boxes are not supported")
    style = data.styles.get("Atoms") or "molecular"
    if style != "molecular":
        raise SystemExit(f"replicate_tissue: atom style {style}; only molecular is supported")
    (xlo, xhi), (ylo, yhi) = data.bounds("x"), data.bounds("y")
    lx, ly = xhi - xlo, yhi - ylo
    # id mol type x y z, then the image flags (0 0 0 where the file has none)
    atoms = {int(w[0]): (w + ["0", "0", "0"])[:9] for w in data.sections["Atoms"]}
    if any(int(w[1]) < 1 for w in atoms.values()):
        raise SystemExit("replicate_tissue: every vertex needs a molecule (cell) ID >= 1")
    if len(atoms) != data.count("atoms"):
        raise SystemExit(f"replicate_tissue: {len(atoms)} atoms listed, the header says "
                         f"{data.count('atoms')}")
    id_step = max(atoms)
    mol_step = max(int(w[1]) for w in atoms.values())
    unwrapped = {i: (float(w[3]) + int(w[6]) * lx, float(w[4]) + int(w[7]) * ly)
                 for i, w in atoms.items()}
    copies = [(a, b) for b in range(ny) for a in range(nx)]

    def copy_index(a, b):
        return b * nx + a

    out_atoms = []
    for k, (a, b) in enumerate(copies):
        for i, w in atoms.items():
            # the copy shifted by (a, b) boxes, wrapped into the nx x ny box
            ix, iy = int(w[6]) + a, int(w[7]) + b
            sa, fx = nearest_copy(ix, nx)
            sb, fy = nearest_copy(iy, ny)
            x = float(w[3]) + sa * lx
            y = float(w[4]) + sb * ly
            out_atoms.append([str(i + k * id_step), str(int(w[1]) + k * mol_step), w[2],
                              repr(x), repr(y), w[5], str(fx), str(fy), w[8]])

    def partner_shift(i, j, a, b):
        """The copy of atom j bonded to copy (a, b) of atom i: the nearest image of j."""
        dx = unwrapped[j][0] - unwrapped[i][0]
        dy = unwrapped[j][1] - unwrapped[i][1]
        # j's copy c is where unwrapped j + c L is i's image plus the minimum-image vector
        ca = a - round(dx / lx)
        cb = b - round(dy / ly)
        return copy_index(ca % nx, cb % ny)

    molecule = {i: w[1] for i, w in atoms.items()}
    topology = {}
    for name, width in TOPOLOGY.items():
        entries = data.sections.get(name, [])
        rows = []
        for k, (a, b) in enumerate(copies):
            for w in entries:
                ids = [int(v) for v in w[2:2 + width]]
                first = ids[0]
                new = []
                for j in ids:
                    # a vertex of the same cell is in the same copy; another cell's, where the
                    # bond reaches it
                    same = molecule[j] == molecule[first]
                    c = k if same else partner_shift(first, j, a, b)
                    new.append(str(j + c * id_step))
                rows.append([str(len(rows) + 1), w[1]] + new)
        topology[name] = rows

    sections = {}
    for name, rows in data.sections.items():
        if name == "Atoms":
            sections[name] = out_atoms
        elif name in topology:
            sections[name] = topology[name]
        elif name in COPIED or name.endswith("Coeffs"):
            sections[name] = rows
        else:    # per atom, keyed by atom ID: Velocities, fix property/atom sections
            if len(rows) != len(atoms):
                raise SystemExit(f"replicate_tissue: section {name} has {len(rows)} lines for "
                                 f"{len(atoms)} atoms; only per-atom sections can be copied")
            sections[name] = [[str(int(w[0]) + k * id_step)] + w[1:]
                              for k in range(len(copies)) for w in rows]

    header = []
    for words in data.header:
        if " ".join(words[1:]) in ("atoms", "bonds", "angles", "dihedrals", "impropers"):
            header.append([str(int(words[0]) * len(copies))] + words[1:])
        elif words[2:] == ["xlo", "xhi"]:
            header.append([repr(xlo), repr(xlo + nx * lx), "xlo", "xhi"])
        elif words[2:] == ["ylo", "yhi"]:
            header.append([repr(ylo), repr(ylo + ny * ly), "ylo", "yhi"])
        else:
            header.append(words)
    return header, sections


def write(path, title, header, sections, styles):
    with open(path, "w") as out:
        out.write(title + "\n\n")
        for words in header:
            out.write(" ".join(words) + "\n")
        for name, rows in sections.items():
            style = f" # {styles[name]}" if styles.get(name) else ""
            out.write(f"\n{name}{style}\n\n")
            for words in rows:
                out.write(" ".join(words) + "\n")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("input", help="data file of the tissue (atom style molecular)")
    p.add_argument("output", help="data file to write")
    p.add_argument("--copies", type=int, nargs=2, metavar=("NX", "NY"), default=(2, 2),
                   help="copies along x and y (default 2 2)")
    args = p.parse_args()
    nx, ny = args.copies
    if nx < 1 or ny < 1:
        p.error(f"--copies must be >= 1 each, got {nx} {ny}")
    data = DataFile(args.input)
    header, sections = replicate(data, nx, ny)
    write(args.output, f"{data.title} (x{nx} x{ny} by MESOPHYLL tools/replicate_tissue.py)",
          header, sections, data.styles)
    print(f"replicate_tissue: {data.count('atoms')} -> {data.count('atoms') * nx * ny} vertices, "
          f"{nx} x {ny} copies, in {args.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
