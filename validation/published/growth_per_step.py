#!/usr/bin/env python3
"""Interpenetrating cells after the first growth step across lambda delta_a: the published code
against the package, from the same tissue, between the products where every run of Fig 4's
sweeps passes (2.5 and below) and where nearly every one fails (3.5 and above).

    growth_per_step.py BINARY [--lmp build/lmp] [--work DIR] [--out growth_per_step.csv]

The first growth step's void-run length growth is proportional to lambda delta_a. The same
comparison as high_lambda.py (same_tissue.compare_first_steps(): the driver's frame 1 and the
package's minimum 2 with the driver's cycle and with fig4.sweep's protocol at seed 1; Fig 4's
base set at P0 = 1e-6 from tissue_N16.data) at the points of POINTS, named lambda x delta_a:
products 2.75 to 3.25 along delta_a 0.5, the product 3 reached four ways, and (5, 0.75), where
1 of the sweeps' 5 runs fails. Then the package's minimum 2 with fig4.sweep's protocol at the
sweep's other seeds, SEEDS, into growth_per_step_seeds.csv beside --out: bonds break after
minimum 1, so minimum 2 depends on the seed.
"""
import os

import same_tissue
from high_lambda import SWEEP_SETTINGS    # the same package modes as high_lambda.py

POINTS = {"5.5x0.5": ("5.5", "0.5"), "6x0.5": ("6", "0.5"), "6.5x0.5": ("6.5", "0.5"),
          "4x0.75": ("4", "0.75"), "5x0.6": ("5", "0.6"), "10x0.3": ("10", "0.3"),
          "5x0.75": ("5", "0.75")}
SEEDS = ("2", "3", "4", "5")


def package_variables(point, mode, seed=None):
    lam, delta_a = POINTS[point]
    variables = dict(SWEEP_SETTINGS[mode], **{"lambda": lam, "delta_a": delta_a})
    if seed:
        variables["seed"] = seed
    return variables


def seed_spread(args):
    """fig4.sweep's protocol at SEEDS: one row per point and seed."""
    lmp = os.path.abspath(args.lmp)
    rows = []
    for point in POINTS:
        for seed in SEEDS:
            rows.append([point, seed] + same_tissue.package_first_step(
                lmp, args.work, f"package_sweep_{point}_seed{seed}", "package_sweep",
                package_variables(point, "package_sweep", seed), figure="fig4"))
        print(f"{point} seeds {' '.join(SEEDS)}: pairs {[r[5] for r in rows[-len(SEEDS):]]}",
              flush=True)
    out = os.path.join(os.path.dirname(os.path.abspath(args.out)), "growth_per_step_seeds.csv")
    same_tissue.write_csv(out, ["lambda_x_delta_a", "seed", "phi_patch", "calA", "z",
                                "interpenetrating_pairs", "first_pair"], rows)
    print(f"wrote {out}")


def main():
    seed_spread(same_tissue.compare_first_steps(
        __doc__, "growth_per_step", "lambda_x_delta_a", POINTS,
        lambda p: [f"dl0={POINTS[p][0]}", f"da0={POINTS[p][1]}"], package_variables,
        figure="fig4"))


if __name__ == "__main__":
    main()
