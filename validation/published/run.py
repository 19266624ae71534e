#!/usr/bin/env python3
"""Run the published driver (readInMesoNetwork2D, built by build.sh) with the package's default
parameter set (or values given with --set) on one seed, and write its trajectory as a CSV
measured by the package itself.

    run.py BINARY INPUT SEED OUT.csv [--work DIR] [--phi-stop 0.45] [--steps K]
           [--limit SECONDS] [--set NAME=VALUE ...] [--lmp build/lmp] [--measure-only]

INPUT is the file make_input.py wrote. The driver runs in DIR (default: next to OUT.csv,
OUT.work/) and prints a frame (meso2D::printMesoNetworkCTCS2D) once after its initial
fixed-box relaxation (growth_steps 0) and then after every growth step's enthalpy minimization.
Each stdout line is timestamped as it arrives; the driver is stopped once the last frame's
phi_patch (estimated here, patch_phi() below) is at or below --phi-stop, or when it ends by
itself (phi < its phiMin 0.3). Then every frame goes back into a package data file
(frames.write_data) and one lmp run measures them all with compute dpoly/tissue after `run 0`
(in.measure next to this script): the CSV's phi_patch, calA, z, bonds and void_fraction are the
package's numbers, not ours, and so is interpenetrating_pairs: the pairs of cells whose outlines
overlap, as fix dpoly/check counts them (its vector element 8). --measure-only redoes that from
DIR without running the driver.

The driver's arguments are the values of the `default` set of potentials/arabidopsis.mesophyll,
mapped in ARGS below; README.md says why each is what it is. --set NAME=VALUE replaces one of
them (e.g. --set kb0=0.01 for Fig 5's low bending stiffness); --steps K stops the driver after
K growth steps (default: only --phi-stop); --limit stops it after that many seconds of wall time,
also within a minimization (the driver's FIRE stops only after 5e8 iterations: a stall would run
for days), and steps.txt then says so in its last line.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import threading
import time

import numpy as np

import frames

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
# Driver arguments after the input file: kb0 betaEff ctch da0 dl0 cL cB t0_min P0.
# The driver scales t0_min by -pi/2, so theta0_min = -pi/10 is passed as 0.2.
THETA0_MIN = -0.3141592653589793
ARGS = {"kb0": 0.4, "betaEff": 100, "ctch": 1.0, "da0": 0.5, "dl0": 5, "cL": 0.5, "cB": 4,
        "t0_min": THETA0_MIN / (-0.5 * math.pi), "P0": 1.0e-3}
COLUMNS = ["growth_steps", "phi_patch", "calA", "z", "bonds", "vertices", "void_fraction",
           "iterations", "wall_s", "interpenetrating_pairs"]
CONVERGED = re.compile(r"C O N V E R G E D!")
FIREIT = re.compile(r"\*\* fireit\s*=\s*(\d+)")
STEP_DONE = re.compile(r"^\s*\* k\s*=\s*(\d+)")


def patch_phi(t):
    """phi_patch as compute dpoly/tissue defines it (each vertex pushed out from its cell's mean
    vertex by sin(pi/3) r, shoelace area, over the box): only to decide when to stop; the CSV
    takes the package's value, and README.md reports how far the two differ."""
    total = 0.0
    for c in t.cells:
        dx, dy = c.x - c.x.mean(), c.y - c.y.mean()
        d = np.hypot(dx, dy)
        px = c.x + math.sin(math.pi / 3) * c.r * dx / d
        py = c.y + math.sin(math.pi / 3) * c.r * dy / d
        total += 0.5 * np.sum(px * np.roll(py, -1) - np.roll(px, -1) * py)
    return total / t.L ** 2


def last_frame(path):
    last = None
    for last in frames.read_frames(path):
        pass
    return last


def run_driver(binary, inp, seed, work, phi_stop, max_steps=None, limit=None):
    """Run the driver in work/; return [(growth_steps, iterations, wall_s)] per printed frame.
    wall_s of a frame: seconds from the previous frame's minimum to this one's (break, insertion,
    growth and the minimization; for frame 0 the start-up and the initial relaxation). limit:
    seconds after which the driver is stopped wherever it is."""
    os.makedirs(work, exist_ok=True)
    pos = os.path.join(work, "pos.txt")
    command = [binary, os.path.abspath(inp)] + [repr(v) for v in ARGS.values()] + \
        [str(seed), "pos.txt"]
    with open(os.path.join(work, "command.txt"), "w") as f:
        f.write(" ".join(command) + "\n")
    steps, converged, iterations = [], False, None
    start = last = time.monotonic()
    proc = subprocess.Popen(["nice", "-n", "5"] + command, cwd=work, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, bufsize=1)
    fired = threading.Event()

    def stop():
        if proc.poll() is None:
            fired.set()
            proc.terminate()

    timer = threading.Timer(limit, stop) if limit else None
    if timer:
        timer.start()
    with open(os.path.join(work, "stdout.tail"), "w") as tail:
        for line in proc.stdout:
            now = time.monotonic()
            if CONVERGED.search(line):
                converged = True
            elif converged and FIREIT.search(line):
                iterations, converged = int(FIREIT.search(line).group(1)), False
                if not steps:      # the initial relaxation is followed by frame 0 at once
                    steps.append((0, iterations, now - start))
                    last = now
            m = STEP_DONE.match(line)
            if m:
                steps.append((int(m.group(1)) + 1, iterations, now - last))
                last = now
                phi = patch_phi(last_frame(pos))
                print(f"seed {seed}: growth step {steps[-1][0]}, {iterations} FIRE iterations, "
                      f"{steps[-1][2]:.1f} s, phi_patch ~ {phi:.4f}", flush=True)
                tail.write(f"{now - start:.2f} {line}")
                if phi <= phi_stop or (max_steps is not None and steps[-1][0] >= max_steps):
                    proc.terminate()
                    break
            if "ERROR" in line or "did not converge" in line:
                tail.write(f"{now - start:.2f} {line}")
        proc.wait()
    if timer:
        timer.cancel()
    with open(os.path.join(work, "steps.txt"), "w") as f:
        f.write("# growth_steps iterations wall_s\n")
        f.writelines(f"{k} {i} {w:.3f}\n" for k, i, w in steps)
        if fired.is_set():
            f.write(f"# stopped at the --limit of {limit:g} s, {time.monotonic() - last:.1f} s "
                    f"into the minimization after frame {steps[-1][0] if steps else 'none'}\n")
    return steps


def measure(lmp, work):
    """Package values of every frame: write frame_K.data, run in.measure over them all once.
    Returns the tissues, measure.txt's rows and check.txt's pairs of interpenetrating cells."""
    tissues = list(frames.read_frames(os.path.join(work, "pos.txt")))
    listing = os.path.join(work, "frames.list")
    with open(listing, "w") as f:
        for k, t in enumerate(tissues):
            path = os.path.join(work, f"frame_{k}.data")
            frames.write_data(t, path, f"frame {k} of the published code")
            f.write(path + "\n")
    subprocess.run([lmp, "-in", os.path.join(HERE, "in.measure"), "-var", "list", listing,
                    "-log", os.path.join(work, "log.measure"), "-screen", "none"],
                   cwd=work, check=True)
    rows = []
    with open(os.path.join(work, "measure.txt")) as f:
        for line in f:
            rows.append([float(w) for w in line.split() if w != "cells"])
    with open(os.path.join(work, "check.txt")) as f:
        pairs = [int(float(line.split()[1])) for line in f]
    return tissues, rows, pairs


def main():
    p = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    p.add_argument("binary")
    p.add_argument("input")
    p.add_argument("seed", type=int)
    p.add_argument("out")
    p.add_argument("--work")
    p.add_argument("--phi-stop", type=float, default=0.45)
    p.add_argument("--steps", type=int, help="stop after this many growth steps")
    p.add_argument("--limit", type=float, help="stop the driver after this many seconds")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help=f"replace a driver argument ({', '.join(ARGS)})")
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--measure-only", action="store_true")
    p.add_argument("--data", help="package data file the input came from: compare its adhesive "
                   "bonds with those of the driver's frame 0")
    a = p.parse_args()
    if a.steps is not None and a.steps < 1:
        p.error(f"--steps {a.steps}: give at least 1 growth step")
    if a.limit is not None and a.limit <= 0:
        p.error(f"--limit {a.limit:g}: give a positive number of seconds")
    if a.measure_only and (a.set or a.steps is not None or a.limit is not None):
        p.error("--measure-only measures frames already made: --set, --steps and --limit do "
                "not apply")
    for item in a.set:
        name, _, value = item.partition("=")
        if name not in ARGS:
            p.error(f"--set {item}: {name} is not a driver argument ({', '.join(ARGS)})")
        try:
            ARGS[name] = float(value)
        except ValueError:
            p.error(f"--set {item}: {value!r} is not a number")
    work = a.work or os.path.splitext(a.out)[0] + ".work"
    if not a.measure_only:
        run_driver(os.path.abspath(a.binary), a.input, a.seed, work, a.phi_stop, a.steps,
                   a.limit)
    with open(os.path.join(work, "steps.txt")) as f:
        steps = [[float(w) for w in line.split()] for line in f if not line.startswith("#")]
    tissues, rows, pairs = measure(os.path.abspath(a.lmp), work)
    n = min(len(steps), len(tissues), len(rows))
    worst = max(abs(patch_phi(t) - r[2]) for t, r in zip(tissues[:n], rows[:n]))
    print(f"{n} frames; largest |phi_patch here - package| = {worst:.2e}; "
          f"frame 0 bonds: {len(tissues[0].bonds)}")
    if a.data:
        same = set(tissues[0].bonds) == set(frames.read_data(a.data).bonds)
        print(f"frame 0 bonds {'equal' if same else 'DIFFER from'} those of {a.data}")
    with open(a.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for (k, its, wall), t, r, ip in zip(steps, tissues, rows, pairs):
            nv = np.array([len(c.x) for c in t.cells])
            void = np.dot(r[6:], nv) / nv.sum()    # void-facing vertices of all vertices
            w.writerow([int(k), f"{r[2]:.6f}", f"{r[3]:.6f}", f"{r[4]:.4f}", int(r[5]),
                        nv.sum(), f"{void:.6f}", int(its), f"{wall:.2f}", ip])
    print(f"wrote {a.out}")


if __name__ == "__main__":
    sys.exit(main())
