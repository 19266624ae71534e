#!/usr/bin/env python3
"""The growth loop of examples/mesophyll/in.mesophyll, driven from Python through LAMMPS's own
Python module, with the per-cell values of compute dpoly/tissue read at every growth step.

    build/venv/bin/python examples/python/grow_tissue.py [--cells 16|64] [--steps K] [--out DIR]

(`tools/setup.sh --python` makes build/venv: LAMMPS's `lammps` package from its source tree,
loading the build's liblammps.so.) LAMMPS reads in.mesophyll with `-var setup_only yes`: the
tissue, the styles, the stages (check, break, grow, refine) and the computes, but not its loop.
This script then runs the loop: one `minimize` per growth step, after which the stages act as in
the input. At each minimum it reads through the library interface the global vector of compute
dpoly/tissue (phi, phi_patch, <calA>, <z>, bonds, cells) and its per-cell array (cell ID, area,
perimeter, calA, z, void fraction), the pressure and the minimizer's iterations (fix dpoly/check),
prints one line, and at the end writes

    DIR/cells_per_step.csv   one row per cell and growth step: step cell area perimeter calA z void
    DIR/growth.csv           one row per growth step: step P phi phi_patch calA z bonds
                             iterations (the input's growth table without dphi_plus)
    DIR/per_cell.png         calA, void fraction and area of every cell against growth step,
                             phi and phi_patch
    DIR/log.lammps           LAMMPS's log

The trajectory is the input's own: every minimization's thermo rows equal those of lmp running
in.mesophyll with the same variables, and the values read at each minimum equal the log's
(tests/test_python_module.py checks both). It runs --steps growth steps; unlike the input it does
not stop early when phi_patch falls below phi_stop. Needs numpy and matplotlib (Debian's
python3-numpy, python3-matplotlib; the virtual environment sees the system's packages).
"""
import argparse
import csv
import os
import sys

import numpy as np

try:
    from lammps import lammps, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY, LMP_TYPE_VECTOR
except ImportError:
    sys.exit("grow_tissue.py: no Python module 'lammps'; run tools/setup.sh --python and use "
             "build/venv/bin/python")

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "mesophyll")
CELL_COLUMNS = ["cell", "area", "perimeter", "calA", "z", "void"]    # compute dpoly/tissue array
GROWTH_COLUMNS = ["step", "P", "phi", "phi_patch", "calA", "z", "bonds", "iterations"]


def start(cells, out, variables):
    """LAMMPS with in.mesophyll set up and its loop left out; the log goes to out."""
    args = ["-nocite", "-screen", "none", "-log", os.path.join(out, "log.lammps"),
            "-var", "N", str(cells), "-var", "setup_only", "yes"]
    for name, value in variables:
        args += ["-var", name, value]
    lmp = lammps(cmdargs=args)
    cwd = os.getcwd()
    os.chdir(EXAMPLE)    # in.mesophyll reads its data and parameter files from its own folder
    try:
        lmp.file("in.mesophyll")
    finally:
        os.chdir(cwd)
    return lmp


def growth_step(lmp):
    """One growth step: minimize (the stages act after it), then what the minimum measured."""
    lmp.command("minimize 0.0 ${ftol} ${maxiter} 2000000")
    tissue = lmp.numpy.extract_compute("tissue", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)
    per_cell = np.array(lmp.numpy.extract_compute("tissue", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY))
    iterations = lmp.extract_fix("check", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, 5)
    summary = {"P": lmp.get_thermo("press"), "phi": tissue[0], "phi_patch": tissue[1],
               "calA": tissue[2], "z": tissue[3], "bonds": tissue[4], "iterations": iterations}
    if per_cell.shape != (int(tissue[5]), len(CELL_COLUMNS)):
        raise RuntimeError(f"compute dpoly/tissue's array is {per_cell.shape}, expected "
                           f"({int(tissue[5])}, {len(CELL_COLUMNS)})")
    return summary, per_cell


def write_tables(out, summaries, arrays):
    with open(os.path.join(out, "growth.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(GROWTH_COLUMNS)
        for k, s in enumerate(summaries, start=1):
            w.writerow([k] + [repr(float(s[c])) for c in GROWTH_COLUMNS[1:]])
    with open(os.path.join(out, "cells_per_step.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["step"] + CELL_COLUMNS)
        for k, array in enumerate(arrays, start=1):
            for row in array:
                w.writerow([k, int(row[0])] + [repr(float(v)) for v in row[1:]])


def plot(out, summaries, arrays):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator

    steps = np.arange(1, len(arrays) + 1)
    # cells keep their IDs and rows (sorted by ID) from step to step
    stacked = np.stack(arrays)    # step, cell, column
    fig, axes = plt.subplots(1, 4, figsize=(16, 3.6), constrained_layout=True)
    for ax, column, label in zip(axes, ["calA", "void", "area"],
                                 ["shape parameter calA", "void-facing fraction", "area"]):
        values = stacked[:, :, CELL_COLUMNS.index(column)]
        ax.plot(steps, values, color="tab:green", alpha=0.35, lw=0.8)
        ax.plot(steps, values.mean(axis=1), color="black", lw=2, label="mean over cells")
        ax.set_xlabel("growth step")
        ax.set_ylabel(label)
        ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    axes[0].legend(frameon=False)
    axes[3].plot(steps, [s["phi"] for s in summaries], "o-", label="phi")
    axes[3].plot(steps, [s["phi_patch"] for s in summaries], "s-", label="phi_patch")
    axes[3].set_xlabel("growth step")
    axes[3].xaxis.set_major_locator(MaxNLocator(integer=True))
    axes[3].set_ylabel("packing fraction")
    axes[3].legend(frameon=False)
    fig.suptitle(f"{stacked.shape[1]} cells: one thin line per cell, read from compute "
                 "dpoly/tissue through LAMMPS's Python module")
    path = os.path.join(out, "per_cell.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cells", type=int, default=16, choices=[16, 64],
                        help="tissue_N16.data or tissue_N64.data (default 16)")
    parser.add_argument("--steps", type=int, default=5, help="growth steps (default 5)")
    parser.add_argument("--out", default=".", help="folder for the tables, plot and log")
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                        help="another variable of in.mesophyll, e.g. --var set beta30")
    args = parser.parse_args(argv)
    if args.steps < 1:
        parser.error(f"--steps must be at least 1, got {args.steps}")
    # growth_step() minimizes at ${ftol} itself; in.mesophyll's scaled tolerance is its own loop's
    if any(name == "ftol_scale" and value != "none" for name, value in args.var):
        parser.error("--var ftol_scale: only none here (growth_step minimizes at ${ftol})")
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)

    lmp = start(args.cells, out, args.var)
    summaries, arrays = [], []
    try:
        for k in range(1, args.steps + 1):
            summary, per_cell = growth_step(lmp)
            summaries.append(summary)
            arrays.append(per_cell)
            calA = per_cell[:, CELL_COLUMNS.index("calA")]
            print(f"growth step {k}/{args.steps}: P {summary['P']:.6g} phi {summary['phi']:.4f} "
                  f"phi_patch {summary['phi_patch']:.4f} calA per cell {calA.min():.3f}-"
                  f"{calA.max():.3f} (mean {calA.mean():.4f}) iterations "
                  f"{int(summary['iterations'])}", flush=True)
    finally:
        lmp.close()
    write_tables(out, summaries, arrays)
    png = plot(out, summaries, arrays)
    print(f"Tables: {out}/growth.csv, {out}/cells_per_step.csv; plot: {png}")


if __name__ == "__main__":
    main()
