#!/usr/bin/env python3
"""Does a shared liblammps (the build's default since LAMMPS's Python module needs it) cost speed
or change results? The same input with two lmp executables built from the same sources: one
linked against liblammps.so, one against liblammps.a.

    python3 bench/shared_library.py --shared build/lmp --static STATIC_LMP [--repeats 5]
                                    [--input in.mesophyll_short] [--var NAME VALUE ...]

Make STATIC_LMP from the same build folder: `cmake -DBUILD_SHARED_LIBS=OFF build && ninja -C
build lmp && cp build/lmp STATIC_LMP`, then `cmake -DBUILD_SHARED_LIBS=ON build && ninja -C build`
(each switch only relinks: the objects are compiled alike). The runs alternate between the two
executables (one rank, scratch copies of examples/mesophyll); per run it records the CPU seconds
of the LAMMPS process (user + system, from the kernel: robust when other jobs share the machine)
and the summed loop times, and checks that both executables print the same thermo tables, value
for value. Prints a table and writes bench/results/shared_library.csv and .png.
"""
import argparse
import csv
import os
import statistics
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_run    # noqa: E402

RESULTS = os.path.join(ROOT, "bench", "results")


def one_run(lmp, input_name, variables, work):
    before = mesophyll_run.children_cpu_seconds()
    run = mesophyll_run.run(lmp, input_name, work, variables, capture=True)
    cpu = mesophyll_run.children_cpu_seconds() - before
    return cpu, sum(loop.seconds for loop in run.loops), run.thermo


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--shared", required=True, help="lmp linked against liblammps.so")
    parser.add_argument("--static", required=True, help="lmp linked against liblammps.a")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--input", default="in.mesophyll_short")
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    parser.add_argument("--out", default=os.path.join(RESULTS, "shared_library"))
    args = parser.parse_args()
    variables = dict(args.var)
    variables.setdefault("restart_every", "0")
    executables = {"shared": os.path.abspath(args.shared), "static": os.path.abspath(args.static)}

    rows, thermo = [], {}
    with tempfile.TemporaryDirectory(prefix="shared_library_") as tmp:
        for repeat in range(args.repeats):
            order = ["shared", "static"] if repeat % 2 == 0 else ["static", "shared"]
            for kind in order:
                work = os.path.join(tmp, f"{kind}{repeat}")
                cpu, loops, blocks = one_run(executables[kind], args.input, variables, work)
                thermo.setdefault(kind, blocks)
                rows.append({"repeat": repeat, "library": kind, "cpu_s": cpu, "loop_s": loops})
                print(f"repeat {repeat} {kind:6s}: CPU {cpu:7.2f} s, loop time {loops:7.2f} s",
                      flush=True)

    same = thermo["shared"] == thermo["static"]
    n_rows = sum(len(r) for _, r in thermo["shared"])
    print(f"\n{args.input}, 1 rank, {args.repeats} runs each (alternating):")
    print(f"{'library':8s} {'CPU s median':>13s} {'min':>7s} {'max':>7s} {'loop s median':>14s}")
    summary = {}
    for kind in ("shared", "static"):
        cpu = [r["cpu_s"] for r in rows if r["library"] == kind]
        loops = [r["loop_s"] for r in rows if r["library"] == kind]
        summary[kind] = statistics.median(cpu)
        print(f"{kind:8s} {statistics.median(cpu):13.2f} {min(cpu):7.2f} {max(cpu):7.2f} "
              f"{statistics.median(loops):14.2f}")
    print(f"shared / static, median CPU: {summary['shared'] / summary['static']:.3f}")
    print(f"thermo tables ({n_rows} rows): {'identical' if same else 'DIFFERENT'}")

    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out + ".csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["repeat", "library", "cpu_s", "loop_s"],
                                lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib (Debian: python3-matplotlib): no plot")
    else:
        fig, ax = plt.subplots(figsize=(5, 3.5), constrained_layout=True)
        for x, kind in enumerate(("shared", "static")):
            cpu = [r["cpu_s"] for r in rows if r["library"] == kind]
            ax.plot([x] * len(cpu), cpu, "o", alpha=0.6)
            ax.plot([x - 0.2, x + 0.2], [statistics.median(cpu)] * 2, "k-")
        ax.set_xticks([0, 1], ["liblammps.so", "liblammps.a"])
        ax.set_xlim(-0.6, 1.6)
        ax.set_ylabel("CPU seconds per run")
        ax.set_title(f"{args.input}, 1 rank; thermo {'identical' if same else 'DIFFERENT'}")
        fig.savefig(args.out + ".png", dpi=110)
        plt.close(fig)
    print(f"wrote {args.out}.csv and .png")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
