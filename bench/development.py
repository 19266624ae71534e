#!/usr/bin/env python3
"""Benchmark the growth protocol: wall time and minimizer iterations per growth step.

    bench/development.py [--lmp build/lmp] [--cells 16 64] [--ranks 1 2] [--steps 11]
                         [--refine published] [--csv bench/results/development.csv] [--mpirun CMD]

Runs examples/mesophyll/in.mesophyll (default parameter set, min_style fire/nph) for each number
of cells and MPI ranks, one after the other, with vertex insertion by fix dpoly/refine rules --refine
(the example's published; none: no insertion), and writes one CSV row per growth step: cells, ranks, refine, step,
phi_patch, mean calA, vertices, iterations, force evaluations, minimization wall time (LAMMPS's
"Loop time"). Prints a summary per run with the published code's figures beside it. Not a
test: run it on an otherwise idle machine and record the machine with the figures. Standard
library only.
"""
import argparse
import csv
import os
import platform
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_run  # noqa: E402

# The figures for the published code (FIRE, N = 16, this kind of machine)
PUBLISHED = "published code, N = 16: 3e3 -> 1e5 FIRE iterations per growth step, " \
            "about 5.4 min for the first 11 growth steps (phi 0.93 -> 0.49)"


def run(args, cells, ranks, workdir):
    result = mesophyll_run.run(args.lmp, "in.mesophyll", workdir,
                               {"N": cells, "steps": args.steps, "refine": args.refine},
                               ranks=ranks, log="log.bench", mpirun=args.mpirun)
    growth = result.growth[cells]
    loops = mesophyll_run.minimization_loops(result.loops)
    rows = []
    for k in range(len(growth["step"])):
        loop, (iterations, evaluations) = loops[k], result.minimizations[k]
        rows.append({"cells": cells, "ranks": ranks, "refine": args.refine,
                     "step": int(growth["step"][k]), "phi_patch": growth["phi_patch"][k],
                     "calA": growth["calA"][k], "vertices": loop.atoms,
                     "iterations": iterations, "force_evaluations": evaluations,
                     "wall_s": loop.seconds})
    return rows, result.wall


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--cells", type=int, nargs="+", default=[16, 64])
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    p.add_argument("--steps", type=int, default=11)
    p.add_argument("--refine", default="published",
                   help="fix dpoly/refine rules (published, consistent, tension); none: no insertion")
    p.add_argument("--csv", default=os.path.join(HERE, "results", "development.csv"))
    p.add_argument("--mpirun", default=None,
                   help="MPI launcher (default $MESOPHYLL_MPIRUN, else mpirun: tools/mpi_launcher.py)")
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)

    print(f"machine: {platform.node()}, {os.cpu_count()} cores, {platform.processor() or platform.machine()}")
    print(f"{'cells':>5} {'ranks':>5} {'steps':>5} {'phi_patch':>17} {'iterations/step':>22} "
          f"{'minimize s':>10} {'total s':>8} {'us/(iter vertex)':>16}")
    all_rows = []
    for cells in args.cells:
        for ranks in args.ranks:
            with tempfile.TemporaryDirectory() as workdir:
                rows, total = run(args, cells, ranks, workdir)
            all_rows += rows
            iters = [r["iterations"] for r in rows]
            wall = sum(r["wall_s"] for r in rows)
            per = 1e6 * wall / sum(r["iterations"] * r["vertices"] for r in rows)
            print(f"{cells:5d} {ranks:5d} {len(rows):5d} {rows[0]['phi_patch']:7.3f} -> "
                  f"{rows[-1]['phi_patch']:6.3f} {min(iters):7d} .. {max(iters):6d} "
                  f"(mean {sum(iters) // len(iters):6d}) {wall:10.1f} {total:8.1f} {per:16.3f}")
    print(PUBLISHED)

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(all_rows[0].keys()))
        writer.writeheader()
        writer.writerows(all_rows)
    print(f"wrote {args.csv}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
