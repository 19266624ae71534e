#!/usr/bin/env python3
"""Buckling before compaction: the Hessian's lowest mode at every minimum of a development.

    bench/buckling.py [--lmp build/lmp] [--set beta30] [--seed 20261122] [--cells 16]
                      [--steps 40] [--csv bench/results/buckling.csv]
                      [--png bench/results/buckling.png]

Runs examples/mesophyll/in.mesophyll with compute dpoly/hessian in its thermo output, so that the
Hessian (fixed box, every term of the model) is diagonalized at the last step of each
minimization, at the minimum and before the growth fix changes the preferred values. For every
growth step it records the lowest eigenvalue above the zero level (the two translations and any
other zero modes left out), the number of extra zero modes, and the compaction of that step,
delta_phi_plus(k) - delta_phi_plus(k-1). A cell that buckles softens one mode to zero before the
tissue compacts, so the step before each compaction should show a lower lowest eigenvalue than the
other steps of the same stage. The input's defaults apply (vertex insertion on).
Prints a table and a verdict, writes CSV and a PNG. Needs python3-numpy and python3-matplotlib.
"""
import argparse
import csv
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_run  # noqa: E402
MODES = 8           # eigenvalues reported per minimum
ZERO = 1.0e-8       # the compute's zero level
COMPACTION = 1e-3   # a step whose phi rises by more than this counts as a compaction


def minima_rows(thermo):
    """The last thermo row of every minimization: the state at the minimum."""
    return [dict(zip(columns, rows[-1])) for columns, rows in thermo if rows]


def lowest_nonzero(row):
    values = [row[f"c_hessian[{k}]"] for k in range(1, MODES + 1)]
    nonzero = [v for v in values if abs(v) > ZERO]
    return nonzero[0] if nonzero else float("nan")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--set", default="beta30", help="parameter set of arabidopsis.mesophyll")
    p.add_argument("--seed", default="20261122")
    p.add_argument("--cells", type=int, default=16)
    p.add_argument("--steps", type=int, default=40)
    p.add_argument("--csv", default=os.path.join(ROOT, "bench", "results", "buckling.csv"))
    p.add_argument("--png", default=os.path.join(ROOT, "bench", "results", "buckling.png"))
    args = p.parse_args()

    with tempfile.TemporaryDirectory() as work:
        work = mesophyll_run.scratch(os.path.join(work, "run"))
        path = os.path.join(work, "in.mesophyll")
        text = open(path).read()
        columns = " ".join(f"c_hessian[{k}]" for k in range(1, MODES + 1))
        text = text.replace("thermo_style    custom step pe press vol",
                            f"compute         hessian all dpoly/hessian modes {MODES} zero {ZERO}\n"
                            f"thermo_style    custom step pe press vol c_hessian {columns}")
        open(path, "w").write(text)
        result = mesophyll_run.run(os.path.abspath(args.lmp), "in.mesophyll", work,
                                   {"N": args.cells, "set": args.set, "seed": args.seed,
                                    "steps": args.steps}, example=None)
    minima = minima_rows(result.thermo)
    growth = result.growth[args.cells]

    steps = np.array(growth["step"]).astype(int)
    phi = np.array(growth["phi_patch"])
    compaction = np.diff(np.concatenate([[0.0], growth["dphi_plus"]]))
    lowest = np.array([lowest_nonzero(m) for m in minima[:len(steps)]])
    zero_modes = np.array([m["c_hessian"] for m in minima[:len(steps)]])

    rows = []
    print(" step  phi_patch  compaction  extra zero modes  lowest eigenvalue")
    for k in range(len(steps)):
        rows.append({"step": steps[k], "phi_patch": phi[k], "compaction": f"{compaction[k]:.6f}",
                     "zero_modes": int(zero_modes[k]), "lowest_eigenvalue": f"{lowest[k]:.6g}"})
        mark = "  <- compaction" if compaction[k] > COMPACTION else ""
        print(f"{steps[k]:5d}  {phi[k]:9.4f}  {compaction[k]:10.5f}  {int(zero_modes[k]):16d}  "
              f"{lowest[k]:17.6g}{mark}")

    # the step before a compaction against the steps before none, from the first compaction on
    # (the whole tissue softens as it opens, so earlier steps would compare stiff with soft)
    jumps = [k for k in range(1, len(steps)) if compaction[k] > COMPACTION]
    before = [lowest[k - 1] for k in jumps]
    quiet = [lowest[k - 1] for k in range(jumps[0] if jumps else 1, len(steps)) if k not in jumps]
    if jumps and quiet:
        print(f"from step {steps[jumps[0]]} on, lowest eigenvalue the step before a compaction: "
              f"median {np.median(before):.3g} ({len(before)} compactions); before the other "
              f"steps: median {np.median(quiet):.3g} ({len(quiet)} steps)")
    else:
        print("no compaction in this run: nothing to compare")

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(5.5, 5), sharex=True)
    top.semilogy(steps, np.abs(lowest), "o-", ms=3)
    top.set_ylabel("lowest nonzero eigenvalue")
    bottom.bar(steps, compaction, color="tab:red")
    bottom.set_ylabel(r"compaction $\Delta\delta\phi_+$")
    bottom.set_xlabel("growth step")
    for k in jumps:
        top.axvline(steps[k], color="tab:red", lw=0.6, ls=":")
    top.set_title(f"{args.set}, N = {args.cells}, seed {args.seed}", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.png, dpi=150)
    print(f"wrote {args.csv} and {args.png}")


if __name__ == "__main__":
    main()
