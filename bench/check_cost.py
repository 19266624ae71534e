#!/usr/bin/env python3
"""Cost of fix dpoly/check at one minimum, against the number of cells.

    bench/check_cost.py [--lmp build/lmp] [--cells 64 256 1024 4096] [--minima 40]
                        [--out bench/results]

Tissues: examples/tissue/voronoi_N64.data, voronoi_N256.data, and copies of voronoi_N256.data
(tools/replicate_tissue.py) for more cells. For each, lmp runs --minima minimizations of no
iterations (each: setup, one force evaluation, then the stages: fix dpoly/check alone here;
1024/cells times as many below 1024 cells) under
`perf record` with call graphs, and the CPU time inside the check's functions is read from the
samples (children included): the whole check, its search for interpenetrating cells (the outlines
and DPoly::interpenetrating_cells) and, for comparison, its test for self-crossing rings. A
difference of two whole runs with and without the check is lost in the setup's noise at these
costs. For scale, the time of one force evaluation of the same tissue (a run of 20 steps without
an integrator, LAMMPS's loop time). One MPI rank: every rank does the same check on the gathered
vertices. Writes check_cost.csv and check_cost.png under --out and prints the table. Needs
linux-perf (Debian) with perf_event_paranoid <= 2 and python3-matplotlib; tools/setup.sh installs
neither perf nor any other profiler (only this benchmark uses it), so the script checks for perf
first and stops with the package to install.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

try:
    import matplotlib
except ImportError:
    sys.exit("check_cost: needs matplotlib (Debian: apt-get install python3-matplotlib)")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
import mesophyll_run  # noqa: E402
from regression import tissue_commands  # noqa: E402

MINIMA = """{check}thermo_style custom step pe
variable k loop {minima}
label again
minimize 0.0 0.0 0 0
next k
jump SELF again
"""
EVALUATIONS = """thermo_style custom step pe press
thermo {steps}
run {steps}
"""


def tissue(cells, workdir):
    """A data file of that many cells: a shipped Voronoi tissue or copies of the 256-cell one."""
    shipped = os.path.join(ROOT, "examples", "tissue", f"voronoi_N{cells}.data")
    if os.path.exists(shipped):
        return shipped
    copies = int(round((cells / 256) ** 0.5))
    if copies * copies * 256 != cells:
        sys.exit(f"check_cost: {cells} cells is neither a shipped tissue nor 256 x k^2")
    path = os.path.join(workdir, f"N{cells}.data")
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "replicate_tissue.py"),
                    os.path.join(ROOT, "examples", "tissue", "voronoi_N256.data"), path,
                    "--copies", str(copies), str(copies)], check=True, stdout=subprocess.DEVNULL)
    return path


# the check's functions whose time (children included) the samples give, by column name
FUNCTIONS = {"check_ms": "FixDPolyCheck::check",
             "interpenetration_ms": "FixDPolyCheck::interpenetrating_cells",
             "self_crossing_ms": "FixDPolyCheck::tangled_cells"}


def require_perf(workdir):
    """Stop with what to install or set when perf cannot sample here."""
    if shutil.which("perf") is None:
        sys.exit("check_cost: needs perf, which is not on PATH: install the Debian package "
                 "linux-perf (apt-get install linux-perf); tools/setup.sh does not")
    paranoid = "/proc/sys/kernel/perf_event_paranoid"
    if os.path.exists(paranoid):
        with open(paranoid) as f:
            level = int(f.read())
        if level > 2:
            sys.exit(f"check_cost: perf may not sample here: kernel.perf_event_paranoid is {level}, "
                     "needs <= 2 (sysctl kernel.perf_event_paranoid=2, as root)")
    probe = subprocess.run(["perf", "record", "-q", "-e", "cpu-clock", "-o", os.path.join(workdir, "probe.data"),
                            "--", "true"], capture_output=True, text=True)
    if probe.returncode != 0:
        sys.exit("check_cost: perf record fails here (exit code "
                 f"{probe.returncode}): {(probe.stderr or probe.stdout).strip()[:500]}")


def check_ms(lmp, data, minima, workdir):
    """{column: CPU ms per check} from perf samples of minima minimizations with the check."""
    path = os.path.join(workdir, "in.minima")
    with open(path, "w") as f:
        f.write(tissue_commands(data) + MINIMA.format(check="fix check all dpoly/check\n",
                                                      minima=minima))
    samples = os.path.join(workdir, "perf.data")
    # cpu-clock: the event count is then nanoseconds (the default event, where hardware counters
    # exist, counts cycles)
    subprocess.run(["perf", "record", "-q", "-e", "cpu-clock", "-F", "999", "--call-graph", "dwarf,8192", "-o",
                    samples, lmp, "-in", path, "-log", "none", "-screen", "none"], cwd=workdir,
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    report = subprocess.run(["perf", "report", "-i", samples, "--children", "--sort", "symbol",
                             "-g", "none", "--stdio"], capture_output=True, text=True,
                            check=True).stdout
    total_ns = float(re.search(r"Event count \(approx.\): (\d+)", report).group(1))
    result = {}
    for column, function in FUNCTIONS.items():
        # "  11.71%   0.00%  [.] LAMMPS_NS::FixDPolyCheck::check": the first is with children
        share = [float(m.group(1)) for m in re.finditer(
            r"^\s+([0-9.]+)%\s+[0-9.]+%\s+\[\.\] LAMMPS_NS::" + re.escape(function) + r"(?=\s)",
            report, re.M)]
        if not share and column == "check_ms":
            sys.exit(f"check_cost: no perf samples in {function} of {lmp}: a build without "
                     "symbols, or a check that did not run")
        result[column] = sum(share) / 100 * total_ns / 1e6 / minima
    os.remove(samples)
    return result


def evaluation_ms(lmp, data, workdir):
    steps = 20
    text = tissue_commands(data) + EVALUATIONS.format(steps=steps)
    with open(os.path.join(workdir, "in.evaluations"), "w") as f:
        f.write(text)
    loop = mesophyll_run.run(lmp, "in.evaluations", workdir, log="log.evaluations",
                             example=None).loops[-1]
    return loop.seconds / loop.steps * 1e3, loop.atoms


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--cells", type=int, nargs="+", default=[64, 256, 1024, 4096])
    p.add_argument("--minima", type=int, default=40)
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "results"))
    args = p.parse_args()

    rows = []
    with tempfile.TemporaryDirectory() as work:
        require_perf(work)
        for cells in args.cells:
            data = tissue(cells, work)
            # as many checks at every size as --minima at 1024 cells: enough samples
            check = check_ms(args.lmp, data, args.minima * max(1, 1024 // cells), work)
            evaluation, vertices = evaluation_ms(args.lmp, data, work)
            row = {"cells": cells, "vertices": vertices, **check,
                   "force_evaluation_ms": evaluation}
            rows.append(row)
            print(", ".join(f"{k} {v:.3f}" if isinstance(v, float) else f"{k} {v}"
                            for k, v in row.items()), flush=True)

    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "check_cost.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("\n| cells | vertices | check (ms) | of which interpenetration | of which self-crossing "
          "| one force evaluation (ms) |\n| --- | --- | --- | --- | --- | --- |")
    for r in rows:
        print(f"| {r['cells']} | {r['vertices']} | {r['check_ms']:.2f} | "
              f"{r['interpenetration_ms']:.2f} | {r['self_crossing_ms']:.2f} | "
              f"{r['force_evaluation_ms']:.2f} |")

    fig, ax = plt.subplots(figsize=(5, 3.6))
    cells = [r["cells"] for r in rows]
    for column, style, label in [("check_ms", "o-", "fix dpoly/check"),
                                 ("interpenetration_ms", "s--", "its interpenetration search"),
                                 ("self_crossing_ms", "d--", "its self-crossing test"),
                                 ("force_evaluation_ms", "^:", "one force evaluation")]:
        ax.loglog(cells, [r[column] for r in rows], style, label=label)
    ax.set_xlabel("cells")
    ax.set_ylabel("CPU ms (one rank)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "check_cost.png"), dpi=150)
    print(f"wrote {args.out}/check_cost.csv and check_cost.png")


if __name__ == "__main__":
    main()
