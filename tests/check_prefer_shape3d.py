#!/usr/bin/env python3
"""Check tools/prefer_current_shape3d.py against tools/make_cells3d.py, standard library only.

    check_prefer_shape3d.py ROOT SCRATCH_DIR [--theta0-only]

make_cells3d.py writes jittered cells across the periodic boundary whose preferred edge lengths,
bending angles and volumes are those of the written geometry. With every EdgeLengths and
EdgeAngles value and every v0 replaced by 1, the tool must bring back each edge's length and
angle and each cell's volume (to round-off: it unwraps the written positions), or with
--theta0-only each edge's angle alone, leaving the lengths and volumes at 1, also with vertex 1
moved by a box length in its image flags; every other line stays as it was. Exits 1 with the
first difference.
"""
import argparse
import os
import subprocess
import sys

p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
p.add_argument("root")
p.add_argument("scratch")
p.add_argument("--theta0-only", action="store_true")
args = p.parse_args()
mode = "angles3d" if args.theta0_only else "shape3d"
os.makedirs(args.scratch, exist_ok=True)
made, spoiled, redone = (os.path.join(args.scratch, f"{mode}_{n}.data")
                         for n in ("made", "spoiled", "redone"))
subprocess.run([sys.executable, os.path.join(args.root, "tools", "make_cells3d.py"), made,
                "--cells", "2", "--level", "1", "--jitter", "0.08",
                "--seed", "3" if args.theta0_only else "5", "--shift", "0.3", "--spacing", "1.3"],
               check=True)


def section_rows(lines, title):
    start = next(n for n, line in enumerate(lines) if line.startswith(title)) + 2
    end = start
    while end < len(lines) and lines[end].strip():
        end += 1
    return range(start, end)


with open(made) as f:
    original = f.read().split("\n")
# line index: (first column of its values, whether the tool brings them back, whether they are
# angles: compared to round-off, lengths and volumes relative to their size)
values = {}
for title, first in (("EdgeLengths", 1), ("EdgeAngles", 1), ("Vertices", 2)):
    angles = title == "EdgeAngles"
    for n in section_rows(original, title):
        values[n] = (first, angles or not args.theta0_only, angles)
spoilt = list(original)
for n, (first, _, _) in values.items():
    w = spoilt[n].split()
    spoilt[n] = " ".join(w[:first] + ["1.0" if float(v) != 0.0 else v for v in w[first:]])
if args.theta0_only:
    # vertex 1 one box length away in x by its image flag: its hinges' angles need the nearest
    # images (a cell's volume needs consistent image flags, so the full check keeps them)
    n = next(n for n in section_rows(original, "Atoms") if spoilt[n].split()[0] == "1")
    w = spoilt[n].split()
    spoilt[n] = " ".join(w[:6] + [str(int(w[6]) + 1)] + w[7:])
with open(spoiled, "w") as f:
    f.write("\n".join(spoilt))
subprocess.run([sys.executable, os.path.join(args.root, "tools", "prefer_current_shape3d.py"),
                spoiled, redone] + (["--theta0-only"] if args.theta0_only else []), check=True)
with open(redone) as f:
    result = f.read().split("\n")

if len(result) != len(spoilt):
    sys.exit(f"{len(result)} lines written, {len(spoilt)} read")
worst = 0.0
for n, (want, got) in enumerate(zip(original, result)):
    if n in values and values[n][1]:
        a, b = [float(v) for v in want.split()[1:]], [float(v) for v in got.split()[1:]]
        if want.split()[0] != got.split()[0] or len(a) != len(b):
            sys.exit(f"line {n + 1}: '{got}' for '{want}'")
        absolute = values[n][2]
        worst = max([worst] + [abs(x - y) / (1.0 if absolute else max(1.0, abs(x)))
                               for x, y in zip(a, b)])
    elif got != spoilt[n]:
        sys.exit(f"line {n + 1} changed: '{got}' for '{spoilt[n]}'")
print(f"largest difference from the generator's {'angles' if args.theta0_only else 'shape'}: "
      f"{worst:.3g}")
if worst > 1.0e-12:
    sys.exit("the tool's preferred shape differs from the generator's")
