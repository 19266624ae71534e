#!/usr/bin/env python3
"""The two Fig 4 directions of the paper that fig4_phi045.sweep was run for, from its folder.

    python3 validation/fig4_stall/verdicts.py DIR      (after tools/sweep.py summary DIR)

Reads DIR/summary.csv and compares the point (lambda, delta_a) = (5, 0.01) with the base (5, 0.5)
by tools/sweep_report.py's rule (the difference of the ensemble means against 2 standard errors
of the difference; only runs with status ok): "delta_a = 0.01 with lambda = 5 compacts"
(delta_phi_plus larger) and "few contacts at small delta_a" (z nearest phi_patch = 0.5 smaller).
Standard library only.
"""
import csv
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tools"))
import sweep_report    # noqa: E402  (its ensembles and comparison rule)

DIRECTIONS = (("delta_a = 0.01 with lambda = 5 compacts", "delta_phi_plus", +1),
              ("few contacts at small delta_a", "z_half", -1))


def number(x, spec):
    return "-" if x is None else format(x, spec)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    with open(os.path.join(sys.argv[1], "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    small = sweep_report.ensemble_at(rows, {"lambda": 5, "delta_a": 0.01}, ["ok"])
    base = sweep_report.ensemble_at(rows, {"lambda": 5, "delta_a": 0.5}, ["ok"])
    if small is None or base is None:
        sys.exit(f"{sys.argv[1]}: the sweep lacks the point (5, 0.01) or the base (5, 0.5)")
    print(f"(5, 0.01): {small.status_text()}; base (5, 0.5): {base.status_text()}")
    for name, quantity, sign in DIRECTIONS:
        verdict, ma, sa, na, mb, sb, nb, score = sweep_report.compare(small, base, quantity, sign)
        print(f"{name} ({quantity}): {number(ma, '.4g')} +- {number(sa, '.2g')} (n = {na}) at "
              f"(5, 0.01) against {number(mb, '.4g')} +- {number(sb, '.2g')} (n = {nb}) at the "
              f"base; difference {number(score, '+.1f')} standard errors: {verdict}")


if __name__ == "__main__":
    main()
