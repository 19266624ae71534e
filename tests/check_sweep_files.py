#!/usr/bin/env python3
"""Every sweep file the package ships plans, and the parts of a split sweep add up to it.

    check_sweep_files.py

Plans each examples/sweep/*.sweep (but in.sweep, the LAMMPS input) with tools/sweep.py (no
LAMMPS run, nothing written), so that a sweep file broken by a renamed parameter, a moved tissue
or a changed protocol fails here and not hours into a sweep. For every sweep that other files name as their whole (part_of): the
parts together plan each of its runs exactly once, so that the parts, run in different sessions
or on different machines, are the whole grid. Then, in a scratch folder, a made-up part with a
run the whole lacks (a value off its grid) must be refused by the plan, naming that run, and so
must two files that name each other as their whole.
"""
import collections
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SWEEPS = os.path.join(ROOT, "examples", "sweep")
sys.path.insert(0, os.path.join(ROOT, "tools"))
import sweep  # noqa: E402


def plan_quietly(path):
    """(SweepFile, runs) or the plan's error message."""
    try:
        definition, _, runs = sweep.planned_runs(path)
    except SystemExit as stop:
        return str(stop.code)
    return definition, runs


def check_parts(whole_path, parts, problems):
    """The parts' runs are the whole's, each planned by exactly one part."""
    whole, whole_runs = plan_quietly(whole_path)
    want = collections.Counter(sweep.run_key(whole, run) for run in whole_runs)
    have = collections.Counter(sweep.run_key(part, run) for part, runs in parts for run in runs)
    names = ", ".join(os.path.basename(part.path) for part, _ in parts)
    missing, twice = want - have, have - want
    if missing:
        problems.append(f"{os.path.basename(whole_path)}: {sum(missing.values())} of its "
                        f"{len(whole_runs)} runs are in none of its parts ({names})")
    if twice:
        problems.append(f"{os.path.basename(whole_path)}: {sum(twice.values())} runs are "
                        f"planned by more than one of its parts ({names})")
    print(f"{os.path.basename(whole_path)}: {len(whole_runs)} runs; its parts {names} plan "
          f"{sum(have.values())}")


def plan_in(scratch, sweep_file):
    """tools/sweep.py plan of sweep_file into a folder of scratch, its output captured."""
    return subprocess.run([sys.executable, os.path.join(ROOT, "tools", "sweep.py"), "plan",
                           sweep_file, os.path.join(scratch, "dir")],
                          capture_output=True, text=True)


def check_foreign_run(problems):
    """A part with a run off the whole's grid is refused, and the message names the run."""
    with tempfile.TemporaryDirectory(prefix="sweep_files_") as scratch:
        whole = os.path.join(scratch, "whole.sweep")
        part = os.path.join(scratch, "part.sweep")
        common = (f"protocol {os.path.join(ROOT, 'examples', 'mesophyll', 'in.mesophyll')}\n"
                  f"parameters {os.path.join(ROOT, 'potentials', 'fig5.mesophyll')}\n"
                  f"set base\nvary eps_b 0.1 0.4\nseeds 1 2\n"
                  f"tissue {os.path.join(ROOT, 'examples', 'tissue', 'tissue_N16.data')}\n")
        with open(whole, "w") as f:
            f.write(common + "vary beta 30 100\n")
        with open(part, "w") as f:
            f.write(common + "part_of whole.sweep\nvary beta 100 300\n")
        result = plan_in(scratch, part)
        said = result.stderr.strip()
        if result.returncode == 0:
            problems.append("a part with a run the whole does not plan (beta 300) was planned")
        elif "eps_b=0.1 beta=300, seed 1" not in said or "not a run of the whole" not in said:
            problems.append(f"the refusal of a foreign run does not name it: {said}")
        else:
            print(f"a foreign run is refused: {said}")
        # two files each naming the other as its whole: refused, not planned without end
        with open(whole, "w") as f:
            f.write(common + "part_of part.sweep\nvary beta 30 100\n")
        result = plan_in(scratch, part)
        if result.returncode != 1 or "is a part of another sweep itself" not in result.stderr:
            problems.append(f"a cycle of part_of: exit {result.returncode}, "
                            f"{result.stderr.strip()[-300:]}")


def main():
    problems, wholes = [], collections.defaultdict(list)
    # in.sweep is the LAMMPS input that runs a planned sweep, not a sweep file
    files = sorted(f for f in os.listdir(SWEEPS) if f.endswith(".sweep") and f != "in.sweep")
    for name in files:
        planned = plan_quietly(os.path.join(SWEEPS, name))
        if isinstance(planned, str):
            problems.append(f"{name} does not plan: {planned}")
            continue
        definition, runs = planned
        if definition.part_of:
            wholes[definition.part_of].append((definition, runs))
    print(f"{len(files)} sweep files planned")
    if not wholes:
        problems.append("no sweep file is a part of another (examples/sweep/fig5_part*.sweep)")
    for whole_path, parts in sorted(wholes.items()):
        check_parts(whole_path, parts, problems)
    check_foreign_run(problems)
    for p in problems:
        print(f"FAILED: {p}")
    print(f"check_sweep_files: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
