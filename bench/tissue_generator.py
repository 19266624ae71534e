#!/usr/bin/env python3
"""Compare the fast tissue generator with in.make_tissue: time and the tissues it makes.

    bench/tissue_generator.py [--lmp build/lmp] [--sizes 16 64] [--seeds 1 2 3 4]
                              [--old-sizes 16] [--old-seeds 11 13] [--old-csv FILE]
                              [--large 1024] [--csv bench/results/tissue_generator.csv]

For each size and seed, tools/make_tissue.py (Voronoi-seeded rings relaxed by
examples/tissue/in.relax_tissue, one rank) makes a tissue; examples/tissue/in.make_tissue (random
rings compressed in 1% steps) makes one for every --old-seeds at each --old-sizes (16 cells by
default); the shipped tissue_N16.data (seed 7), tissue_N32.data (seed 7) and tissue_N64.data
(seed 3) join them without a time (made before), each where its size is among --sizes or
--old-sizes.
Every tissue is then measured the same way, by one `run 0` with the main example's styles:
phi_patch, mean calA, mean z, adhesive bonds per cell, pressure. CPU seconds are those of the
processes (make_tissue.py with its LAMMPS run, or lmp), from getrusage. --old-csv reuses the
in.make_tissue rows of an earlier CSV (they take minutes each); --large N adds one generator run
at N cells (seed 1). Prints a table with the mean and spread per group, writes the CSV and a PNG
(one panel per measure, one column of points per group). Not a test; record the machine.
"""
import argparse
import csv
import os
import platform
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
import mesophyll_frames  # noqa: E402
import mesophyll_run  # noqa: E402
from regression import tissue_commands  # noqa: E402

mesophyll_frames.require(["numpy", "matplotlib"])
import numpy as np  # noqa: E402

TISSUE = os.path.join(ROOT, "examples", "tissue")
GENERATOR = os.path.join(ROOT, "tools", "make_tissue.py")
MEASURES = ["phi_patch", "calA", "z", "bonds_per_cell", "P"]
SHIPPED = {16: 7, 32: 7, 64: 3}    # examples/tissue/tissue_N<cells>.data: the seed it was made with
FIELDS = ["method", "cells", "seed", "cpu_s", "wall_s", "phi", "phi_patch", "calA", "z",
          "bonds_per_cell", "P"]
MEASURE_INPUT = """compute tissue all dpoly/tissue
thermo_style custom step press c_tissue[1] c_tissue[2] c_tissue[3] c_tissue[4] &
             c_tissue[5] c_tissue[6]
thermo_modify norm no format float %.12g
run 0 post no
"""


def timed(command, cwd):
    cpu, wall = mesophyll_run.children_cpu_seconds(), time.perf_counter()
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"tissue_generator: {' '.join(command)} failed:\n{result.stdout[-3000:]}"
                 f"{result.stderr[-3000:]}")
    return mesophyll_run.children_cpu_seconds() - cpu, time.perf_counter() - wall


def measure(lmp, data, workdir):
    """The tissue measures of a data file, all tissues alike (one run 0)."""
    path = os.path.join(workdir, "in.measure")
    with open(path, "w") as f:
        f.write(tissue_commands(os.path.abspath(data)) + MEASURE_INPUT)
    result = subprocess.run([lmp, "-in", path, "-log", "none", "-echo", "none"], cwd=workdir,
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"tissue_generator: measuring {data} failed:\n{result.stdout[-2000:]}")
    lines = result.stdout.splitlines()
    k = next(i for i, line in enumerate(lines) if line.split()[:2] == ["Step", "Press"])
    _, press, phi, phi_patch, calA, z, bonds, cells = (float(v) for v in lines[k + 1].split())
    return {"phi": phi, "phi_patch": phi_patch, "calA": calA, "z": z,
            "bonds_per_cell": bonds / cells, "P": press, "cells": int(cells)}


def generator_row(args, cells, seed, workdir):
    out = os.path.join(workdir, f"gen_N{cells}_s{seed}.data")
    cpu, wall = timed([sys.executable, GENERATOR, out, "--cells", str(cells), "--seed", str(seed),
                       "--lmp", args.lmp], workdir)
    row = {"method": "make_tissue.py", "seed": seed, "cpu_s": cpu, "wall_s": wall}
    row.update(measure(args.lmp, out, workdir))
    return row


def old_row(args, cells, seed, workdir):
    out = os.path.join(workdir, f"old_N{cells}_s{seed}.data")
    cpu, wall = timed([args.lmp, "-in", os.path.join(TISSUE, "in.make_tissue"), "-var", "N",
                       str(cells), "-var", "seed", str(seed), "-var", "out", out, "-log", "none",
                       "-screen", "none"], TISSUE)
    row = {"method": "in.make_tissue", "seed": seed, "cpu_s": cpu, "wall_s": wall}
    row.update(measure(args.lmp, out, workdir))
    return row


def shipped_row(args, cells, seed, workdir):
    row = {"method": "in.make_tissue", "seed": seed, "cpu_s": "", "wall_s": ""}
    row.update(measure(args.lmp, os.path.join(TISSUE, f"tissue_N{cells}.data"), workdir))
    return row


def summary(rows):
    groups = {}
    for r in rows:
        groups.setdefault((r["method"], int(r["cells"])), []).append(r)
    print(f"{'method':16s} {'cells':>5s} {'tissues':>7s} {'CPU s':>14s} " +
          " ".join(f"{m:>20s}" for m in MEASURES))
    for (method, cells), group in sorted(groups.items(), key=lambda g: (g[0][1], g[0][0])):
        cpu = [float(r["cpu_s"]) for r in group if r["cpu_s"] != ""]
        cpu_text = f"{min(cpu):.1f}-{max(cpu):.1f}" if cpu else "-"
        cols = []
        for m in MEASURES:
            v = np.array([float(r[m]) for r in group])
            cols.append(f"{v.mean():.4g} ({v.min():.4g}-{v.max():.4g})" if m != "P" else
                        f"{v.mean():.2g} ({v.min():.2g}-{v.max():.2g})")
        print(f"{method:16s} {cells:5d} {len(group):7d} {cpu_text:>14s} " +
              " ".join(f"{c:>20s}" for c in cols))
    return groups


def plot(groups, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    keys = sorted(groups, key=lambda g: (g[1], g[0]))
    labels = [f"{method}\n{cells} cells" for method, cells in keys]
    names = {"phi_patch": "phi_patch", "calA": "mean calA", "z": "mean z",
             "bonds_per_cell": "adhesive bonds per cell", "P": "pressure", "cpu_s": "CPU s"}
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    for ax, m in zip(axes.flat, MEASURES + ["cpu_s"]):
        for k, key in enumerate(keys):
            v = [float(r[m]) for r in groups[key] if r[m] != ""]
            colour = "tab:blue" if key[0] == "make_tissue.py" else "tab:orange"
            ax.plot([k] * len(v), v, "o", color=colour, alpha=0.7)
        ax.set_xticks(range(len(keys)))
        ax.set_xticklabels(labels, fontsize=7)
        ax.set_title(names[m])
        if m in ("P", "cpu_s"):
            ax.set_yscale("log")
    fig.suptitle("Initial tissues: tools/make_tissue.py (blue) against in.make_tissue (orange)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--sizes", type=int, nargs="*", default=[16, 64])
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4])
    p.add_argument("--old-sizes", type=int, nargs="*", default=[16])
    p.add_argument("--old-seeds", type=int, nargs="*", default=[11, 13])
    p.add_argument("--old-csv", default=None,
                   help="take the in.make_tissue rows from this CSV instead of rerunning them")
    p.add_argument("--large", type=int, default=0, help="one generator run at this many cells")
    p.add_argument("--csv", default=os.path.join(HERE, "results", "tissue_generator.csv"))
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        if args.old_csv:
            with open(args.old_csv) as f:
                rows += [r for r in csv.DictReader(f) if r["method"] == "in.make_tissue"]
        else:
            rows += [shipped_row(args, cells, seed, work) for cells, seed in SHIPPED.items()
                     if cells in args.sizes + args.old_sizes]
            for cells in args.old_sizes:
                for seed in args.old_seeds:
                    rows.append(old_row(args, cells, seed, work))
                    print(f"in.make_tissue N{cells} seed {seed}: {rows[-1]['cpu_s']:.1f} CPU s",
                          flush=True)
        for cells in args.sizes + ([args.large] if args.large else []):
            for seed in (args.seeds if cells != args.large else [1]):
                rows.append(generator_row(args, cells, seed, work))
                print(f"make_tissue.py N{cells} seed {seed}: {rows[-1]['cpu_s']:.1f} CPU s, "
                      f"phi_patch {rows[-1]['phi_patch']:.4f}", flush=True)
    os.makedirs(os.path.dirname(args.csv), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    print(f"machine: {platform.node()}, {os.cpu_count()} cores, one rank per run")
    groups = summary(rows)
    png = os.path.splitext(args.csv)[0] + ".png"
    plot(groups, png)
    print(f"wrote {args.csv} and {png}")


if __name__ == "__main__":
    main()
