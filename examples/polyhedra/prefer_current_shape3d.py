#!/usr/bin/env python3
"""Make the current shape of every 3d cell its preferred shape: each edge's l0 and theta0 and each
cell's v0 set to the current edge length, bending angle and volume.

    prefer_current_shape3d.py IN OUT

IN is a data file of deformable polyhedra as write_data writes it (Atoms with image flags, Angles
= faces, Dihedrals = hinges, and the sections Vertices, Edges, EdgeLengths and EdgeAngles of
doc/Howto_polyhedra.rst). make_open_tissue3d.sh uses it on a tissue pressed to jamming at a high
P_jam: the pressed, flattened cells then rest in the shapes that fill the box, so the tissue stays
confluent when it is relaxed at a lower P0 (doc/Howto_polyhedra.rst, "Growth: what opens a 3d
tissue"). tools/prefer_current_angles3d.py sets theta0 only. Everything else (adhesive bonds,
sigma) is copied as it is. Standard library only.
"""
import argparse
import math
import os
import sys

tools = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, tools)
from make_cells3d import bending_angle, cross, dot  # noqa: E402  (one definition each)
from prefer_current_angles3d import box_lengths, rows, sections  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    args = parser.parse_args()
    with open(args.input) as f:
        lines = f.read().split("\n")
    found = sections(lines)
    for needed in ("Atoms", "Angles", "Dihedrals", "Vertices", "Edges", "EdgeLengths",
                   "EdgeAngles"):
        if needed not in found:
            raise SystemExit(f"prefer_current_shape3d: {args.input} has no {needed} section")
    box = box_lengths(lines)
    position, cell = {}, {}
    for w in rows(lines, found["Atoms"]):
        if len(w) < 9:
            raise SystemExit("prefer_current_shape3d: Atoms lines need image flags "
                             "(atom_style molecular: id mol type x y z ix iy iz)")
        position[int(w[0])] = [float(w[3 + d]) + int(w[6 + d]) * box[d] for d in range(3)]
        cell[int(w[0])] = int(w[1])

    def near(p, to):  # the image of p nearest to 'to'
        return [p[d] - box[d] * round((p[d] - to[d]) / box[d]) for d in range(3)]

    # per cell: the divergence-theorem volume over its faces, wings at the images nearest to b
    volume = {}
    for w in rows(lines, found["Angles"]):
        a, b, c = (int(v) for v in w[2:5])
        xb = position[b]
        volume[cell[b]] = volume.get(cell[b], 0.0) + dot(
            near(position[a], xb), cross(xb, near(position[c], xb))) / 6.0
    for m, v in volume.items():
        if not (v > 0.0 and math.isfinite(v)):
            raise SystemExit(f"prefer_current_shape3d: cell {m} has volume {v!r}: not a cell "
                             "with outward faces")
    length, angle = {}, {}
    for w in rows(lines, found["Dihedrals"]):
        a, b, c, d = (int(v) for v in w[2:6])
        xb = position[b]
        xc = near(position[c], xb)
        key = (min(b, c), max(b, c))
        length[key] = math.dist(xb, xc)
        angle[key] = bending_angle(near(position[a], xb), xb, xc, near(position[d], xb))

    partners = {int(w[0]): [int(v) for v in w[1:]] for w in rows(lines, found["Edges"])}

    def rewrite(section, current):
        start, end = found[section]
        changed = 0
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
                    raise SystemExit(f"prefer_current_shape3d: edge {owner}-{partner} has no "
                                     "hinge (dihedral) in the Dihedrals section")
                values[k] = repr(current[key])
                changed += 1
            lines[n] = " ".join([w[0]] + values)
        if changed != len(current):
            raise SystemExit(f"prefer_current_shape3d: {len(current)} hinges but {changed} "
                             f"edges with {section}: every edge needs one hinge and one column")

    rewrite("EdgeLengths", length)
    rewrite("EdgeAngles", angle)
    start, end = found["Vertices"]
    for n in range(start, end):
        w = lines[n].split()
        if w:
            lines[n] = " ".join([w[0], w[1], repr(volume[cell[int(w[0])]])])
    with open(args.output, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {args.output}: l0 and theta0 of {len(length)} edges and v0 of {len(volume)} "
          f"cells set to the current shape (mean v0 {sum(volume.values()) / len(volume):.4f})")


if __name__ == "__main__":
    main()
