#!/usr/bin/env python3
"""Set every edge's preferred bending angle of a 3d MESOPHYLL data file to its current one.

    prefer_current_angles3d.py IN OUT

IN is a data file of deformable polyhedra as write_data writes it (Atoms with image flags,
Dihedrals, and the per-edge sections Edges and EdgeAngles of doc/Howto_polyhedra.rst). Each hinge
(dihedral a b c d, faces (a, b, c) and (c, b, d)) gives the current bending angle of its edge b-c,
the signed angle between the outward normals of the two faces (tools/make_cells3d.py); OUT is IN
with that angle as the edge's theta0 in its EdgeAngles column. Everything else is copied as it
is, adhesive bonds included. An initial tissue keeps the shapes it was pressed into this way, as
the 2d tissue's preferred turning angles are set to its current ones. Standard library only.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_cells3d import bending_angle  # noqa: E402  (the one definition of the angle)


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
                raise SystemExit("prefer_current_angles3d: triclinic boxes are not supported")
    if len(lengths) != 3:
        raise SystemExit("prefer_current_angles3d: the header lacks xlo xhi, ylo yhi or zlo zhi")
    return [lengths["x"], lengths["y"], lengths["z"]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    args = parser.parse_args()
    with open(args.input) as f:
        lines = f.read().split("\n")
    found = sections(lines)
    for needed in ("Atoms", "Dihedrals", "Edges", "EdgeAngles"):
        if needed not in found:
            raise SystemExit(f"prefer_current_angles3d: {args.input} has no {needed} section")
    box = box_lengths(lines)

    position = {}
    for w in rows(lines, found["Atoms"]):
        if len(w) < 9:
            raise SystemExit("prefer_current_angles3d: Atoms lines need image flags "
                             "(atom_style molecular: id mol type x y z ix iy iz)")
        position[int(w[0])] = [float(w[3 + d]) + int(w[6 + d]) * box[d] for d in range(3)]

    def near(p, to):  # the image of p nearest to 'to'
        return [p[d] - box[d] * round((p[d] - to[d]) / box[d]) for d in range(3)]

    angle = {}
    for w in rows(lines, found["Dihedrals"]):
        a, b, c, d = (int(v) for v in w[2:6])
        xb = position[b]
        theta = bending_angle(near(position[a], xb), xb, near(position[c], xb),
                              near(position[d], xb))
        angle[(min(b, c), max(b, c))] = theta

    partners = {int(w[0]): [int(v) for v in w[1:]] for w in rows(lines, found["Edges"])}
    start, end = found["EdgeAngles"]
    changed, largest = 0, 0.0
    for n in range(start, end):
        w = lines[n].split()
        if not w:
            continue
        owner = int(w[0])
        values = w[1:]
        for k, partner in enumerate(partners.get(owner, [])):
            if partner == 0:
                continue
            key = (min(owner, partner), max(owner, partner))
            if key not in angle:
                raise SystemExit(f"prefer_current_angles3d: edge {owner}-{partner} has no hinge "
                                 "(dihedral) in the Dihedrals section")
            largest = max(largest, abs(angle[key] - float(values[k])))
            values[k] = repr(angle[key])
            changed += 1
        lines[n] = " ".join([w[0]] + values)
    if changed != len(angle):
        raise SystemExit(f"prefer_current_angles3d: {len(angle)} hinges but {changed} edges with "
                         "values: every edge needs one hinge and one EdgeAngles column")
    with open(args.output, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {args.output}: theta0 of {changed} edges set to the current bending angles "
          f"(largest change {largest:.3g} rad)")


if __name__ == "__main__":
    main()
