#!/usr/bin/env python3
"""validation/published/in.measure on the published code's first two frames.

    published_measure.py --lmp BUILD/lmp --published validation/published [--np N] ...

in.measure is how run.py measures every frame of the published code with the package's own
definitions. On growth_step/published_frame_0.data and published_frame_1.data (frames 0 and 1
of the run of seed 20261122) its measure.txt must give the phi_patch, calA, z and bonds of the
first two rows of N16_insert_seed20261122.csv (written by the same script: 1e-6, bonds exactly),
and its check.txt the pairs of interpenetrating cells that fix dpoly/check finds: none in frame 0
and one in frame 1, cells 3 and 7 (whose outlines overlap there), as the CSV's
interpenetrating_pairs column says when it has one. Standard library only.
"""
import csv
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from regression import parse_lmp_arguments, run_lmp    # noqa: E402

TOLERANCE = 1e-6


def main():
    args = parse_lmp_arguments(__doc__, lambda p: p.add_argument(
        "--published", required=True, help="the folder validation/published"))
    published = os.path.abspath(args.published)
    frames = [os.path.join(published, "growth_step", f"published_frame_{k}.data") for k in (0, 1)]
    with open(os.path.join(published, "N16_insert_seed20261122.csv")) as f:
        expected = list(csv.DictReader(f))[:2]
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "frames.list"), "w") as f:
            f.write("\n".join(frames) + "\n")
        run_lmp(args, ["-in", os.path.join(published, "in.measure"), "-var", "list",
                       "frames.list", "-log", "log.measure", "-screen", "none"], work,
                "published_measure: lmp -in in.measure failed")
        with open(os.path.join(work, "measure.txt")) as f:
            measured = [line.split() for line in f]
        with open(os.path.join(work, "check.txt")) as f:
            checked = [line.split() for line in f]
        log = open(os.path.join(work, "log.measure")).read()
    problems = []
    if len(measured) != 2 or len(checked) != 2:
        sys.exit(f"published_measure: {len(measured)} lines in measure.txt, {len(checked)} in "
                 "check.txt, expected 2 each")
    for k, (row, want) in enumerate(zip(measured, expected)):
        got = {"phi_patch": float(row[2]), "calA": float(row[3]), "z": float(row[4]),
               "bonds": int(row[5])}
        for key, value in got.items():
            if abs(value - float(want[key])) > (0 if key == "bonds" else TOLERANCE):
                problems.append(f"frame {k}: {key} {value} where the CSV has {want[key]}")
        pairs = int(float(checked[k][1]))
        if pairs != k:
            problems.append(f"frame {k}: {pairs} pairs of cells interpenetrate, expected {k}")
        if "interpenetrating_pairs" in want and int(want["interpenetrating_pairs"]) != pairs:
            problems.append(f"frame {k}: {pairs} interpenetrating pairs where the CSV has "
                            f"{want['interpenetrating_pairs']}")
    if "1 pairs of cells interpenetrate (first: cells 3 and 7)" not in log:
        problems.append("fix dpoly/check did not name cells 3 and 7 in frame 1")
    for problem in problems:
        print("FAIL:", problem)
    print(f"frames 0 and 1: measure.txt {'differs from' if problems else 'agrees with'} the CSV; "
          f"interpenetrating pairs {checked[0][1]} and {checked[1][1]}")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
