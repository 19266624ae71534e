#!/usr/bin/env python3
"""regression.py's rule for fix dpoly/check: a minimum that fails where the reference passed is a
difference, even when every thermo row matches (the check may see more than when the reference
was written). Runs on a copy of examples/development's reference log, one minimum's check line
marked failed as fix dpoly/check writes it; no LAMMPS run. Standard library only.

    check_regression_rule.py EXAMPLES_DIR
"""
import glob
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import regression  # noqa: E402

FAILURE = "; FAILED; 1 pairs of cells interpenetrate (first: cells 3 and 7)"


def with_failure(reference, minimum, path):
    """Copy reference to path, minimum's fix dpoly/check line failed; thermo rows untouched."""
    marker = f"fix dpoly/check: minimum {minimum} at step "
    marked = 0
    with open(reference) as src, open(path, "w") as out:
        for line in src:
            if line.startswith(marker):
                line = line.rstrip("\n") + FAILURE + "\n"
                marked += 1
            out.write(line)
    if marked != 1:
        sys.exit(f"check_regression_rule: {marked} check lines of minimum {minimum} in {reference}")
    return path


def main():
    logs = sorted(glob.glob(os.path.join(sys.argv[1], "development", "log.*.grow_small.g++.1")))
    if not logs:
        sys.exit("check_regression_rule: no reference log of examples/development/in.grow_small")
    reference = logs[-1]
    failures = []

    def expect(label, problems, count):
        print(f"{label}: {len(problems)} differences {problems}")
        if len(problems) != count:
            failures.append(f"{label}: expected {count} differences")

    if regression.failed_checks(reference):
        sys.exit(f"check_regression_rule: {reference} already has a failed check")
    with tempfile.TemporaryDirectory() as tmp:
        failed3 = with_failure(reference, 3, os.path.join(tmp, "failed3.log"))
        failed3_again = with_failure(reference, 3, os.path.join(tmp, "failed3_again.log"))
        failed5 = with_failure(failed3, 5, os.path.join(tmp, "failed3_5.log"))
        if regression.thermo_blocks(failed3) != regression.thermo_blocks(reference):
            failures.append("marking a check line changed the thermo tables")
        expect("reference against itself", regression.compare(reference, reference, 1e-8, 1e-12), 0)
        new = regression.compare(reference, failed3, 1e-8, 1e-12)
        expect("minimum 3 fails, passed in the reference", new, 1)
        if new and "minimum 3" not in new[0]:
            failures.append(f"the difference does not name minimum 3: {new[0]}")
        expect("minimum 3 fails in both", regression.compare(failed3, failed3_again, 1e-8, 1e-12),
               0)
        expect("minimum 5 fails too", regression.compare(failed3, failed5, 1e-8, 1e-12), 1)
        expect("minimum 3 passes again", regression.compare(failed3, reference, 1e-8, 1e-12), 0)
    if failures:
        sys.exit("check_regression_rule: " + "; ".join(failures))
    print(f"regression.py counts a new fix dpoly/check failure as a difference ({reference})")


if __name__ == "__main__":
    main()
