#!/usr/bin/env python3
"""Interpenetrating cells after the first growth step at Fig 5's bending stiffnesses: the
published code against the package, from the same tissue.

    low_bending.py BINARY [--lmp build/lmp] [--work DIR] [--out low_bending.csv]

BINARY is the driver build.sh made. From tissue_N16.data (through make_input.py), with Fig 5's
base set (beta 100, theta0_min -3 pi/20) at P0 = 1e-5 (the pressure of fig5_coarse.sweep) and
eps_b each value of EPS_B:

  * published: the driver's frame 1 (run.py --steps 1: the relaxed input grown once and
    minimized at P0; no bond breaks before it, so the seed does not matter), measured by
    in.measure;
  * package_published_rules: in.mesophyll's minimum 2 (-var steps 2) with the driver's cycle
    (rules published, break_start 2, steer mass);
  * package_sweep: the same with the protocol fig5_coarse.sweep ran (in.mesophyll's defaults:
    its parameter set's rules code, break_start 1, steer force).

Each row gives phi_patch, calA and z of that state and the pairs of cells whose outlines
overlap as fix dpoly/check counts them (and the first pair it names).
"""
import same_tissue

EPS_B = ("0.01", "0.03", "0.1", "0.4", "0.6")


def main():
    same_tissue.compare_first_steps(__doc__, "low_bending", "eps_b", EPS_B,
                                    lambda eps_b: [f"kb0={eps_b}"],
                                    lambda eps_b, mode: {"eps_b": eps_b})


if __name__ == "__main__":
    main()
