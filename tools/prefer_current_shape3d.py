#!/usr/bin/env python3
"""Make the current shape of every 3d cell of a MESOPHYLL data file its preferred shape.

    prefer_current_shape3d.py IN OUT [--theta0-only]

IN is a data file of deformable polyhedra as write_data writes it (Atoms with image flags, Angles
= faces, Dihedrals = hinges, and the sections Vertices, Edges, EdgeLengths and EdgeAngles of
doc/Howto_polyhedra.rst). Each hinge (dihedral a b c d, faces (a, b, c) and (c, b, d)) gives the
current length of its edge b-c and its bending angle, the signed angle between the outward
normals of the two faces (tools/make_cells3d.py); each cell's faces give its volume (divergence
theorem). OUT is IN with every edge's l0 and theta0 and every cell's v0 set to these current
values, or, with --theta0-only, every edge's theta0 alone. Everything else (adhesive bonds,
sigma) is copied as it is.

The initial tissues use it on the state pressed to jamming (examples/polyhedra/make_tissue3d.sh):
with --theta0-only a tissue keeps the bent shapes it was pressed into, as the 2d tissue's
preferred turning angles are set to its current ones; in full, the pressed, flattened cells rest
in the shapes that fill the box, so that a tissue pressed at a high P_jam stays confluent when it
is relaxed at a lower P0 (doc/Howto_polyhedra.rst, "Growth: what opens a 3d tissue").
Standard library only.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_cells3d import bending_angle, cross, dot  # noqa: E402  (one definition each)

NAME = "prefer_current_shape3d"


def sections(lines):
    """{title: (first line index, last index + 1)} of the data file's body sections."""
    found, title, start = {}, None, 0
    for n, line in enumerate(lines):
        word = line.split("#")[0].strip()
        if word and word[0].isalpha() and not any(c.isdigit() for c in word.split()[0]):
            if title:
                found[title] = (start, n)
            title, start = word, n + 1
    if title:
        found[title] = (start, len(lines))
    return found


def rows(lines, span):
    return [line.split() for line in lines[span[0]:span[1]] if line.split()]


def box_lengths(lines):
    lengths = {}
    for line in lines:
        w = line.split()
        if len(w) >= 4 and w[2] in ("xlo", "ylo", "zlo"):
            lengths[w[2][0]] = float(w[1]) - float(w[0])
        if len(w) >= 6 and w[3] == "xy":
            if any(float(v) != 0.0 for v in w[:3]):
                raise SystemExit(f"{NAME}: triclinic boxes are not supported")
    if len(lengths) != 3:
        raise SystemExit(f"{NAME}: the header lacks xlo xhi, ylo yhi or zlo zhi")
    return [lengths["x"], lengths["y"], lengths["z"]]


class Tissue:
    """The positions of a data file's vertices, unwrapped by their image flags, and their cells."""

    def __init__(self, lines, found):
        self.box = box_lengths(lines)
        self.position, self.cell = {}, {}
        for w in rows(lines, found["Atoms"]):
            if len(w) < 9:
                raise SystemExit(f"{NAME}: Atoms lines need image flags "
                                 "(atom_style molecular: id mol type x y z ix iy iz)")
            self.position[int(w[0])] = [float(w[3 + d]) + int(w[6 + d]) * self.box[d]
                                        for d in range(3)]
            self.cell[int(w[0])] = int(w[1])

    def near(self, atom, to):
        """The image of atom's position nearest to the point 'to'."""
        p, box = self.position[atom], self.box
        return [p[d] - box[d] * round((p[d] - to[d]) / box[d]) for d in range(3)]

    def edges(self, hinges):
        """{(lower ID, higher ID): (length, bending angle)} of each hinge's edge, its wings at
        the images nearest to b."""
        found = {}
        for w in hinges:
            a, b, c, d = (int(v) for v in w[2:6])
            xb = self.position[b]
            xc = self.near(c, xb)
            found[(min(b, c), max(b, c))] = (math.dist(xb, xc), bending_angle(
                self.near(a, xb), xb, xc, self.near(d, xb)))
        return found

    def volumes(self, faces):
        """{cell: volume} by the divergence theorem over its faces, wings nearest to b."""
        volume = {}
        for w in faces:
            a, b, c = (int(v) for v in w[2:5])
            xb, m = self.position[b], self.cell[b]
            volume[m] = volume.get(m, 0.0) + dot(self.near(a, xb),
                                                 cross(xb, self.near(c, xb))) / 6.0
        for m, v in volume.items():
            if not (v > 0.0 and math.isfinite(v)):
                raise SystemExit(f"{NAME}: cell {m} has volume {v!r}: not a cell with outward "
                                 "faces")
        return volume


def rewrite_edges(lines, found, section, current):
    """Each edge's column of 'section' (per lower-ID vertex, in the order of its Edges row) set to
    current[edge]; returns the largest change."""
    partners = {int(w[0]): [int(v) for v in w[1:]] for w in rows(lines, found["Edges"])}
    start, end = found[section]
    changed, largest = 0, 0.0
    for n in range(start, end):
        w = lines[n].split()
        if not w:
            continue
        owner, values = int(w[0]), w[1:]
        for k, partner in enumerate(partners.get(owner, [])):
            if partner == 0:
                continue
            key = (min(owner, partner), max(owner, partner))
            if key not in current:
                raise SystemExit(f"{NAME}: edge {owner}-{partner} has no hinge (dihedral) in the "
                                 "Dihedrals section")
            largest = max(largest, abs(current[key] - float(values[k])))
            values[k] = repr(current[key])
            changed += 1
        lines[n] = " ".join([w[0]] + values)
    if changed != len(current):
        raise SystemExit(f"{NAME}: {len(current)} hinges but {changed} edges with {section}: "
                         "every edge needs one hinge and one column")
    return largest


def rewrite_volumes(lines, found, tissue, volume):
    """Every vertex's v0 (Vertices: id sigma v0) set to its cell's volume."""
    start, end = found["Vertices"]
    for n in range(start, end):
        w = lines[n].split()
        if w:
            lines[n] = " ".join([w[0], w[1], repr(volume[tissue.cell[int(w[0])]])])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--theta0-only", action="store_true",
                        help="set each edge's preferred bending angle only")
    args = parser.parse_args()
    with open(args.input) as f:
        lines = f.read().split("\n")
    found = sections(lines)
    needed = ["Atoms", "Dihedrals", "Edges", "EdgeAngles"]
    if not args.theta0_only:
        needed += ["Angles", "Vertices", "EdgeLengths"]
    for title in needed:
        if title not in found:
            raise SystemExit(f"{NAME}: {args.input} has no {title} section")
    tissue = Tissue(lines, found)
    volume = {} if args.theta0_only else tissue.volumes(rows(lines, found["Angles"]))
    edges = tissue.edges(rows(lines, found["Dihedrals"]))
    if args.theta0_only:
        largest = rewrite_edges(lines, found, "EdgeAngles", {e: v[1] for e, v in edges.items()})
        summary = f"theta0 of {len(edges)} edges set to the current bending angles (largest " \
                  f"change {largest:.3g} rad)"
    else:
        rewrite_edges(lines, found, "EdgeLengths", {e: v[0] for e, v in edges.items()})
        rewrite_edges(lines, found, "EdgeAngles", {e: v[1] for e, v in edges.items()})
        rewrite_volumes(lines, found, tissue, volume)
        summary = f"l0 and theta0 of {len(edges)} edges and v0 of {len(volume)} cells set to " \
                  f"the current shape (mean v0 {sum(volume.values()) / len(volume):.4f})"
    with open(args.output, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {args.output}: {summary}")


if __name__ == "__main__":
    main()
