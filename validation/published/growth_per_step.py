#!/usr/bin/env python3
"""Interpenetrating cells after the first growth step across lambda delta_a: the published code
against the package, from the same tissue, between the products where every run of Fig 4's
sweeps passes (2.5 and below) and where nearly every one fails (3.5 and above); then the package
alone at the sweeps' five seeds from two tissues, with how far the first growth stretches the
rings' preferred segment lengths.

    growth_per_step.py BINARY [--lmp build/lmp] [--work DIR] [--out growth_per_step.csv]

The first growth step's void-run length growth is proportional to lambda delta_a. The same
comparison as high_lambda.py (same_tissue.compare_first_steps(): the driver's frame 1 and the
package's minimum 2 with the driver's cycle and with fig4.sweep's protocol at seed 1; Fig 4's
base set at P0 = 1e-6 from tissue_N16.data) at the points of POINTS, named lambda x delta_a:
products 2.75 to 3.25 along delta_a 0.5, the product 3 reached four ways, and (5, 0.75), where
1 of the sweeps' 5 runs fails. Then the package's minimum 2 with fig4.sweep's protocol at the
sweeps' five seeds (bonds break after minimum 1, so minimum 2 depends on the seed), at POINTS and
at ANCHORS (grid points whose sweeps all pass or all fail), from each tissue of TISSUES, into
growth_per_step_seeds.csv beside --out, with the largest ratio of a segment's preferred length
to the mean diameter of its two vertices as minimum 2 starts and, where cells interpenetrate, the
rank by that ratio (1: the most stretched cell) of the more stretched cell of the first pair.
Last, whole runs with fig4.sweep's protocol (its step cap and phi_stop) at WHOLE_RUNS, the points
where the seed decides whether minimum 2 has interpenetrating cells on either tissue, into
growth_per_step_runs.csv: whether the runs tangled at minimum 2 are the runs that fail, two at a
time.
"""
import os
import sys

import same_tissue
from high_lambda import SWEEP_SETTINGS    # the same package modes as high_lambda.py

sys.path.insert(0, os.path.join(same_tissue.ROOT, "tools"))
from mesophyll_frames import read_frames  # noqa: E402
from mesophyll_run import check_lines, growth_table  # noqa: E402
from sweep import SweepFile, step_cap     # noqa: E402

POINTS = {"5.5x0.5": ("5.5", "0.5"), "6x0.5": ("6", "0.5"), "6.5x0.5": ("6.5", "0.5"),
          "4x0.75": ("4", "0.75"), "5x0.6": ("5", "0.6"), "10x0.3": ("10", "0.3"),
          "5x0.75": ("5", "0.75")}
ANCHORS = {"10x0.1": ("10", "0.1"), "5x0.5": ("5", "0.5"), "7x0.5": ("7", "0.5"),
           "7x0.75": ("7", "0.75"), "10x0.5": ("10", "0.5")}
SEEDS = ("1", "2", "3", "4", "5")
# the sweeps' tissue (fig4.sweep) and a second one of 16 cells, made by tools/make_tissue.py
TISSUES = {"tissue_N16": same_tissue.TISSUE,
           "voronoi_N16": os.path.join(same_tissue.ROOT, "examples", "tissue", "voronoi_N16.data")}
# (tissue, point): run to the end at SEEDS; (5, 0.75) from tissue_N16 is fig4_part6's, a check,
# and (7, 0.5) from it is fig4_part3's
WHOLE_RUNS = [("tissue_N16", "5x0.75"), ("tissue_N16", "6.5x0.5"), ("tissue_N16", "10x0.3"),
              ("voronoi_N16", "5x0.75"), ("voronoi_N16", "6.5x0.5"), ("voronoi_N16", "7x0.5"),
              ("voronoi_N16", "10x0.3")]
FIG4 = SweepFile(os.path.join(same_tissue.ROOT, "examples", "sweep", "fig4.sweep"))


def grid_point(point):
    """(lambda, delta_a) of a point of POINTS or ANCHORS."""
    return POINTS[point] if point in POINTS else ANCHORS[point]


def package_variables(point, mode, seed=None):
    lam, delta_a = grid_point(point)
    variables = dict(SWEEP_SETTINGS[mode], **{"lambda": lam, "delta_a": delta_a})
    if seed:
        variables["seed"] = seed
    return variables


def stretch_by_cell(folder):
    """{cell (molecule ID): max over its segments of l0 / ((sigma_i + sigma_j)/2)} as minimum 2
    starts: in.mesophyll's first dump frame holds minimum 1's positions with the state after its
    break and the first growth (refine inserts nothing before minimum 2, but with -var
    refine_measure preferred, refine_preferred.py's runs, it inserts after that growth). Above 2
    a segment at its preferred length leaves a gap between its two disks wider than a vertex
    diameter."""
    frame = next(read_frames(os.path.join(folder, "cells.N16.dump")))
    sigma, l0 = frame.columns["d_sigma"], frame.columns["d_l0"]
    stretch = {}
    # l0 of a vertex belongs to the segment to its next vertex (c_vertex[3])
    for i, next_id in enumerate(frame.columns["c_vertex[3]"]):
        j = frame.row_of[int(next_id)]
        cell = int(frame.mol[i])
        stretch[cell] = max(stretch.get(cell, 0.0), l0[i] / (0.5 * (sigma[i] + sigma[j])))
    return stretch


def pair_rank(stretch, first_pair):
    """Rank by stretch (1: the most stretched cell) of the more stretched cell of first_pair
    ('a-b', or 'a-image' for a cell and its periodic image); '' where there is no pair."""
    if not first_pair:
        return ""
    ranked = sorted(stretch, key=stretch.get, reverse=True)
    return min(ranked.index(int(c)) + 1 for c in first_pair.split("-") if c != "image")


def seed_spread(args):
    """fig4.sweep's protocol at SEEDS from each tissue: one row per tissue, point and seed."""
    lmp = os.path.abspath(args.lmp)
    rows = []
    for tissue, path in TISSUES.items():
        for point in list(POINTS) + list(ANCHORS):
            for seed in SEEDS:
                folder = f"package_sweep_{tissue}_{point}_seed{seed}"
                state = same_tissue.package_first_step(
                    lmp, args.work, folder, "package_sweep",
                    package_variables(point, "package_sweep", seed), figure="fig4", tissue=path)
                stretch = stretch_by_cell(os.path.join(args.work, folder))
                rows.append([tissue, point, seed] + state[:3] +
                            [f"{max(stretch.values()):.4f}"] + state[3:] +
                            [pair_rank(stretch, state[4])])
            print(f"{tissue} {point} seeds {' '.join(SEEDS)}: pairs "
                  f"{[r[7] for r in rows[-len(SEEDS):]]}", flush=True)
    out = os.path.join(os.path.dirname(os.path.abspath(args.out)), "growth_per_step_seeds.csv")
    same_tissue.write_csv(out, ["tissue", "lambda_x_delta_a", "seed", "phi_patch", "calA", "z",
                                "largest_l0_over_sigma", "interpenetrating_pairs", "first_pair",
                                "first_pair_stretch_rank"],
                          rows)
    print(f"wrote {out}")


def run_to_end(args, folder, tissue, lam, delta_a, seed, extra=None, resume=False):
    """fig4.sweep's protocol to its end (its step cap and phi_stop) at (lam, delta_a) from
    TISSUES[tissue] into args.work/folder, with the in.mesophyll variables extra; the folder."""
    variables = dict(SWEEP_SETTINGS["package_sweep"], **{"lambda": lam, "delta_a": delta_a},
                     seed=seed, steps=str(step_cap(FIG4.growth, float(delta_a))),
                     phi_stop=FIG4.fixed["phi_stop"], **(extra or {}))
    return same_tissue.package(os.path.abspath(args.lmp), args.work, folder, "package_sweep",
                               variables, resume=resume, figure="fig4", tissue=TISSUES[tissue])


def whole_run(args, tissue, point, seed):
    """One run of fig4.sweep's protocol to its end: [tissue, point, seed, growth steps, phi_patch
    at the end, minima checked, minima with interpenetrating cells, the first of them, other
    failed checks]."""
    folder = run_to_end(args, f"whole_run_{tissue}_{point}_seed{seed}", tissue,
                        *grid_point(point), seed)
    return [tissue, point, seed] + whole_run_outcome(folder)


def whole_run_outcome(folder):
    """[growth steps, phi_patch at the end, minima checked, minima with interpenetrating cells,
    the first of them, other failed checks] of a finished run's folder."""
    checks = check_lines(open(os.path.join(folder, "log.lammps")).read())
    tangled = [c.minimum for c in checks if "cells interpenetrate" in c.problems]
    # checks that failed for anything besides interpenetrating cells
    others = [c for c in checks if c.failed and any(
        "cells interpenetrate" not in part for part in c.problems.split("; "))]
    growth = growth_table(os.path.join(folder, "growth.N16.txt"))
    phi_patch = f"{growth['phi_patch'][-1]:.6f}" if growth["step"] else ""  # in.mesophyll's %.6f
    return [len(growth["step"]), phi_patch, len(checks), len(tangled),
            tangled[0] if tangled else "", len(others)]


def whole_runs(args):
    """whole_run() at WHOLE_RUNS and SEEDS, two at a time, into growth_per_step_runs.csv."""
    jobs = [(tissue, point, seed) for tissue, point in WHOLE_RUNS for seed in SEEDS]
    rows = same_tissue.run_all(2, lambda job: whole_run(args, *job), jobs)
    for tissue, point in WHOLE_RUNS:
        print(f"{tissue} {point} whole runs, minima with interpenetrating cells: "
              f"{[r[6] for r in rows if r[:2] == [tissue, point]]}", flush=True)
    out = os.path.join(os.path.dirname(os.path.abspath(args.out)), "growth_per_step_runs.csv")
    same_tissue.write_csv(out, ["tissue", "lambda_x_delta_a", "seed", "growth_steps",
                                "phi_patch_end", "minima", "minima_interpenetrating",
                                "first_minimum_interpenetrating", "other_failed_checks"], rows)
    print(f"wrote {out}")


def main():
    args = same_tissue.compare_first_steps(
        __doc__, "growth_per_step", "lambda_x_delta_a", POINTS,
        lambda p: [f"dl0={POINTS[p][0]}", f"da0={POINTS[p][1]}"], package_variables,
        figure="fig4")
    seed_spread(args)
    whole_runs(args)


if __name__ == "__main__":
    main()
