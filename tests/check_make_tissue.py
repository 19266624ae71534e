#!/usr/bin/env python3
"""tools/make_tissue.py and in.relax_tissue make a confluent, bonded tissue at P_jam.

    check_make_tissue.py --lmp BUILD/lmp [--np N] [--mpirun CMD] [--numproc-flag F] ...

1. Seeding (Python, any --np): the same seed writes the same file, another seed another; every
   ring counter-clockwise with the area of its cell up to the chords of 32 vertices (within 2%
   below a0); no vertex of one ring within a contact distance s of another ring's (minimum
   image); the per-vertex state of the package's initial cells (sigma = l0 = p0/n,
   theta0 = 2 pi/n, a0 = 1); with --polydispersity the same per cell, sizes of mean sqrt(a0) 1,
   rings no larger than their a0 and apart by their own contact distances.
2. Relaxation of 8 seeded cells (on 1 rank the whole tool, on more in.relax_tissue on --np
   ranks): the data file reads back, and
   measured by a `run 0` with the main example's styles it is at P_jam (abs(P/P_jam - 1) below
   1e-4), confluent (phi_patch above 0.85), every cell bonded to another (adhesive bonds on every
   cell, to other cells), and equal to what the run printed (bonds, phi_patch). The rings are the
   same on any number of ranks (drawn in Python from the seed); the relaxation is not compared
   across rank counts: FIRE on the floppy bending-free rings amplifies round-off (after 3000
   iterations the packing fraction of 8 cells differs in its fourth digit between 1 and 2 ranks).
3. Arguments (with --np 1): every bad value is refused with exit code 2 and a message naming it.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
from regression import launch, parse_lmp_arguments, tissue_commands  # noqa: E402
from lammps_data import DataFile  # noqa: E402

TOOL = os.path.join(ROOT, "tools", "make_tissue.py")
RELAX = os.path.join(ROOT, "examples", "tissue", "in.relax_tissue")
CELLS, N = 8, 32
P_JAM = 1.0e-6
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def seed_rings(work, seed, name):
    path = os.path.join(work, name)
    subprocess.run([sys.executable, TOOL, path, "--cells", str(CELLS), "--seed", str(seed),
                    "--rings-only"], check=True, capture_output=True)
    return path


def rings_of(data):
    lx = data.bounds("x")[1] - data.bounds("x")[0]
    ly = data.bounds("y")[1] - data.bounds("y")[0]
    rings = {}
    for w in data.sections["Atoms"]:
        x = float(w[3]) + int(w[6]) * lx
        y = float(w[4]) + int(w[7]) * ly
        rings.setdefault(int(w[1]), []).append((int(w[0]), x, y))
    return {m: sorted(v) for m, v in rings.items()}, lx, ly


def check_seeding(work):
    first = seed_rings(work, 5, "a.data")
    again = seed_rings(work, 5, "b.data")
    other = seed_rings(work, 6, "c.data")
    same = open(first).read() == open(again).read()
    check(same, "the same seed writes the same rings")
    check(open(first).read() != open(other).read(), "another seed writes other rings")
    data = DataFile(first)
    rings, lx, ly = rings_of(data)
    state = {int(w[0]): [float(v) for v in w[1:5]] for w in data.sections["Vertices"]}
    regular = N * math.tan(math.pi / N) / math.pi
    l0 = math.sqrt(4.0 * math.pi * 1.14 * regular) / N
    check(all(abs(s[0] - l0) < 1e-12 and abs(s[1] - l0) < 1e-12 and
              abs(s[2] - 2 * math.pi / N) < 1e-12 and s[3] == 1.0 for s in state.values()),
          f"every vertex has sigma = l0 = {l0:.6f}, theta0 = 2 pi/n, a0 = 1")
    areas = []
    for ring in rings.values():
        xy = [(x, y) for _, x, y in ring]
        areas.append(0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1)
                               in zip(xy, xy[1:] + xy[:1])))
    check(len(rings) == CELLS and all(len(r) == N for r in rings.values()),
          f"{CELLS} rings of {N} vertices")
    check(all(0.98 < a <= 1.0 + 1e-12 for a in areas),
          f"rings counter-clockwise with area a0 up to the chords: "
          f"{min(areas):.5f}..{max(areas):.5f}")
    closest = math.inf
    cells = list(rings.items())
    for k, (m, ring) in enumerate(cells):
        for _, ring2 in cells[k + 1:]:
            for _, x, y in ring:
                for _, x2, y2 in ring2:
                    dx = (x2 - x) - lx * round((x2 - x) / lx)
                    dy = (y2 - y) - ly * round((y2 - y) / ly)
                    closest = min(closest, math.hypot(dx, dy))
    check(closest >= l0 * (1 - 1e-9),
          f"no vertex pair of different rings closer than s = {l0:.6f}: closest {closest:.6f}")
    return first


def check_polydisperse(work):
    """--polydispersity: sizes drawn with mean sqrt(a0) = 1, each ring in its cell's own state,
    no larger than its a0, and apart from its neighbours by their mean vertex diameter."""
    path = os.path.join(work, "poly.data")
    subprocess.run([sys.executable, TOOL, path, "--cells", str(CELLS), "--seed", "5",
                    "--polydispersity", "0.3", "--rings-only"], check=True, capture_output=True)
    data = DataFile(path)
    rings, lx, ly = rings_of(data)
    state = {int(w[0]): [float(v) for v in w[1:5]] for w in data.sections["Vertices"]}
    regular = N * math.tan(math.pi / N) / math.pi
    a0, sigma, ok_state, ok_area = {}, {}, True, True
    for m, ring in rings.items():
        a0[m] = state[ring[0][0]][3]
        sigma[m] = math.sqrt(4.0 * math.pi * a0[m] * 1.14 * regular) / N
        ok_state &= all(abs(state[i][0] - sigma[m]) < 1e-12 and abs(state[i][1] - sigma[m]) < 1e-12
                        and state[i][3] == a0[m] for i, _, _ in ring)
        xy = [(x, y) for _, x, y in ring]
        area = 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(xy, xy[1:] + xy[:1]))
        ok_area &= 0.0 < area <= a0[m] * (1 + 1e-12)
    sizes = [math.sqrt(a) for a in a0.values()]
    check(abs(sum(sizes) / len(sizes) - 1) < 1e-12 and max(sizes) / min(sizes) > 1.2,
          f"polydisperse: mean sqrt(a0) 1, sqrt(a0) {min(sizes):.3f}..{max(sizes):.3f}")
    check(ok_state and ok_area, "polydisperse: each ring in its cell's state, area in (0, a0]")
    closest = math.inf
    cells = list(rings.items())
    for k, (m, ring) in enumerate(cells):
        for m2, ring2 in cells[k + 1:]:
            s = 0.5 * (sigma[m] + sigma[m2])
            for _, x, y in ring:
                for _, x2, y2 in ring2:
                    dx = (x2 - x) - lx * round((x2 - x) / lx)
                    dy = (y2 - y) - ly * round((y2 - y) / ly)
                    closest = min(closest, math.hypot(dx, dy) / s)
    check(closest >= 1 - 1e-9, f"polydisperse: no vertex pair closer than its s: closest "
                               f"{closest:.4f} s")


def relax(args, work, rings, name, np):
    """On one rank the whole tool from the seed (its LAMMPS driver included; it draws the same
    rings as check_seeding's); on more, in.relax_tissue on those rings through the launcher."""
    out = os.path.join(work, name)
    if np == 1:
        command = [sys.executable, TOOL, out, "--cells", str(CELLS), "--seed", "5",
                   "--pack-rate", "1e-2", "--lmp", args.lmp]
        env = dict(os.environ)
    else:
        args_np = argparse.Namespace(**dict(vars(args), np=np))
        command, env = launch(args_np, ["-in", RELAX, "-var", "rings", rings, "-var", "out", out,
                                        "-var", "pack_rate", "1e-2",
                                        "-log", "none", "-echo", "none"])
    result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"check_make_tissue: the relaxation failed on {np} ranks:\n"
                 f"{result.stdout[-3000:]}{result.stderr[-2000:]}")
    line = next(x for x in result.stdout.splitlines() if x.startswith("make_tissue: tissue:"))
    printed = dict(zip(re.findall(r"(phi_patch|bonds) ", line),
                       (float(v) for v in re.findall(r"(?:phi_patch|bonds) ([0-9.eE+-]+)", line))))
    return out, printed


MEASURE = """compute tissue all dpoly/tissue
variable bonded equal 0
thermo_style custom step press c_tissue[2] c_tissue[3] c_tissue[4] c_tissue[5] c_tissue[6]
thermo_modify norm no format float %.12g
run 0 post no
"""


def measure(args, work, data):
    path = os.path.join(work, "in.measure")
    with open(path, "w") as f:
        f.write(tissue_commands(data) + MEASURE)
    args1 = argparse.Namespace(**dict(vars(args), np=1))
    command, env = launch(args1, ["-in", path, "-log", "none", "-echo", "none"])
    result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"check_make_tissue: reading {data} back failed:\n{result.stdout[-3000:]}")
    lines = result.stdout.splitlines()
    k = next(i for i, x in enumerate(lines) if x.split()[:2] == ["Step", "Press"])
    _, press, phi_patch, calA, z, bonds, cells = (float(v) for v in lines[k + 1].split())
    # per cell from the data file: adhesive bonds (type 2) and the cells they join it to
    written = DataFile(data)
    cell = {int(w[0]): int(w[1]) for w in written.sections["Atoms"]}
    per_cell = {c: [0, set()] for c in set(cell.values())}
    for w in written.sections["Bonds"]:
        if w[1] == "2":
            a, b = cell[int(w[2])], cell[int(w[3])]
            for one, other in ((a, b), (b, a)):
                per_cell[one][0] += 1
                per_cell[one][1].add(other)
    return {"P": press, "phi_patch": phi_patch, "calA": calA, "z": z, "bonds": bonds,
            "cells": cells, "per_cell": per_cell}


def check_relaxation(args, work, rings):
    data, printed = relax(args, work, rings, "tissue.data", args.np)
    m = measure(args, work, data)
    check(m["cells"] == CELLS, f"the data file reads back: {m['cells']:g} cells")
    check(abs(m["P"] / P_JAM - 1) < 1e-4, f"P at P_jam: P/P_jam - 1 = {m['P'] / P_JAM - 1:.2e}")
    check(m["phi_patch"] > 0.85, f"confluent: phi_patch {m['phi_patch']:.4f} > 0.85")
    check(m["bonds"] > 0 and len(m["per_cell"]) == CELLS and
          all(count > 0 and len(partners) > 0 and c not in partners
              for c, (count, partners) in m["per_cell"].items()),
          f"{m['bonds']:g} adhesive bonds, every cell bonded to others: bonds per cell "
          f"{[count for count, _ in m['per_cell'].values()]}")
    check(printed["bonds"] == m["bonds"] and abs(printed["phi_patch"] - m["phi_patch"]) < 1e-4,
          f"read back as printed: bonds {printed['bonds']:g}, phi_patch {printed['phi_patch']}")


BAD = [(["--cells", "3"], "--cells must be at least 4", "3"),
       (["--vertices", "5"], "--vertices", "5"),
       (["--calA0", "0.9"], "--calA0", "0.9"),
       (["--polydispersity", "0.7"], "--polydispersity", "0.7"),
       (["--pressure=-1e-6"], "--pressure", "-1e-06"),
       (["--pack-pressure", "0"], "--pack-pressure", "0.0"),
       (["--start-phi", "0.99"], "--start-phi", "0.99"),
       (["--lloyd=-1"], "--lloyd", "-1"),
       (["--lmp", "/nonexistent/lmp"], "--lmp", "/nonexistent/lmp")]


def check_arguments(work):
    for extra, what, value in BAD:
        argv = [sys.executable, TOOL, os.path.join(work, "bad.data"), "--cells", "8"] + extra
        r = subprocess.run(argv, capture_output=True, text=True)
        check(r.returncode == 2 and what in r.stderr and value in r.stderr,
              f"{' '.join(extra)} refused (exit {r.returncode}): "
              f"{r.stderr.strip().splitlines()[-1]}")


def main():
    args = parse_lmp_arguments(__doc__)
    with tempfile.TemporaryDirectory() as work:
        rings = check_seeding(work)
        check_polydisperse(work)
        check_relaxation(args, work, rings)
        if args.np == 1:
            check_arguments(work)
    if failures:
        sys.exit(f"check_make_tissue: {len(failures)} checks failed")
    print("check_make_tissue: all checks passed")


if __name__ == "__main__":
    main()
