#!/usr/bin/env python3
"""Interpenetrating cells after the first growth step at Fig 5's bending stiffnesses: the
published code against the package, from the same tissue.

    low_bending.py BINARY [--lmp build/lmp] [--work DIR] [--out low_bending.csv]

BINARY is the driver build.sh made. From tissue_N16.data (through make_input.py), with Fig 5's
base set (beta 100, theta0_min -3 pi/20) at P0 = 1e-5 (the pressure of fig5_coarse.sweep) and
eps_b each value of EPS_B:

  * published: the driver's frame 1 (run.py --steps 1: the relaxed input grown once and
    minimized at P0; no bond breaks before it, so the seed does not matter), measured by
    in.measure;
  * package_published_rules: in.mesophyll's minimum 2 (-var steps 2) with the driver's cycle
    (rules published, break_start 2, steer mass);
  * package_sweep: the same with the protocol fig5_coarse.sweep ran (in.mesophyll's defaults:
    its parameter set's rules code, break_start 1, steer force).

Each row gives phi_patch, calA and z of that state and the pairs of cells whose outlines
overlap as fix dpoly/check counts them (and the first pair it names).
"""
import os
import re
import sys

import same_tissue

EPS_B = ("0.01", "0.03", "0.1", "0.4", "0.6")
COLUMNS = ["eps_b", "code", "phi_patch", "calA", "z", "interpenetrating_pairs", "first_pair"]
PAIRS = re.compile(r"(\d+) pairs of cells interpenetrate \(first: cells (\d+) and (\d+)\)")
PROGRESS = re.compile(r"^growth step 2/2: .* phi_patch (\S+) <calA> (\S+) <z> (\S+)")


def pairs_in(line):
    """(count, 'a-b') of fix dpoly/check's line, (0, '') where it names none."""
    m = PAIRS.search(line or "")
    return (int(m.group(1)), f"{m.group(2)}-{m.group(3)}") if m else (0, "")


def published(binary, lmp, work, eps_b):
    folder = f"published_{eps_b}"
    rows = same_tissue.published(binary, lmp, work, folder, "20261122",
                                 ["--steps", "1", "--set", f"kb0={eps_b}"])
    frame = next(r for r in rows if r["growth_steps"] == "1")
    # in.measure's fix dpoly/check lines, one per frame: the last is frame 1's
    checks = [line for line in open(os.path.join(work, folder, "log.measure"))
              if line.startswith("fix dpoly/check:")]
    count, first = pairs_in(checks[-1])
    if count != int(frame["interpenetrating_pairs"]):
        sys.exit(f"{work}/{folder}: the check line and the CSV disagree on the pairs")
    return [frame["phi_patch"], frame["calA"], frame["z"], count, first]


def package(lmp, work, eps_b, mode):
    folder = same_tissue.package(lmp, work, f"{mode}_{eps_b}", mode,
                                 {"eps_b": eps_b, "steps": "2"})
    log = open(os.path.join(folder, "log.lammps")).read().splitlines()
    state = next(PROGRESS.match(line).groups() for line in log if PROGRESS.match(line))
    check = next(line for line in log if line.startswith("fix dpoly/check: minimum 2 "))
    return list(state) + list(pairs_in(check))


def main():
    p = same_tissue.arguments(__doc__, "low_bending")
    a = p.parse_args()
    lmp, binary = os.path.abspath(a.lmp), os.path.abspath(a.binary)
    same_tissue.driver_input(a.work)
    rows = []
    for eps_b in EPS_B:
        rows.append([eps_b, "published"] + published(binary, lmp, a.work, eps_b))
        for mode in same_tissue.PACKAGE_MODES:
            rows.append([eps_b, mode] + package(lmp, a.work, eps_b, mode))
        print(f"eps_b {eps_b}: done", flush=True)
    same_tissue.write_csv(a.out, COLUMNS, rows)
    width = max(len(c) for c in same_tissue.PACKAGE_MODES)
    print(f"{'eps_b':6} {'code':{width}} phi_patch calA   z     pairs (first)")
    for r in rows:
        print(f"{r[0]:6} {r[1]:{width}} {float(r[2]):.4f}    {float(r[3]):.4f} "
              f"{float(r[4]):.3f} {r[5]} ({r[6] or '-'})")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
