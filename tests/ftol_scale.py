#!/usr/bin/env python3
"""in.mesophyll -var ftol_scale area: each minimization's tolerance is ftol / phi where it starts.

    ftol_scale.py --lmp BUILD/lmp --example examples/mesophyll [--steps 2] [--np N ...]

Runs in.mesophyll_short with -var ftol_scale area for a few growth steps and checks, from its
log, that every minimization ran with the tolerance ftol / phi, phi being the plain packing
fraction of the state it starts from: for the first, the last thermo row of the 'run 0' that
measures the tissue read; for the others, that of the minimization before (the stages after it
move no vertex, so its phi is the next one's start). Each must stop on the force tolerance with
the final 2-norm below its own tolerance, and at least one above ftol itself (else the scaling
is not seen). The same folder resumed from restart.N16.1 (-var resume) must run its first
minimization, growth step 2, at the uninterrupted run's tolerance for that step, to 1e-9
relative (its run 0 measures the restart's state, which is that of minimum 1). Last, two bad
settings must stop the run with an error naming them: an unknown ftol_scale, and area with
-var fnorm rms. tools/mesophyll_run.py, which the benchmarks use, must tell the run 0's loop time
from the minimizations'.
Standard library only (regression.py's launcher).
"""
import argparse
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import regression    # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "tools"))
import mesophyll_run    # noqa: E402

MINIMIZE = re.compile(r"^minimize\s+0\.0\s+([0-9.][0-9.eE+-]*)\s+\d+\s+\d+\s*$")
FINAL_NORM = re.compile(r"^\s*Force two-norm initial, final = \S+ (\S+)$")
CRITERION = re.compile(r"^\s*Stopping criterion = (.*)$")
FTOL = 1.0e-10


def thermo_phi(block):
    """phi (the thermo column c_tissue[1]) in the last row of a thermo block."""
    columns, rows = block
    return float(rows[-1][columns.index("c_tissue[1]")])


def refused(args, variables, words):
    """None if the run stops with an error whose text has every one of 'words', else why not."""
    with tempfile.TemporaryDirectory() as work:
        _, result = regression.start_example(args, work, "log.bad", variables,
                                             capture_output=True, text=True)
        with open(os.path.join(work, "log.bad")) as f:
            text = f.read()
    errors = [line for line in text.splitlines() if line.startswith("ERROR")]
    if result.returncode == 0:
        return f"{variables}: exit code 0"
    if not any(all(w in line for w in words) for line in errors):
        return f"{variables}: no error naming {words}, got {errors}"
    return None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", required=True)
    p.add_argument("--example", required=True)
    p.add_argument("--steps", type=int, default=2)
    regression.add_launcher_arguments(p)
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    args.input = "in.mesophyll_short"
    args.var = [("steps", str(args.steps)), ("restart_every", "1"), ("ftol", str(FTOL)),
                ("ftol_scale", "area")]

    problems = []
    with tempfile.TemporaryDirectory() as work:
        log = regression.run_example(args, work, "log.ftol_scale")
        log_text = open(log).read()
        text = log_text.splitlines()
        blocks = regression.thermo_blocks(log)
        args.var.append(("resume", "restart.N16.1"))
        resumed_log = regression.run_example(args, work, "log.resumed")
        resumed = [float(m[1]) for m in (MINIMIZE.match(line) for line in open(resumed_log))
                   if m]
    used = [float(m[1]) for m in (MINIMIZE.match(line) for line in text) if m]
    norms = [float(m[1]) for m in (FINAL_NORM.match(line) for line in text) if m]
    criteria = [m[1].strip() for m in (CRITERION.match(line) for line in text) if m]
    # thermo blocks: the run 0, then one per minimization
    if len(blocks) != args.steps + 1:
        problems.append(f"{len(blocks)} thermo blocks, expected run 0 and {args.steps} minima")
    if len(used) != args.steps:
        problems.append(f"{len(used)} minimize commands, expected {args.steps}")
    for k, tolerance in enumerate(used[:len(blocks)], start=1):
        expected = FTOL / thermo_phi(blocks[k - 1])
        if abs(tolerance - expected) > 1e-9 * expected:
            problems.append(f"minimization {k}: ftol {tolerance:.12g}, expected "
                            f"ftol / phi = {expected:.12g}")
    # the benchmarks pair loop times with minimizations: the run 0's loop must not count
    loops = mesophyll_run.loop_times(log_text)
    kinds = [loop.minimization for loop in loops]
    if kinds != [False] + [True] * args.steps:
        problems.append(f"mesophyll_run.loop_times: minimization flags {kinds}, expected the "
                        f"run 0 then {args.steps} minimizations")
    if not len(used) == len(norms) == len(criteria):
        problems.append(f"{len(used)} minimize commands, {len(norms)} final norms and "
                        f"{len(criteria)} stopping criteria in the log")
    for k, (tolerance, norm, criterion) in enumerate(zip(used, norms, criteria), start=1):
        if criterion != "force tolerance":
            problems.append(f"minimization {k} stopped on '{criterion}'")
        if not norm < tolerance:
            problems.append(f"minimization {k}: final norm {norm:.6g} not below {tolerance:.6g}")
    if used and not any(norm > FTOL for norm in norms):
        problems.append(f"no final norm above ftol {FTOL:g}: the scaling is not seen "
                        f"(norms {norms})")

    if len(resumed) != args.steps - 1:
        problems.append(f"resumed after growth step 1: {len(resumed)} minimizations, expected "
                        f"{args.steps - 1}")
    elif len(used) == args.steps and abs(resumed[0] - used[1]) > 1e-9 * used[1]:
        problems.append(f"resumed: growth step 2 at ftol {resumed[0]:.12g}, the uninterrupted "
                        f"run at {used[1]:.12g}")

    for variables, words in (([("ftol_scale", "cells")], ["ftol_scale", "cells"]),
                             ([("ftol_scale", "area"), ("fnorm", "rms")],
                              ["ftol_scale area", "rms"])):
        why = refused(args, variables + [("steps", "1")], words)
        if why:
            problems.append(why)

    for problem in problems:
        print("FAIL:", problem)
    if problems:
        return 1
    print(f"OK: {len(used)} minimizations at ftol / phi ({', '.join(f'{t:.4g}' for t in used)}), "
          f"each stopped below its own; the resumed run's as the uninterrupted one's; "
          f"bad ftol_scale values refused")
    return 0


if __name__ == "__main__":
    sys.exit(main())
