#!/usr/bin/env python3
"""Fig 4's failing points with vertices inserted on preferred lengths right after growth: do the
runs stay clean? The package alone, fig4.sweep's protocol with one variable changed.

    refine_preferred.py [--lmp build/lmp] [--work DIR] [--out refine_preferred.csv] [--jobs 2]
                        [--tissues tissue_N16 voronoi_N16] [--points 7x0.5 10x0.5 ...]

growth_per_step.py traced the failures of fig4.sweep's runs (interpenetrating cells) to the first
growth step, which stretches void segments' preferred lengths l0 to more than about 2.2 vertex
diameters before any vertex is inserted: insertion (fix dpoly/refine) measures segments at the
minimum, so it splits them only after minimum 2 is over. in.mesophyll's -var refine_measure
preferred (fix dpoly/refine measure preferred timing after_growth start 1) measures them by l0 right
after each growth step, the first included, so that minimum 2 starts from split segments. That is
not the published code. At each point of POINTS (every grid point of fig4.sweep with a failed run:
all five seeds at (7, 0.5), (10, 0.5), (7, 0.75) and (10, 0.75), seed 2 at (5, 0.75)) and at the
base (5, 0.5), where every run of the sweeps is clean (what the change does there), each seed of
growth_per_step.SEEDS and each tissue given, a whole run of fig4.sweep's protocol (its step cap and
phi_stop, P0 1e-6, ftol 1e-11, tmaxadapt yes) with refine_measure preferred, two at a time (--jobs;
--tissues and --points choose among them; a run that finished in --work with the same command is
read, not run again). Per run: growth steps, phi_patch and mean calA at the end, the largest
l0/sigma as minimum 2 starts (now after the first insertion), the vertices then and at the end, the
minima checked, those with interpenetrating cells and the first, the other failed checks (as
growth_per_step_runs.csv counts them), delta_A early and late as tools/sweep.py summary computes
them (the paper's text as reference), and the loop time.
"""
import argparse
import os
import re
import sys

import same_tissue
from growth_per_step import SEEDS, TISSUES, run_to_end, stretch_by_cell, whole_run_outcome

sys.path.insert(0, os.path.join(same_tissue.ROOT, "tools"))
from mesophyll_frames import read_frames  # noqa: E402
from mesophyll_run import growth_table  # noqa: E402
from sweep import DEFAULT_REFERENCE, delta_A, read_reference  # noqa: E402

POINTS = {"7x0.5": ("7", "0.5"), "10x0.5": ("10", "0.5"), "7x0.75": ("7", "0.75"),
          "10x0.75": ("10", "0.75"), "5x0.75": ("5", "0.75"), "5x0.5": ("5", "0.5")}
REFERENCE = read_reference(DEFAULT_REFERENCE, 0.25)    # tools/sweep.py summary's default
COLUMNS = ["tissue", "lambda_x_delta_a", "seed", "growth_steps", "phi_patch_end", "minima",
           "minima_interpenetrating", "first_minimum_interpenetrating", "other_failed_checks",
           "calA_end", "largest_l0_over_sigma", "vertices_at_minimum_2", "vertices_end",
           "delta_A_early", "delta_A_late", "loop_s"]
LOOP = re.compile(r"^Loop time of (\S+)", re.MULTILINE)


def run(args, tissue, point, seed):
    folder = run_to_end(args, f"refine_preferred_{tissue}_{point}_seed{seed}", tissue,
                        *POINTS[point], seed, extra={"refine_measure": "preferred"}, resume=True)
    growth = growth_table(os.path.join(folder, "growth.N16.txt"))
    frames = read_frames(os.path.join(folder, "cells.N16.dump"))
    first = next(frames)
    last = first
    for last in frames:
        pass
    log = open(os.path.join(folder, "log.lammps")).read()
    print(f"{tissue} {point} seed {seed}: done", flush=True)
    calA_end = f"{growth['calA'][-1]:.4f}" if growth["step"] else ""
    # as tools/sweep.py summary computes them for a sweep's run
    early, late = (delta_A(growth, REFERENCE, stage)[0] if growth["step"] else None
                   for stage in ("early", "late"))
    return [tissue, point, seed] + whole_run_outcome(folder) + [
        calA_end, f"{max(stretch_by_cell(folder).values()):.4f}", len(first.mol), len(last.mol),
        "" if early is None else f"{early:.6g}", "" if late is None else f"{late:.6g}",
        f"{sum(float(t) for t in LOOP.findall(log)):.1f}"]


def main():
    p = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    p.add_argument("--lmp", default=os.path.join(same_tissue.ROOT, "build", "lmp"))
    p.add_argument("--work", default="/tmp/refine_preferred")
    p.add_argument("--out", default=os.path.join(same_tissue.HERE, "refine_preferred.csv"))
    p.add_argument("--jobs", type=int, default=2, help="runs at a time (one core each)")
    p.add_argument("--tissues", nargs="+", default=list(TISSUES), choices=list(TISSUES))
    p.add_argument("--points", nargs="+", default=list(POINTS), choices=list(POINTS))
    args = p.parse_args()
    if args.jobs < 1:
        p.error(f"--jobs must be at least 1, got {args.jobs}")
    jobs = [(tissue, point, seed) for tissue in args.tissues for point in args.points
            for seed in SEEDS]
    rows = same_tissue.run_all(args.jobs, lambda job: run(args, *job), jobs)
    same_tissue.write_csv(args.out, COLUMNS, rows)
    for tissue in args.tissues:
        for point in args.points:
            group = [r for r in rows if r[:2] == [tissue, point]]
            print(f"{tissue} {point}: minima with interpenetrating cells "
                  f"{[r[6] for r in group]}, other failed checks {[r[8] for r in group]}, "
                  f"growth steps {[r[3] for r in group]}")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
