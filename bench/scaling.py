#!/usr/bin/env python3
"""How the cost of a growth step grows with the tissue: N cells on 1 and 2 ranks, and the same
thermo on oversubscribed ranks.

    bench/scaling.py [--lmp build/lmp] [--cells 64 256 1024] [--ranks 1 2] [--steps 3]
                     [--fnorm two|rms] [--ftol F]
                     [--check-cells 64] [--check-ranks 4 8] [--check-steps 2]
                     [--check-rtol 1e-9]
                     [--base examples/tissue/voronoi_N64.data] [--keep DIR [--report-only]]
                     [--csv bench/results/scaling.csv] [--png bench/results/scaling.png]

Tissues: N = 64 k^2 cells, k x k periodic copies of --base made by tools/replicate_tissue.py
(the same tissue at every size: what changes is the size, not the cells). Each runs the main
example, examples/mesophyll/in.mesophyll -var tissue FILE, for --steps minimizations (the first
relaxes the initial tissue to P0; each later one is a growth step), no restart files, with its
stopping rule (--fnorm two: LAMMPS's 2-norm of all forces below --ftol, default 1e-10, the
example's default; --fnorm rms: the root mean square force per degree of freedom below --ftol,
default 1e-12, the same at every size; in.mesophyll's -var fnorm and -var ftol). Per
minimization: FIRE iterations, vertices, the loop's wall seconds and its CPU seconds (LAMMPS's
"% CPU use" x wall x ranks), CPU microseconds per iteration per vertex, LAMMPS's per-rank memory
(the largest "Per MPI rank memory allocation", its mean x ranks per vertex, in bytes). The
growth-step cost is the mean over the growth steps (minimizations 2 on) that every run reached
(a killed run read by --report-only may have fewer); its slope against N is
fitted on log-log axes per rank count (CPU and wall), and so is that of the iterations per growth
step. The 2-rank speed-up is the ratio of wall loop times: on a machine shared with other jobs
it is not to be trusted (the CPU figures are).

Correctness: --check-cells cells run --check-steps minimizations (the relaxation of the initial
tissue to P0, then growth steps with their breaking, growth and vertex insertion) on 1 rank and on
each --check-ranks (oversubscribed: more ranks than cores); the first thermo row (the data file's
state) must agree to 1e-10 relative, every minimum's (energy, pressure, area, phi, phi_patch,
calA, z) to --check-rtol relative (default 1e-9) and its bond count exactly. The minima are
reached along paths whose round-off depends on the rank count, so they are not bitwise the same.

Prints a table, writes the CSV (one row per run and minimization, plus the fitted slopes and
the checks as rows of their own kind) and a log-log PNG (growth-step CPU seconds and iterations
against N). Not a test; record the machine and its load.
"""
import argparse
import csv
import math
import os
import platform
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_frames  # noqa: E402
import mesophyll_run  # noqa: E402

mesophyll_frames.require(["numpy", "matplotlib"])
import numpy as np  # noqa: E402

REPLICATE = os.path.join(ROOT, "tools", "replicate_tissue.py")
MEMORY = re.compile(r"Per MPI rank memory allocation \(min/avg/max\) = "
                    r"([0-9.eE+-]+) \| ([0-9.eE+-]+) \| ([0-9.eE+-]+) Mbytes")
FIELDS = ["kind", "cells", "ranks", "minimization", "growth_step", "vertices", "iterations",
          "wall_s", "cpu_s", "cpu_us_per_iteration_vertex", "memory_mb_per_rank",
          "memory_bytes_per_vertex", "value", "note"]
CHECK_COLUMNS = ["PotEng", "Press", "Volume", "c_tissue[1]", "c_tissue[2]", "c_tissue[3]",
                 "c_tissue[4]"]


def tissue(base, cells, work):
    """k x k copies of base (its cell count times k^2 = cells); the path of the data file."""
    match = re.search(r"N(\d+)", os.path.basename(base))
    if match is None:
        sys.exit(f"scaling: the base tissue's name must say its cells as N<cells> (as "
                 f"voronoi_N64.data), got {base}")
    base_cells = int(match.group(1))
    k = math.isqrt(cells // base_cells)
    if k * k * base_cells != cells:
        sys.exit(f"scaling: {cells} cells is not {base_cells} k^2 (the base tissue's copies)")
    path = os.path.join(work, f"scaling_N{cells}.data")
    if k == 1 or os.path.exists(path):     # the base itself, or made by an earlier run
        return base if k == 1 else path
    subprocess.run([sys.executable, REPLICATE, base, path + ".tmp", "--copies", str(k), str(k)],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.replace(path + ".tmp", path)     # whole, for a later bench that finds it
    return path


def develop(args, data, cells, ranks, steps, work):
    """Runs in.mesophyll on data for steps minimizations; returns (Run, CPU seconds or None).
    A finished run of the same size, ranks and steps already in the --keep folder is read
    instead (None, None with --report-only when there is none)."""
    rule = "" if args.fnorm == "two" and args.ftol == 1e-10 else f"_{args.fnorm}{args.ftol:g}"
    folder = os.path.join(work, f"N{cells}_np{ranks}_s{steps}{rule}")
    log, cpu_file = os.path.join(folder, "log.scaling"), os.path.join(folder, "process_cpu_s")
    text = open(log).read() if os.path.exists(log) else ""
    finished = "Total wall time" in text
    done = mesophyll_run.minimization_loops(mesophyll_run.loop_times(text))
    if finished or (args.report_only and len(done) >= 2):
        run = mesophyll_run.read(folder, "log.scaling")
        cpu = float(open(cpu_file).read()) if os.path.exists(cpu_file) else None
        print(f"(read the {'finished' if finished else 'UNFINISHED (killed)'} run in {folder}: "
              f"{len(run.minimizations)} minimizations)", flush=True)
    elif args.report_only:
        print(f"(no finished run of {cells} cells on {ranks} ranks in {work}: left out)",
              flush=True)
        return None, None
    else:
        variables = {"N": cells, "tissue": os.path.basename(data), "steps": steps,
                     "restart_every": 0, "phi_stop": 0, "fnorm": args.fnorm, "ftol": args.ftol}
        cpu = mesophyll_run.children_cpu_seconds()
        run = mesophyll_run.run(args.lmp, "in.mesophyll", folder, variables, ranks=ranks,
                                files=[data], log="log.scaling", capture=True)
        cpu = mesophyll_run.children_cpu_seconds() - cpu
        with open(cpu_file, "w") as f:
            f.write(f"{cpu:.3f}\n")
    if run.failures:
        sys.exit(f"scaling: fix dpoly/check failed at {cells} cells on {ranks} ranks: "
                 f"{run.failures[0].text}")
    return run, cpu


def rows_of(cells, ranks, run, rule):
    memory = [tuple(float(v) for v in m.groups()) for m in MEMORY.finditer(run.log)]
    largest = max(memory, key=lambda m: m[2])
    rows = []
    loops = mesophyll_run.minimization_loops(run.loops)
    for k, (loop, (iterations, _)) in enumerate(zip(loops, run.minimizations)):
        cpu = loop.seconds * (loop.cpu or 1.0) * loop.procs
        rows.append({"kind": "minimization", "cells": cells, "ranks": ranks,
                     "minimization": k + 1, "growth_step": "yes" if k > 0 else "no",
                     "vertices": loop.atoms, "iterations": iterations,
                     "wall_s": round(loop.seconds, 3), "cpu_s": round(cpu, 3),
                     "cpu_us_per_iteration_vertex": round(1e6 * cpu / (iterations * loop.atoms), 4),
                     "memory_mb_per_rank": largest[2],
                     "memory_bytes_per_vertex": round(largest[1] * ranks * 2**20 / loop.atoms),
                     "value": "", "note": rule})
    return rows


def slope(xs, ys):
    if len(xs) < 2:
        return float("nan")
    return float(np.polyfit(np.log(xs), np.log(ys), 1)[0])


def growth_cost(rows, cells, ranks, key):
    values = [r[key] for r in rows if r["kind"] == "minimization" and r["cells"] == cells
              and r["ranks"] == ranks and r["growth_step"] == "yes"]
    return sum(values) / len(values) if values else None


def check_ranks(args, data, work):
    """--check-steps minimizations on 1 rank and on each --check-ranks;
    [(ranks, largest relative difference at a minimum, note, passed)]."""
    reference, _ = develop(args, data, args.check_cells, 1, args.check_steps, work)
    results = []
    if reference is None:
        return results
    for ranks in args.check_ranks:
        run, _ = develop(args, data, args.check_cells, ranks, args.check_steps, work)
        if run is None:
            continue
        worst, problems = 0.0, []
        if len(run.thermo) != len(reference.thermo):
            problems.append(f"{len(run.thermo)} thermo tables, {len(reference.thermo)} on 1 rank")
        for k, ((ref_cols, ref_rows), (cols, rows)) in enumerate(zip(reference.thermo,
                                                                      run.thermo)):
            # the data file's state (first row of the first table) and every minimum
            compared = ([(0, 1e-10)] if k == 0 else []) + [(-1, args.check_rtol)]
            for row_index, rtol in compared:
                for name in CHECK_COLUMNS:
                    ref = ref_rows[row_index][ref_cols.index(name)]
                    val = rows[row_index][cols.index(name)]
                    rel = abs(val - ref) / max(abs(ref), 1e-300)
                    if row_index == -1:
                        worst = max(worst, rel)
                    if rel > rtol:
                        problems.append(f"minimization {k + 1} {name}: {val!r} vs {ref!r}")
            bonds = (ref_rows[-1][ref_cols.index("c_tissue[5]")],
                     rows[-1][cols.index("c_tissue[5]")])
            if bonds[0] != bonds[1]:
                problems.append(f"minimization {k + 1} bonds {bonds[1]} vs {bonds[0]}")
        iterations = ([m[0] for m in run.minimizations], [m[0] for m in reference.minimizations])
        note = (f"iterations {iterations[0]} ({iterations[1]} on 1 rank); "
                + ("; ".join(problems) if problems else "agrees"))
        results.append((ranks, worst, note, not problems))
    return results


def plot(rows, path, ranks_list, rule):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 4, figsize=(17, 4))
    for ranks in ranks_list:
        cells = sorted({r["cells"] for r in rows if r["kind"] == "minimization"
                        and r["ranks"] == ranks})
        for ax, key, label in ((axes[0], "cpu_s", "CPU s"), (axes[0], "wall_s", "wall s"),
                               (axes[1], "iterations", None),
                               (axes[2], "cpu_us_per_iteration_vertex", None),
                               (axes[3], "memory_bytes_per_vertex", None)):
            ys = [growth_cost(rows, n, ranks, key) for n in cells]
            pts = [(n, y) for n, y in zip(cells, ys) if y]
            if not pts:
                continue
            style = "o-" if key != "wall_s" else "s--"
            tag = f"{ranks} rank{'s' if ranks > 1 else ''}" + (f", {label}" if label else "")
            ax.loglog(*zip(*pts), style, label=f"{tag} (slope {slope(*zip(*pts)):.2f})")
    for ax, title in zip(axes, ("growth-step cost", "FIRE iterations per growth step",
                                "CPU us per iteration per vertex",
                                "LAMMPS memory, bytes per vertex")):
        ax.set_xlabel("cells N")
        ax.set_title(title)
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"MESOPHYLL growth-step scaling, {rule} ({platform.node()}; machine may be "
                 f"shared)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--cells", type=int, nargs="+", default=[64, 256, 1024])
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    p.add_argument("--steps", type=int, default=3,
                   help="minimizations per run: the relaxation, then steps-1 growth steps")
    p.add_argument("--check-cells", type=int, default=64)
    p.add_argument("--check-ranks", type=int, nargs="*", default=[4, 8])
    p.add_argument("--check-steps", type=int, default=2,
                   help="minimizations of the check runs (default 2: relaxation, growth step)")
    p.add_argument("--check-rtol", type=float, default=1e-9)
    p.add_argument("--base", default=os.path.join(ROOT, "examples", "tissue",
                                                  "voronoi_N64.data"))
    p.add_argument("--keep", default=None,
                   help="keep the runs' folders here; finished runs found there are read, "
                        "not rerun (a killed bench continues)")
    p.add_argument("--report-only", action="store_true",
                   help="run nothing: report the runs in --keep (also killed ones with a growth "
                        "step done, said so), leave out the rest")
    p.add_argument("--fnorm", choices=["two", "rms"], default="two",
                   help="in.mesophyll's stopping rule: two (LAMMPS's 2-norm, the default) or "
                        "rms (per degree of freedom)")
    p.add_argument("--ftol", type=float, default=None,
                   help="force tolerance (default 1e-10 with --fnorm two, 1e-12 with rms)")
    p.add_argument("--csv", default=os.path.join(HERE, "results", "scaling.csv"))
    p.add_argument("--png", default=os.path.join(HERE, "results", "scaling.png"))
    args = p.parse_args()
    if args.ftol is None:
        args.ftol = 1e-10 if args.fnorm == "two" else 1e-12
    if not args.ftol > 0.0:
        p.error(f"--ftol must be positive, got {args.ftol}")
    rule = f"fnorm {args.fnorm} ftol {args.ftol:g}"
    if args.steps < 2:
        p.error(f"--steps must be at least 2 (the relaxation and a growth step), got {args.steps}")
    if args.check_steps < 1:
        p.error(f"--check-steps must be at least 1, got {args.check_steps}")
    if any(n < 1 for n in args.cells + args.ranks + args.check_ranks):
        p.error("--cells, --ranks and --check-ranks must be positive")
    if not os.access(args.lmp, os.X_OK):
        p.error(f"--lmp {args.lmp}: no LAMMPS executable there (tools/setup.sh builds it)")
    args.lmp = os.path.abspath(args.lmp)
    if args.report_only and not args.keep:
        p.error("--report-only reads the runs of --keep DIR")
    work = args.keep or tempfile.mkdtemp(prefix="scaling.")
    os.makedirs(work, exist_ok=True)

    rows = []
    print(f"{'cells':>6} {'ranks':>5} {'min':>4} {'vertices':>8} {'iters':>7} {'wall s':>8} "
          f"{'CPU s':>8} {'CPU us/it/vertex':>16} {'MB/rank':>8} {'B/vertex':>8}", flush=True)
    for cells in args.cells:
        data = tissue(args.base, cells, work)
        for ranks in args.ranks:
            run, cpu = develop(args, data, cells, ranks, args.steps, work)
            if run is None:
                continue
            for r in rows_of(cells, ranks, run, rule):
                rows.append(r)
                print(f"{cells:>6} {ranks:>5} {r['minimization']:>4} {r['vertices']:>8} "
                      f"{r['iterations']:>7} {r['wall_s']:>8.1f} {r['cpu_s']:>8.1f} "
                      f"{r['cpu_us_per_iteration_vertex']:>16.3f} {r['memory_mb_per_rank']:>8.1f} "
                      f"{r['memory_bytes_per_vertex']:>8}", flush=True)
            if cpu is not None:
                rows.append({"kind": "process_cpu", "cells": cells, "ranks": ranks,
                             "value": round(cpu, 2), "note": "CPU s of the whole run (getrusage)"})

    # compare like with like: the growth steps that every run got to (a killed run has fewer)
    done = {}
    for r in rows:
        if r["kind"] == "minimization" and r["minimization"] > 1:
            key = (r["cells"], r["ranks"])
            done[key] = max(done.get(key, 0), r["minimization"] - 1)
    common = min(done.values()) if done else 0
    for r in rows:
        if r["kind"] == "minimization" and r["minimization"] - 1 > common:
            r["growth_step"] = "not compared"
    print(f"\ngrowth steps 1 to {common} (minimizations 2 to {common + 1}), means:")
    print(f"{'cells':>6} {'ranks':>5} {'iters':>8} {'wall s':>8} {'CPU s':>8} {'speed-up':>8}")
    for cells in args.cells:
        for ranks in args.ranks:
            wall = growth_cost(rows, cells, ranks, "wall_s")
            one = growth_cost(rows, cells, args.ranks[0], "wall_s")
            if wall is None or one is None:
                continue
            print(f"{cells:>6} {ranks:>5} {growth_cost(rows, cells, ranks, 'iterations'):>8.0f} "
                  f"{wall:>8.1f} {growth_cost(rows, cells, ranks, 'cpu_s'):>8.1f} "
                  f"{one / wall:>8.2f}")
            if ranks != args.ranks[0]:
                rows.append({"kind": "speedup", "cells": cells, "ranks": ranks,
                             "value": round(one / wall, 3),
                             "note": f"wall loop time on {args.ranks[0]} over {ranks} ranks "
                                     "(untrustworthy on a shared machine)"})
    print("\nfitted slopes against N (log-log, growth steps):")
    for ranks in args.ranks:
        for key in ("cpu_s", "wall_s", "iterations", "cpu_us_per_iteration_vertex"):
            pts = [(n, growth_cost(rows, n, ranks, key)) for n in args.cells]
            pts = [(n, y) for n, y in pts if y is not None]
            if len(pts) < 2:    # a slope needs two sizes; a nan row would read as a result
                print(f"  {ranks} rank(s) {key:>28}: fewer than 2 sizes ran")
                continue
            s = slope(*zip(*pts))
            print(f"  {ranks} rank(s) {key:>28}: {s:.3f}")
            rows.append({"kind": "slope", "ranks": ranks, "value": round(s, 3),
                         "note": f"{key} of a growth step against N = "
                                 f"{' '.join(str(n) for n, _ in pts)}"})

    if args.check_ranks:
        print(f"\ncorrectness: {args.check_steps} minimizations of {args.check_cells} cells, "
              "against 1 rank:")
        data = tissue(args.base, args.check_cells, work)
        ok = True
        for ranks, worst, note, passed in check_ranks(args, data, work):
            ok &= passed
            print(f"  {ranks} ranks: largest relative difference at the minimum {worst:.2e} "
                  f"(tolerance {args.check_rtol:g}); {note}")
            rows.append({"kind": "check", "cells": args.check_cells, "ranks": ranks,
                         "value": f"{worst:.3e}",
                         "note": f"{'PASS' if passed else 'FAIL'} rtol {args.check_rtol:g}: "
                                 f"{note}"})

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS, restval="")
        w.writeheader()
        w.writerows(rows)
    plot(rows, args.png, args.ranks, rule)
    print(f"\nwrote {args.csv} and {args.png}; runs in {work}")
    if args.check_ranks and not ok:
        sys.exit("scaling: the oversubscribed runs disagree with 1 rank (above)")


if __name__ == "__main__":
    main()
