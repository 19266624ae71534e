#!/usr/bin/env python3
"""Where the FIRE iterations of a growth step go: the force against the iteration, by size.

    bench/force_tail.py [--lmp build/lmp] [--cells 64 256 1024] [--every 50]
                        [--fnorm two] [--ftol 1e-10] [--accept 64]
                        [--base examples/tissue/voronoi_N64.data] [--keep DIR]
                        [--csv bench/results/force_tail.csv] [--png bench/results/force_tail.png]

Each tissue (N = 64 k^2 cells: k x k periodic copies of --base, as bench/scaling.py makes them)
runs the main example's setup (examples/mesophyll/in.mesophyll -var setup_only yes), then two
minimizations, the relaxation to P0 and growth step 1, with a thermo row every --every
iterations (force 2-norm of the vertices, pressure, area). Per row: LAMMPS's 2-norm with the box
term, sqrt(|f|^2 + (2 V (P - P0))^2), and the root mean square force per degree of freedom,
sqrt((|f|^2 + (2 L (P - P0))^2) / (2 vertices + 1)), the force on the box length counted as one
more degree of freedom (fire/nph's min_modify rms yes).

Reported per size: the growth step's iterations, the iteration at which the root mean square
first falls below thresholds 1e-9 ... 1e-12 and below the value at which the --accept-cell run's
growth step stopped (the accuracy that size already accepts), and how many iterations came after
it. Prints a table, writes the CSV (one row per size and threshold) and a PNG (root mean square
against iteration). Iteration counts do not depend on the machine's load. Not a test.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_frames  # noqa: E402

mesophyll_frames.require(["matplotlib"])

P0 = 1.0e-3    # the default parameter set's pressure
THRESHOLDS = [1e-9, 1e-10, 1e-11, 1e-12]
PROBE = """# the main example's setup, then the relaxation and growth step 1 with the force logged
include         in.mesophyll
thermo_style    custom step pe press vol fnorm fmax c_tissue[2] atoms
thermo_modify   norm no format float %.10g
thermo          ${every}
minimize        0.0 ${ftol} ${maxiter} 2000000
minimize        0.0 ${ftol} ${maxiter} 2000000
"""


def tissue(base, cells, work):
    k = math.isqrt(cells // 64)
    if k * k * 64 != cells:
        sys.exit(f"force_tail: {cells} cells is not 64 k^2")
    if k == 1:
        return os.path.abspath(base)
    path = os.path.join(work, f"N{cells}.data")
    if not os.path.exists(path):
        subprocess.run([sys.executable, os.path.join(ROOT, "tools", "replicate_tissue.py"), base,
                        path, "--copies", str(k), str(k)], check=True, stdout=subprocess.DEVNULL)
    return path


def run(args, cells, work):
    """The log of the probe of cells (run unless --keep holds a finished one)."""
    log = os.path.join(work, f"log.probe{cells}")
    if os.path.exists(log) and "Total wall time" in open(log).read():
        print(f"(read the finished probe {log})", flush=True)
        return log
    data = tissue(args.base, cells, work)
    example = os.path.join(ROOT, "examples", "mesophyll")
    for name in ("in.mesophyll", "arabidopsis.mesophyll"):
        with open(os.path.join(example, name)) as src, open(os.path.join(work, name), "w") as dst:
            dst.write(src.read())
    with open(os.path.join(work, "in.probe"), "w") as f:
        f.write(PROBE)
    command = [args.lmp, "-in", "in.probe", "-var", "setup_only", "yes", "-var", "N", str(cells),
               "-var", "tissue", data, "-var", "every", str(args.every), "-var", "fnorm",
               args.fnorm, "-var", "ftol", repr(args.ftol), "-log", log, "-screen", "none"]
    if subprocess.run(command, cwd=work).returncode != 0:
        sys.exit(f"force_tail: {' '.join(command)} failed (see {log})")
    return log


def tables(log):
    """Thermo tables of the two minimizations: lists of dicts."""
    out, rows, header = [], None, None
    for line in open(log):
        words = line.split()
        if words[:1] == ["Step"]:
            header = words if "Atoms" in words else None
            rows = [] if header else None
            if header:
                out.append(rows)
        elif words[:1] == ["Loop"]:
            rows = None
        elif rows is not None and len(words) == len(header):
            try:
                rows.append(dict(zip(header, map(float, words))))
            except ValueError:
                pass
    return out


def norms(row):
    dof = 2 * row["Atoms"]
    pressure = row["Press"] - P0
    two = math.hypot(row["Fnorm"], 2 * row["Volume"] * pressure)
    rms = math.sqrt((row["Fnorm"] ** 2 + (2 * math.sqrt(row["Volume"]) * pressure) ** 2)
                    / (dof + 1))
    return two, rms


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--cells", type=int, nargs="+", default=[64, 256, 1024])
    p.add_argument("--every", type=int, default=50)
    p.add_argument("--fnorm", choices=["two", "rms"], default="two")
    p.add_argument("--ftol", type=float, default=1e-10)
    p.add_argument("--accept", type=int, default=64,
                   help="the size whose final root mean square is the accepted accuracy")
    p.add_argument("--base", default=os.path.join(ROOT, "examples", "tissue",
                                                  "voronoi_N64.data"))
    p.add_argument("--keep", default=None, help="work folder; finished probes there are read")
    p.add_argument("--csv", default=os.path.join(HERE, "results", "force_tail.csv"))
    p.add_argument("--png", default=os.path.join(HERE, "results", "force_tail.png"))
    args = p.parse_args()
    if args.every < 1 or not args.ftol > 0.0:
        p.error("--every and --ftol must be positive")
    if args.accept not in args.cells:
        p.error(f"--accept {args.accept} must be one of --cells")
    args.lmp = os.path.abspath(args.lmp)
    work = os.path.abspath(args.keep or os.path.join(ROOT, "build", "force_tail"))
    os.makedirs(work, exist_ok=True)

    steps = {}
    for cells in args.cells:
        minimizations = tables(run(args, cells, work))
        if len(minimizations) < 2:
            sys.exit(f"force_tail: the probe of {cells} cells has {len(minimizations)} tables")
        growth = minimizations[1]
        first = growth[0]["Step"]
        steps[cells] = [(row["Step"] - first,) + norms(row) for row in growth]
    accepted = steps[args.accept][-1][2]

    rows = []
    print(f"growth step 1 ({args.fnorm} ftol {args.ftol:g}); the {args.accept}-cell step stops at "
          f"a root mean square of {accepted:.3g}")
    print(f"{'cells':>6} {'iterations':>10} " + " ".join(f"{'rms<' + format(t, 'g'):>11}"
                                                        for t in THRESHOLDS + [accepted])
          + f" {'after it':>9}")
    for cells in args.cells:
        total = int(steps[cells][-1][0])
        reached = []
        for t in THRESHOLDS + [accepted]:
            hit = next((int(it) for it, _, r in steps[cells] if r <= t * (1 + 1e-12)), None)
            reached.append(hit)
            rows.append({"cells": cells, "iterations": total, "threshold_rms": f"{t:.4g}",
                         "first_iteration_below": "" if hit is None else hit,
                         "iterations_after": "" if hit is None else total - hit,
                         "note": f"accepted by {args.accept} cells" if t == accepted else ""})
        after = "" if reached[-1] is None else total - reached[-1]
        print(f"{cells:>6} {total:>10} " + " ".join(f"{'-' if h is None else h:>11}"
                                                    for h in reached) + f" {after:>9}")

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        w = csv.DictWriter(f, ["cells", "iterations", "threshold_rms", "first_iteration_below",
                               "iterations_after", "note"])
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for cells in args.cells:
        ax.semilogy([s[0] for s in steps[cells]], [s[2] for s in steps[cells]],
                    label=f"{cells} cells")
    ax.axhline(accepted, color="k", ls="--", lw=0.8,
               label=f"where {args.accept} cells stop ({accepted:.2g})")
    ax.set_xlabel("FIRE iteration of growth step 1")
    ax.set_ylabel("root mean square force per degree of freedom")
    ax.set_title(f"growth step 1, stopping rule {args.fnorm} ftol {args.ftol:g}")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.csv} and {args.png}; probes in {work}")


if __name__ == "__main__":
    main()
