#!/usr/bin/env python3
"""The main example's progress line: one per growth step, with the growth table's values.

    progress_line.py --lmp BUILD/lmp --example examples/mesophyll [--steps 2] [--np N ...]

Runs in.mesophyll_short for a few growth steps and checks that its log has exactly one line
"growth step k/K: P .. phi .. phi_patch .. ... <min_style> iterations N; A min so far, about B min
left (estimate: S s per growth step so far x L steps left)" per step, in order, whose phi,
phi_patch and iterations are those of the growth table the same run wrote, with L = K - k,
S > 0 and finite, A = S k / 60 and B = S L / 60 to their printed digits, A not falling; and,
per growth step, one closing line of min_style fire/nph ("fire/nph: N iterations, U uphill ...,
mean time step T (tmax x timestep = C)", with ", lowered n times to D by tmaxadapt" before the
closing parenthesis where min_modify tmaxadapt acted) with the same N, U <= N, 0 < T <= C and
C = 5 x the timestep given by in.mesophyll's -var timestep (--timestep, 0.008 here: not its
default).
Standard library only (regression.py's launcher).
"""
import argparse
import math
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import regression    # noqa: E402

LINE = re.compile(r"^growth step (\d+)/(\d+): P (\S+) phi (\S+) phi_patch (\S+) <calA> \S+ <z> \S+ "
                  r"bonds \S+ (\S+) iterations (\d+); (\S+) min so far, about (\S+) min left "
                  r"\(estimate: (\S+) s per growth step so far x (\d+) steps left\)$")
FIRE = re.compile(r"^  fire/nph: (\d+) iterations, (\d+) uphill .*, mean time step (\S+) "
                  r"\(tmax x timestep = ([^,)]+)"
                  r"(?:, lowered (\d+) times to (\S+) by tmaxadapt)?\)$")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", required=True)
    p.add_argument("--example", required=True)
    p.add_argument("--steps", type=int, default=2)
    p.add_argument("--timestep", default="0.008")
    regression.add_launcher_arguments(p)
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    args.input = "in.mesophyll_short"
    args.var = [("steps", str(args.steps)), ("restart_every", "0"), ("timestep", args.timestep)]

    problems = []
    with tempfile.TemporaryDirectory() as work:
        log = regression.run_example(args, work, "log.progress")
        with open(log) as f:
            text = f.read().splitlines()
        lines = [m for m in (LINE.match(line) for line in text) if m]
        fire = [m for m in (FIRE.match(line) for line in text) if m]
        with open(os.path.join(work, "growth.N16.txt")) as f:
            table = [line.split() for line in f if not line.startswith("#")]
    if len(lines) != args.steps:
        problems.append(f"{len(lines)} progress lines, expected {args.steps}")
    if len(fire) != args.steps:
        problems.append(f"{len(fire)} fire/nph closing lines, expected {args.steps}")
    for k, (m, row) in enumerate(zip(fire, table), start=1):
        iterations, uphill, mean_dt, cap = int(m[1]), int(m[2]), float(m[3]), float(m[4])
        if str(iterations) != row[8]:
            problems.append(f"step {k}: fire/nph says {iterations} iterations, table {row[8]}")
        if uphill > iterations:
            problems.append(f"step {k}: {uphill} uphill steps in {iterations} iterations")
        if abs(cap - 5 * float(args.timestep)) > 1e-12:
            problems.append(f"step {k}: cap {cap}, not 5 x timestep {args.timestep}")
        if not 0 < mean_dt <= cap * (1 + 1e-3):
            problems.append(f"step {k}: mean time step {mean_dt}, cap {cap}")
    so_far_before = 0.0
    for k, (m, row) in enumerate(zip(lines, table), start=1):
        step, steps, _, phi, phi_patch, style, iterations, so_far, left, per_step, steps_left = \
            m.groups()
        if (int(step), int(steps)) != (k, args.steps):
            problems.append(f"line {k} says growth step {step}/{steps}")
        if style != "fire/nph":
            problems.append(f"step {k}: minimizer '{style}', the example's is fire/nph")
        for name, printed, recorded in (("phi", phi, row[2]), ("phi_patch", phi_patch, row[3])):
            if abs(float(printed) - float(recorded)) > 0.5e-4 + 1e-12:
                problems.append(f"step {k}: {name} {printed}, growth table {recorded}")
        if iterations != row[8]:
            problems.append(f"step {k}: {iterations} iterations, growth table {row[8]}")
        if int(steps_left) != args.steps - k:
            problems.append(f"step {k}: {steps_left} steps left, expected {args.steps - k}")
        so_far, left, per_step = float(so_far), float(left), float(per_step)
        if not (math.isfinite(per_step) and per_step > 0):
            problems.append(f"step {k}: {per_step} s per growth step")
            continue
        # each printed to 0.1: the seconds per step to 0.05 s, the minutes to 0.05 min
        for name, value, count in (("so far", so_far, k), ("left", left, int(steps_left))):
            expected = per_step * count / 60
            if abs(value - expected) > 0.05 + 0.05 * count / 60 + 1e-9:
                problems.append(f"step {k}: {value} min {name}, {expected:.3f} from the mean")
        if so_far < so_far_before:
            problems.append(f"step {k}: {so_far} min so far, less than the step before")
        so_far_before = so_far
    for problem in problems:
        print("FAIL:", problem)
    if problems:
        return 1
    print(f"OK: {len(lines)} progress lines, phi, phi_patch and iterations as in the growth table; "
          f"fire/nph's closing lines agree, cap 5 x timestep {args.timestep}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
