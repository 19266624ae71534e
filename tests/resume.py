#!/usr/bin/env python3
"""A killed development run, resumed from its last restart file, ends as the uninterrupted one.

    resume.py --lmp BUILD/lmp --example examples/mesophyll [--steps 4] [--cells 16] [--np N]
              [--mpirun CMD] [--numproc-flag FLAG] [--preflags FLAGS] [--postflags FLAGS]

Runs examples/NAME/in.mesophyll (16 cells, 4 growth steps, a restart file every step) three
ways in scratch copies of the example folder:

  straight  uninterrupted;
  killed    started the same way and sent SIGKILL as soon as its first restart file
            (restart.N16.1) exists, then resumed from the newest restart file with
            -var resume FILE; the kill must land while lmp still runs and before the last
            growth step is recorded, else the test fails (the run was too fast to interrupt);
  rewound   the finished straight folder resumed from restart.N16.2, an earlier step than the
            records reach: the growth table and the dump must be cut back, then appended.

The growth table growth.N16.txt and the dump cells.N16.dump of the last two must equal the
straight one's: the same growth steps and snapshots, bond counts, contact numbers and vertex
ids exactly, the floating-point columns and vertex positions to round-off (a restart changes
the summation order; FIRE's iteration count may differ by a few steps and is not compared).
With --np N > 1 the runs are launched as regression.py launches them (CMake's MPIEXEC_*
order); the kill then goes to the launcher's whole process group and to every process left
working in the run's folder, so that no rank outlives it (Linux: /proc).
Standard library only.
"""
import argparse
import glob
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regression import add_launcher_arguments, launch    # noqa: E402

GROWTH_COLUMNS = "step P phi phi_patch calA z bonds dphi_plus iterations".split()
# (rtol, atol) per column; None: must be equal; "skip": not compared
TOLERANCES = {"step": None, "P": (1e-9, 0.0), "phi": (0.0, 2e-6), "phi_patch": (0.0, 2e-6),
              "calA": (0.0, 2e-6), "z": None, "bonds": None, "dphi_plus": (0.0, 2e-6),
              "iterations": "skip"}
POSITION_ATOL = 1e-6


def lmp_command(args, extra):
    return launch(args, ["-in", "in.mesophyll", "-screen", "none", "-var", "N", str(args.cells),
                         "-var", "steps", str(args.steps), "-var", "restart_every", "1"] + extra)


def run(args, folder, log, extra=()):
    command, env = lmp_command(args, ["-log", log] + list(extra))
    result = subprocess.run(command, cwd=folder, env=env, timeout=args.timeout)
    if result.returncode != 0:
        sys.exit(f"resume: {' '.join(command)} in {folder} failed with exit code "
                 f"{result.returncode}")


def growth_rows(folder, cells):
    rows = []
    with open(os.path.join(folder, f"growth.N{cells}.txt")) as table:
        for line in table:
            if not line.startswith("#") and line.strip():
                rows.append([float(w) for w in line.split()])
    return rows


def dump_snapshots(folder, cells):
    """List of {id: (mol, xu, yu, next)} per snapshot."""
    snapshots, lines = [], open(os.path.join(folder, f"cells.N{cells}.dump")).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[i + 1])
            while not lines[i].startswith("ITEM: ATOMS"):
                i += 1
            atoms = {}
            for line in lines[i + 1:i + 1 + n]:
                w = line.split()
                atoms[int(w[0])] = (int(w[1]), float(w[2]), float(w[3]), int(float(w[4])))
            snapshots.append(atoms)
            i += n
        i += 1
    return snapshots


def compare(reference, folder, cells, what):
    problems = []
    ref_rows, rows = growth_rows(reference, cells), growth_rows(folder, cells)
    if len(rows) != len(ref_rows):
        problems.append(f"{what}: {len(rows)} growth rows, uninterrupted run has {len(ref_rows)}")
    for ref_row, row in zip(ref_rows, rows):
        for column, ref, value in zip(GROWTH_COLUMNS, ref_row, row):
            tol = TOLERANCES[column]
            if tol == "skip":
                continue
            if (value != ref) if tol is None else (abs(value - ref) > tol[1] + tol[0] * abs(ref)):
                problems.append(f"{what}: growth step {int(ref_row[0])} {column} {value!r}, "
                                f"uninterrupted {ref!r}")
    ref_snaps, snaps = dump_snapshots(reference, cells), dump_snapshots(folder, cells)
    if len(snaps) != len(ref_snaps):
        problems.append(f"{what}: {len(snaps)} dump snapshots, uninterrupted run has "
                        f"{len(ref_snaps)}")
    worst = 0.0
    for k, (ref_atoms, atoms) in enumerate(zip(ref_snaps, snaps)):
        if sorted(atoms) != sorted(ref_atoms):
            problems.append(f"{what}: snapshot {k + 1} has other vertex ids")
            continue
        for atom_id, (mol, x, y, nxt) in atoms.items():
            rmol, rx, ry, rnxt = ref_atoms[atom_id]
            worst = max(worst, abs(x - rx), abs(y - ry))
            if (mol, nxt) != (rmol, rnxt):
                problems.append(f"{what}: snapshot {k + 1} vertex {atom_id}: mol/next "
                                f"{mol}/{nxt}, uninterrupted {rmol}/{rnxt}")
    if worst > POSITION_ATOL:
        problems.append(f"{what}: vertex positions differ by up to {worst:.3g} "
                        f"(> {POSITION_ATOL})")
    return problems, len(rows), len(snaps), worst


def kill_processes_in(folder):
    """SIGKILL every process whose working directory is folder, and wait until none is left."""
    folder = os.path.realpath(folder)
    killed = set()
    deadline = time.time() + 30
    while time.time() < deadline:
        found = False
        for pid in os.listdir("/proc"):
            if not pid.isdigit():
                continue
            try:
                if os.path.realpath(f"/proc/{pid}/cwd") != folder:
                    continue
                found = True
                os.kill(int(pid), signal.SIGKILL)
                killed.add(pid)
            except (FileNotFoundError, ProcessLookupError, PermissionError):
                continue
        if not found:
            return len(killed)
        time.sleep(0.05)
    sys.exit(f"resume: processes in {folder} outlived SIGKILL for 30 s")


def restart_step(path):
    return int(path.rsplit(".", 1)[1])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", required=True)
    p.add_argument("--example", required=True, help="examples/mesophyll")
    p.add_argument("--cells", type=int, default=16)
    p.add_argument("--steps", type=int, default=4)
    p.add_argument("--timeout", type=float, default=300, help="seconds per lmp run")
    add_launcher_arguments(p)
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    start = time.time()
    cells = args.cells

    with tempfile.TemporaryDirectory() as scratch:
        straight, killed, rewound = (os.path.join(scratch, name)
                                     for name in ("straight", "killed", "rewound"))
        for folder in (straight, killed):
            shutil.copytree(args.example, folder)    # follows the parameter file's symlink

        # the killed run: SIGKILL to lmp (or its launcher) once its first restart file is there
        first = os.path.join(killed, f"restart.N{cells}.1")
        command, env = lmp_command(args, ["-log", "log.killed"])
        proc = subprocess.Popen(command, cwd=killed, env=env, start_new_session=True)
        deadline = time.time() + args.timeout
        while not os.path.exists(first) and proc.poll() is None and time.time() < deadline:
            time.sleep(0.005)
        still_running = proc.poll() is None
        if still_running:    # lmp, or the launcher and its ranks, in their own process group
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
        # ranks a launcher put in a process group of their own
        if kill_processes_in(killed):
            print("killed processes that had outlived their launcher in the run's folder")
        if not os.path.exists(first):
            sys.exit(f"resume: the run ended (exit code {proc.returncode}) or timed out "
                     f"before writing {first}")
        if not still_running or proc.returncode != -signal.SIGKILL:
            sys.exit(f"resume: the kill came too late: lmp had finished (exit code "
                     f"{proc.returncode}) before SIGKILL")
        recorded = len(growth_rows(killed, cells))
        if recorded >= args.steps:
            sys.exit(f"resume: the kill came too late: all {recorded} growth steps recorded")
        restarts = sorted(glob.glob(os.path.join(killed, f"restart.N{cells}.[0-9]*")),
                          key=restart_step)
        last = os.path.basename(restarts[-1])
        print(f"killed lmp (SIGKILL) with {recorded} of {args.steps} growth steps recorded; "
              f"resuming from {last}")
        run(args, killed, "log.resumed", ["-var", "resume", last])

        run(args, straight, "log.straight")

        # resuming from an earlier restart than the records reach cuts them back
        shutil.copytree(straight, rewound)
        run(args, rewound, "log.rewound", ["-var", "resume", f"restart.N{cells}.2"])

        problems = []
        for folder, what in ((killed, f"killed and resumed from {last}"),
                             (rewound, f"rewound to restart.N{cells}.2")):
            found, rows, snaps, worst = compare(straight, folder, cells, what)
            problems += found
            print(f"{what}: {rows} growth rows, {snaps} dump snapshots, positions within "
                  f"{worst:.2g} of the uninterrupted run")
    if problems:
        print("\n".join(problems[:40]))
        sys.exit(1)
    print(f"resumed runs equal the uninterrupted one ({time.time() - start:.1f} s)")


if __name__ == "__main__":
    main()
