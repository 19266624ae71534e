#!/usr/bin/env python3
"""examples/python/grow_tissue.py through LAMMPS's own Python module, against the input it drives.

    test_python_module.py --lmp BUILD/lmp --library BUILD/liblammps.so --lammps-python DIR
                          --example examples/mesophyll [--steps 2]

Runs the Python example for a few growth steps of the 16-cell tissue with the `lammps` package of
the LAMMPS source tree (DIR, LAMMPS's python/ folder) and this build's shared library, and
in.mesophyll_short for as many steps with lmp. Checks that
  * every thermo row of every minimization of the Python-driven run equals lmp's (regression.py's
    comparison, 1e-12 relative): the loop in Python is the input's loop;
  * the global values read through the library interface are those the log prints at each
    minimum, and the per-cell array agrees with them (mean calA and mean z over the cells are the
    global <calA> and <z>, and one row per cell);
  * the tables and the plot are written, one row per cell and step.
Exits 77 (skipped) when liblammps is a static library (BUILD_SHARED_LIBS=OFF, e.g. a sanitizer
build) or numpy or matplotlib is missing.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import regression    # noqa: E402  (its thermo-table reader and comparison)

EXAMPLE_SCRIPT = os.path.join(HERE, "..", "examples", "python", "grow_tissue.py")


def python_with_packages():
    """An interpreter with numpy and matplotlib: this one, or Debian's."""
    for candidate in (sys.executable, "/usr/bin/python3"):
        if candidate and subprocess.run([candidate, "-c", "import numpy, matplotlib"],
                                        capture_output=True).returncode == 0:
            return candidate
    return None


def last_rows(log):
    """Per thermo table, its last row as {column: value}: the minimum of each minimization."""
    return [dict(zip(columns, rows[-1])) for columns, rows in regression.thermo_blocks(log)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--library", required=True, help="the build's liblammps")
    parser.add_argument("--lammps-python", required=True, help="LAMMPS's python/ folder")
    parser.add_argument("--example", required=True, help="examples/mesophyll")
    parser.add_argument("--steps", type=int, default=2)
    args = parser.parse_args()

    if not args.library.endswith(".so") and ".so." not in args.library:
        print(f"SKIP: {args.library} is not a shared library (configure with "
              "-DBUILD_SHARED_LIBS=ON, as tools/setup.sh does outside sanitizer builds)")
        return 77
    python = python_with_packages()
    if python is None:
        print("SKIP: no python3 with numpy and matplotlib (Debian: python3-numpy "
              "python3-matplotlib)")
        return 77

    problems = []
    with tempfile.TemporaryDirectory(prefix="mesophyll_python_") as tmp:
        env = dict(os.environ)
        env["PYTHONPATH"] = (os.path.abspath(args.lammps_python) + os.pathsep +
                             env.get("PYTHONPATH", ""))
        env["LD_LIBRARY_PATH"] = (os.path.dirname(os.path.abspath(args.library)) + os.pathsep +
                                  env.get("LD_LIBRARY_PATH", ""))
        out = os.path.join(tmp, "python")
        run = subprocess.run([python, EXAMPLE_SCRIPT, "--cells", "16", "--steps", str(args.steps),
                              "--out", out], env=env, capture_output=True, text=True)
        print(run.stdout + run.stderr)
        if run.returncode != 0:
            print(f"FAIL: grow_tissue.py exited with {run.returncode}")
            return 1

        # the same growth steps with lmp and the input's own loop
        work = os.path.join(tmp, "lmp")
        shutil.copytree(args.example, work)
        lmp_run = subprocess.run([os.path.abspath(args.lmp), "-in", "in.mesophyll_short", "-var",
                                  "steps", str(args.steps), "-var", "restart_every", "0",
                                  "-log", "log.lammps", "-screen", "none"],
                                 cwd=work, capture_output=True, text=True)
        if lmp_run.returncode != 0:
            print(lmp_run.stdout + lmp_run.stderr)
            print(f"FAIL: lmp exited with {lmp_run.returncode}")
            return 1

        python_log = os.path.join(out, "log.lammps")
        lmp_log = os.path.join(work, "log.lammps")
        problems += regression.compare(lmp_log, python_log, rtol=1e-12, atol=0.0)
        minima = last_rows(python_log)
        if len(minima) != args.steps:
            problems.append(f"{len(minima)} minimizations in the Python run's log, expected "
                            f"{args.steps}")

        with open(os.path.join(out, "growth.csv")) as f:
            growth = list(csv.DictReader(f))
        with open(os.path.join(out, "cells_per_step.csv")) as f:
            cells = list(csv.DictReader(f))
        if len(growth) != args.steps:
            problems.append(f"growth.csv has {len(growth)} rows, expected {args.steps}")
        for k, (row, minimum) in enumerate(zip(growth, minima), start=1):
            # what the library interface gave is what the log printed at the minimum
            for column, thermo in (("P", "Press"), ("phi", "c_tissue[1]"),
                                   ("phi_patch", "c_tissue[2]"), ("calA", "c_tissue[3]"),
                                   ("z", "c_tissue[4]"), ("bonds", "c_tissue[5]")):
                value, printed = float(row[column]), minimum[thermo]
                if abs(value - printed) > 1e-13 * abs(printed) + 1e-300:
                    problems.append(f"step {k}: {column} {value!r} through the library, "
                                    f"{printed!r} in the log")
            step_cells = [c for c in cells if int(c["step"]) == k]
            if len(step_cells) != 16:
                problems.append(f"step {k}: {len(step_cells)} rows of cells, expected 16")
                continue
            for column in ("calA", "z"):
                mean = sum(float(c[column]) for c in step_cells) / len(step_cells)
                if abs(mean - float(row[column])) > 1e-12 * abs(float(row[column])):
                    problems.append(f"step {k}: mean {column} over the cells {mean!r}, global "
                                    f"{row[column]}")
        png = os.path.join(out, "per_cell.png")
        if not os.path.isfile(png) or os.path.getsize(png) < 1000:
            problems.append(f"no plot {png}")

    for p in problems:
        print("FAIL:", p)
    if not problems:
        print(f"OK: {args.steps} growth steps from Python equal lmp's run of in.mesophyll_short "
              "row for row; library values and per-cell array agree with the log")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
