#!/usr/bin/env python3
"""Resample every ring of a tissue to n vertices, keeping the cells' mechanics (MESOPHYLL).

    tools/resample_tissue.py TISSUE.data N OUT.data [--lmp build/lmp] [--rings-only]

Reads a tissue data file (write_data of examples/tissue/in.make_tissue or of a run: Atoms,
Bonds, Angles, Vertices and, if present, Stiffness), resamples each ring at n points of equal arc
length along its current outline (starting at its first vertex), and gives the new ring the
state that makes it the same elastic curve, the rule of fix dpoly/refine's *rules consistent*
applied to any change of n (doc/fix_dpoly_refine.rst):

* Stretching. A segment U = (eps_l d_kl / 2)(l/l0 - 1)^2 is a spring of tension
  T = EA (l/l0 - 1) with EA = eps_l d_kl / l0 and compliance l0 / EA. The sum of l0 along the
  ring is a material coordinate u. A new segment spans the material u..u' of the arc it replaces
  and gets that material's strain, l0 = chord (u' - u) / arc, and its EA, the harmonic mean over
  the old segments it spans (springs in series): d_kl = l0 (u' - u) / sum(piece / EA). So the
  strain and tension field and the stretching stiffness per length are kept, and the preferred
  perimeter up to the corners the chords cut; for equal segments l0 ~ L0 / n, d_kl ~ d_kl_old
  n_old / n (the springs-in-series rule of rules consistent's split).
* Bending. A vertex standing for the ring length lbar = (l0_in + l0_out)/2 with
  U = (eps_b d_kb / 2)(theta - theta0)^2 is a curve of modulus B = eps_b d_kb lbar and preferred
  curvature kappa0 = theta0 / lbar. B and kappa0 are interpolated linearly in u between the old
  vertices, and the new vertex gets d_kb = B / lbar and theta0 = kappa0 lbar: d_kb ~ n / n_old,
  theta0 ~ n_old / n.
* Vertex diameter sigma: kept (interpolated in u; equal in the package's tissues). sigma is a
  physical length of the model, not of the discretisation: it is the contact range and the wall
  thickness that phi_patch adds, the breaking stretch r* = 2.41 sigma, and refinement's split
  length (3 radii). Scaling it with l0 would change all four and the observable with n. The cost:
  below about n = 16 for these cells (segments > 2 sigma) a vertex of another cell fits between
  two disks of a ring, so contacts no longer seal the outline, and at n = 64 (segments sigma/2)
  a ring's next-nearest vertices touch, so self-contact acts on every bent vertex.
* a0 per cell, as it was. Adhesive bonds are dropped: they are made again from the overlaps.

Then, without --rings-only, the initial-state definition of the package's tissues is applied:
examples/tissue/in.make_tissue -var rings, its step 2: bond every pair of vertices of different
cells that overlap, counting as overlapping the pairs closer than 1.001 s (relaxed rings touch at
r = s to round-off, so resampling noise would decide otherwise), theta0 = current angles, relax
with bending on at P0 = 1e-3 (the resampled polygons are inscribed in the old ones: less area,
other corners, so the box must relax), theta0 again; write_data OUT.data. At n = 32 the result is
the input (tests/check_resample_tissue.py: the rings to 1e-4 of a segment, 314 -> 315 bonds,
phi_patch and <calA> to 1e-4). Standard library only.
"""
import argparse
import bisect
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import make_cells  # noqa: E402
from lammps_data import DataFile  # noqa: E402

ANGLE_MAX = 3.0    # |theta0| bound of the resampled state (fix dpoly/cells needs (-pi, pi])


def read_sections(path):
    """Header lines and {section name: [rows of words]} of a LAMMPS data file."""
    data = DataFile(path)
    return data.header, data.sections


def read_tissue(path):
    """Box (xlo, xhi, ylo, yhi) and the rings: per cell, its vertices in ring order, each a dict
    of the unwrapped position and per-vertex state (l0, d_kl of the segment to the next)."""
    header, sections = read_sections(path)
    box = {}
    for words in header:
        if words[-2:] in (["xlo", "xhi"], ["ylo", "yhi"]):
            box[words[-2][0]] = (float(words[0]), float(words[1]))
    (xlo, xhi), (ylo, yhi) = box["x"], box["y"]
    vertex = {}
    for w in sections["Atoms"]:
        x = float(w[3]) + int(w[6]) * (xhi - xlo)
        y = float(w[4]) + int(w[7]) * (yhi - ylo)
        vertex[int(w[0])] = {"tag": int(w[0]), "cell": int(w[1]), "x": x, "y": y, "kl": 1.0,
                             "kb": 1.0}
    for w in sections["Vertices"]:
        vertex[int(w[0])].update(sigma=float(w[1]), l0=float(w[2]), theta0=float(w[3]),
                                 a0=float(w[4]))
    for w in sections.get("Stiffness", []):
        vertex[int(w[0])].update(kl=float(w[1]), kb=float(w[2]))
    following = {int(w[3]): int(w[4]) for w in sections["Angles"]}    # here -> next
    rings = {}
    for tag in sorted(vertex):
        cell = vertex[tag]["cell"]
        if cell in rings:
            continue
        ring = [tag]
        while following[ring[-1]] != tag:
            ring.append(following[ring[-1]])
        rings[cell] = [vertex[t] for t in ring]
    return (xlo, xhi, ylo, yhi), [rings[c] for c in sorted(rings)]


def interpolate(us, values, u, period):
    """Periodic linear interpolation of values given at increasing us (us[0] = 0) at u."""
    u %= period
    k = bisect.bisect_right(us, u) - 1
    u_next = us[k + 1] if k + 1 < len(us) else period
    t = (u - us[k]) / (u_next - us[k])
    return (1 - t) * values[k] + t * values[(k + 1) % len(values)]


def resample_ring(ring, n):
    """The n vertices (dicts as read_tissue's) of the same elastic curve; see the docstring."""
    m = len(ring)
    length = [math.hypot(ring[(k + 1) % m]["x"] - v["x"], ring[(k + 1) % m]["y"] - v["y"])
              for k, v in enumerate(ring)]
    s_at, u_at = [0.0], [0.0]    # arc length and material coordinate at each old vertex
    for k in range(m - 1):
        s_at.append(s_at[-1] + length[k])
        u_at.append(u_at[-1] + ring[k]["l0"])
    perimeter, material = s_at[-1] + length[-1], u_at[-1] + ring[-1]["l0"]
    lbar = [0.5 * (ring[k - 1]["l0"] + v["l0"]) for k, v in enumerate(ring)]
    modulus = [v["kb"] * lbar[k] for k, v in enumerate(ring)]
    curvature = [v["theta0"] / lbar[k] for k, v in enumerate(ring)]

    def at(s):    # old segment, position and material coordinate at arc length s (< perimeter)
        k = bisect.bisect_right(s_at, s) - 1
        t = (s - s_at[k]) / length[k]
        a, b = ring[k], ring[(k + 1) % m]
        return k, a["x"] + t * (b["x"] - a["x"]), a["y"] + t * (b["y"] - a["y"]), \
            u_at[k] + t * a["l0"]

    points = [at(j * perimeter / n) for j in range(n)]
    new = []
    for j, (k, x, y, u) in enumerate(points):
        u_end = points[(j + 1) % n][3] + (material if j == n - 1 else 0.0)
        # compliance (l0 / EA per unit l0 is l0 / d_kl, eps_l = 1) of the material u .. u_end
        compliance, start = 0.0, u
        while start < u_end:
            end = min(u_at[k % m] + material * (k // m) + ring[k % m]["l0"], u_end)
            compliance += (end - start) * ring[k % m]["l0"] / ring[k % m]["kl"]
            start, k = end, k + 1
        new.append({"cell": ring[0]["cell"], "x": x, "y": y, "u": u, "span": u_end - u,
                    "compliance": compliance, "a0": ring[0]["a0"],
                    "sigma": interpolate(u_at, [v["sigma"] for v in ring], u, material)})
    for j, v in enumerate(new):
        # the chord at the strain of the arc it replaces: l0 = chord (span / arc); EA kept
        after = new[(j + 1) % n]
        chord = math.hypot(after["x"] - v["x"], after["y"] - v["y"])
        v["l0"] = chord * v["span"] / (perimeter / n)
        v["kl"] = v["l0"] * v["span"] / v["compliance"]
    for j, v in enumerate(new):
        lbar_new = 0.5 * (new[j - 1]["l0"] + v["l0"])
        v["kb"] = interpolate(u_at, modulus, v["u"], material) / lbar_new
        # kappa0 lbar, kept a turning angle (in.make_tissue's step 2 sets theta0 anew)
        theta0 = interpolate(u_at, curvature, v["u"], material) * lbar_new
        v["theta0"] = max(-ANGLE_MAX, min(ANGLE_MAX, theta0))
    return new


def write_rings(path, box, rings, comment):
    """The rings as a data file of make_cells.write (box from 0; adhesive bond type declared)."""
    xlo, xhi, ylo, yhi = box
    if not math.isclose(xhi - xlo, yhi - ylo):
        raise ValueError("make_cells.write needs a square box")
    side = xhi - xlo
    atoms, bonds, angles, state, stiffness = [], [], [], [], []
    for ring in rings:
        first, n = len(atoms) + 1, len(ring)
        for v in ring:
            x, y = v["x"] - xlo, v["y"] - ylo
            ix, iy = math.floor(x / side), math.floor(y / side)
            atoms.append((len(atoms) + 1, v["cell"], x - ix * side, y - iy * side, ix, iy))
            state.append((v["sigma"], v["l0"], v["theta0"], v["a0"]))
            stiffness.append((v["kl"], v["kb"]))
        for k in range(n):
            bonds.append((first + k, first + (k + 1) % n))
            angles.append((first + (k - 1) % n, first + k, first + (k + 1) % n))
    make_cells.write(path, side, atoms, bonds, angles, state, comment, bond_types=2,
                     stiffness=stiffness)


def define_tissue(lmp, rings_path, out_path, log):
    """examples/tissue/in.make_tissue's step 2 on the rings of rings_path, written to out_path."""
    tissue_dir = os.path.join(ROOT, "examples", "tissue")
    result = subprocess.run([lmp, "-in", "in.make_tissue", "-var", "rings",
                             os.path.abspath(rings_path), "-var", "out", os.path.abspath(out_path),
                             "-log", os.path.abspath(log), "-screen", "none"],
                            cwd=tissue_dir, capture_output=True, text=True)
    if result.returncode != 0:
        with open(log) as f:
            raise RuntimeError("in.make_tissue -var rings failed:\n" + "".join(f.readlines()[-5:]))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("tissue", help="data file of the tissue to resample")
    p.add_argument("vertices", type=int, help="vertices per cell of the new tissue (>= 6)")
    p.add_argument("output", help="data file to write")
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--rings-only", action="store_true",
                   help="write the resampled rings without bonding and relaxing them")
    args = p.parse_args(argv)
    if args.vertices < 6:
        p.error("need at least 6 vertices per cell")
    box, rings = read_tissue(args.tissue)
    rings = [resample_ring(ring, args.vertices) for ring in rings]
    comment = (f"{len(rings)} cells of {os.path.basename(args.tissue)} resampled to "
               f"{args.vertices} vertices (MESOPHYLL tools/resample_tissue.py)")
    if args.rings_only:
        write_rings(args.output, box, rings, comment)
        return
    with tempfile.TemporaryDirectory() as scratch:
        raw = os.path.join(scratch, "rings.data")
        write_rings(raw, box, rings, comment)
        log = os.path.join(scratch, "log.lammps")
        define_tissue(os.path.abspath(args.lmp), raw, args.output, log)
        with open(log) as f:
            print("".join(line for line in f if line.startswith("tissue:")), end="")


if __name__ == "__main__":
    main()
