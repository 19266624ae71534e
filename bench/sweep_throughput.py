#!/usr/bin/env python3
"""Throughput of a sweep on LAMMPS partitions: the same sweep on 1 and on P partitions.

    bench/sweep_throughput.py [--lmp build/lmp] [--sweep examples/sweep/tiny.sweep]
                              [--steps 6] [--partitions 1 2] [--out bench/results]

Plans the sweep (with `fixed steps` replaced by --steps) once per partition count, runs
examples/sweep/in.sweep as `mpirun -np P lmp -partition Px1` (P = 1: plain lmp), and measures
the wall time of the whole sweep and the CPU time of its processes (user + system, from the
kernel's accounting of the children). Prints a table, writes sweep_throughput.csv and
sweep_throughput.png under --out: runs per hour, wall and CPU seconds against the partition
count. On a shared machine wall times depend on the other jobs; the CPU seconds do not, and the
speed-up is wall(1) / wall(P). Needs python3-matplotlib for the PNG.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_run  # noqa: E402
import mpi_launcher  # noqa: E402


def run(args, partitions, scratch):
    sweep_file = os.path.join(scratch, f"bench{partitions}.sweep")
    with open(args.sweep) as f:    # the sweep with its paths made absolute and --steps
        lines = []
        for line in f:
            words = line.split("#")[0].split()
            if words and words[0] in ("protocol", "parameters", "tissue"):
                here = os.path.dirname(os.path.abspath(args.sweep))
                line = " ".join([words[0]] + [os.path.join(here, w) for w in words[1:]]) + "\n"
            elif words and words[0] == "fixed":
                pairs = [p for p in zip(words[1::2], words[2::2]) if p[0] != "steps"]
                line = " ".join(["fixed", "steps", str(args.steps)] +
                                [w for p in pairs for w in p]) + "\n"
            lines.append(line)
    with open(sweep_file, "w") as f:
        f.writelines(lines)
    folder = os.path.join(scratch, f"p{partitions}")
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "sweep.py"), "plan", sweep_file,
                    folder], check=True, stdout=subprocess.DEVNULL)
    command = [args.lmp, "-in", os.path.join(ROOT, "examples", "sweep", "in.sweep")]
    if partitions > 1:
        command = command[:1] + ["-partition", f"{partitions}x1"] + command[1:]
    command, env = mpi_launcher.command(partitions, command)
    cpu0, wall0 = mesophyll_run.children_cpu_seconds(), time.perf_counter()
    subprocess.run(command, cwd=folder, env=env, check=True, stdout=subprocess.DEVNULL)
    wall, cpu = time.perf_counter() - wall0, mesophyll_run.children_cpu_seconds() - cpu0
    runs = len(os.listdir(os.path.join(folder, "runs")))
    finished = sum(os.path.exists(os.path.join(folder, "runs", r, "finished"))
                   for r in os.listdir(os.path.join(folder, "runs")))
    if finished != runs:
        sys.exit(f"sweep_throughput: {finished} of {runs} runs finished on {partitions} "
                 f"partitions")
    return {"partitions": partitions, "runs": runs, "steps": args.steps, "wall_s": wall,
            "cpu_s": cpu, "runs_per_hour": 3600 * runs / wall}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--sweep", default=os.path.join(ROOT, "examples", "sweep", "tiny.sweep"))
    p.add_argument("--steps", type=int, default=6)
    p.add_argument("--partitions", type=int, nargs="+", default=[1, 2])
    p.add_argument("--out", default=os.path.join(ROOT, "bench", "results"))
    p.add_argument("--plot-only", action="store_true",
                   help="draw the PNG from the CSV of an earlier run, without running")
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    path = os.path.join(args.out, "sweep_throughput.csv")
    if args.plot_only:
        rows = [{k: float(v) if k != "sweep" else v for k, v in r.items()}
                for r in csv.DictReader(open(path))]
        return plot(rows, args)
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        for partitions in args.partitions:
            rows.append(run(args, partitions, scratch))
    base = rows[0]["wall_s"]
    print(f"{'partitions':>10} {'runs':>5} {'steps':>5} {'wall s':>8} {'CPU s':>8} "
          f"{'runs/h':>8} {'speed-up':>8}")
    for r in rows:
        r["speed_up"] = base / r["wall_s"]
        print(f"{r['partitions']:>10} {r['runs']:>5} {r['steps']:>5} {r['wall_s']:>8.1f} "
              f"{r['cpu_s']:>8.1f} {r['runs_per_hour']:>8.0f} {r['speed_up']:>8.2f}")
    os.makedirs(args.out, exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {path}")
    plot(rows, args)


def plot(rows, args):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no PNG: python3-matplotlib is missing (Debian's python3 has it: "
              "/usr/bin/python3 bench/sweep_throughput.py --plot-only)")
        return
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), constrained_layout=True)
    x = [int(r["partitions"]) for r in rows]
    axes[0].bar([str(v) for v in x], [r["runs_per_hour"] for r in rows])
    axes[0].set_xlabel("partitions (1 rank each)")
    axes[0].set_ylabel("runs per hour")
    axes[1].plot(x, [r["wall_s"] for r in rows], "o-", label="wall")
    axes[1].plot(x, [r["cpu_s"] for r in rows], "s-", label="CPU (all processes)")
    axes[1].set_xlabel("partitions")
    axes[1].set_ylabel("seconds")
    axes[1].legend()
    fig.suptitle(f"{os.path.basename(args.sweep)}: {rows[0]['runs']:.0f} runs of "
                 f"{rows[0]['steps']:.0f} growth steps")
    png = os.path.join(args.out, "sweep_throughput.png")
    fig.savefig(png, dpi=110)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
