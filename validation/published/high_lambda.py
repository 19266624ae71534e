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
import same_tissue

LAMBDAS = ("3", "5", "7", "10")
DELTA_A = "0.5"
# what each package mode adds to the run's variables (same_tissue.package sets ftol 1e-11 for all)
SWEEP_SETTINGS = {"package_published_rules": {},
                  "package_sweep": {"tmaxadapt": "yes", "seed": "1"}}


def main():
    same_tissue.compare_first_steps(
        __doc__, "high_lambda", "lambda", LAMBDAS, lambda lam: [f"dl0={lam}", f"da0={DELTA_A}"],
        lambda lam, mode: dict(SWEEP_SETTINGS[mode], **{"lambda": lam, "delta_a": DELTA_A}),
        figure="fig4")


if __name__ == "__main__":
    main()
