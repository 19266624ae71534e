#!/usr/bin/env python3
"""Interpenetrating cells after the first growth step along Fig 4's delta_a 0.5 row: the
published code against the package, from the same tissue.

    high_lambda.py BINARY [--lmp build/lmp] [--work DIR] [--out high_lambda.csv]

BINARY is the driver build.sh made. From tissue_N16.data (through make_input.py), with Fig 4's
base set (eps_b 0.4, beta 100, theta0_min -3 pi/20) at its caption's P0 = 1e-6, delta_a 0.5 and
lambda each value of LAMBDAS:

  * published: the driver's frame 1 (the relaxed input grown once and minimized at P0; no bond
    breaks before it, so the seed does not matter), measured by in.measure;
  * package_published_rules: in.mesophyll's minimum 2 with the driver's cycle (rules published,
    break_start 2, steer mass);
  * package_sweep: the same with the protocol of fig4.sweep (in.mesophyll's defaults: its
    parameter set's rules code, break_start 1, steer force; ftol 1e-11 and tmaxadapt yes as the
    sweep fixes them) and the sweep's seed 1, so that it repeats the first minimum after growth
    of seed 1 of fig4_part1, fig4_part3 and fig4_part4.

Each row gives phi_patch, calA and z of that state and the pairs of cells whose outlines
overlap as fix dpoly/check counts them (and the first pair it names).
"""
import os

import same_tissue

LAMBDAS = ("3", "5", "7", "10")
DELTA_A = "0.5"
COLUMNS = ["lambda", "code", "phi_patch", "calA", "z", "interpenetrating_pairs", "first_pair"]
# what each package mode adds to the run's variables (same_tissue.package sets ftol 1e-11 for all)
SWEEP_SETTINGS = {"package_published_rules": {},
                  "package_sweep": {"tmaxadapt": "yes", "seed": "1"}}


def main():
    p = same_tissue.arguments(__doc__, "high_lambda")
    a = p.parse_args()
    lmp, binary = os.path.abspath(a.lmp), os.path.abspath(a.binary)
    same_tissue.driver_input(a.work)
    rows = []
    for lam in LAMBDAS:
        rows.append([lam, "published"] + same_tissue.published_first_step(
            binary, lmp, a.work, f"published_{lam}", [f"dl0={lam}", f"da0={DELTA_A}"],
            figure="fig4"))
        for mode in same_tissue.PACKAGE_MODES:
            variables = dict(SWEEP_SETTINGS[mode], **{"lambda": lam, "delta_a": DELTA_A})
            rows.append([lam, mode] + same_tissue.package_first_step(
                lmp, a.work, f"{mode}_{lam}", mode, variables, figure="fig4"))
        print(f"lambda {lam}: done", flush=True)
    same_tissue.write_csv(a.out, COLUMNS, rows)
    same_tissue.print_first_steps("lambda", rows)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
