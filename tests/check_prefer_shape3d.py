#!/usr/bin/env python3
"""Check examples/polyhedra/prefer_current_shape3d.py against tools/make_cells3d.py, standard
library only.

    check_prefer_shape3d.py ROOT SCRATCH_DIR

make_cells3d.py writes jittered cells across the periodic boundary whose preferred edge lengths,
bending angles and volumes are those of the written geometry; with every EdgeLengths and
EdgeAngles value and every v0 replaced by 1, the script must bring back each edge's length and
angle and each cell's volume (to round-off: it unwraps the written positions) and leave every
other line as it was. Exits 1 with the first difference.
"""
import os
import subprocess
import sys

root, scratch = sys.argv[1], sys.argv[2]
os.makedirs(scratch, exist_ok=True)
made, spoiled, redone = (os.path.join(scratch, n) for n in
                         ("shape3d_made.data", "shape3d_spoiled.data", "shape3d_redone.data"))
subprocess.run([sys.executable, os.path.join(root, "tools", "make_cells3d.py"), made, "--cells",
                "2", "--level", "1", "--jitter", "0.08", "--seed", "5", "--shift", "0.3",
                "--spacing", "1.3"], check=True)


def section_rows(lines, title):
    start = next(n for n, line in enumerate(lines) if line.startswith(title)) + 2
    end = start
    while end < len(lines) and lines[end].strip():
        end += 1
    return range(start, end)


with open(made) as f:
    original = f.read().split("\n")
rewritten = {}    # line index: first column that the script rewrites
for title in ("EdgeLengths", "EdgeAngles"):
    for n in section_rows(original, title):
        rewritten[n] = 1
for n in section_rows(original, "Vertices"):
    rewritten[n] = 2
spoilt = list(original)
for n, first in rewritten.items():
    w = spoilt[n].split()
    spoilt[n] = " ".join(w[:first] + ["1.0" if float(v) != 0.0 else v for v in w[first:]])
with open(spoiled, "w") as f:
    f.write("\n".join(spoilt))
subprocess.run([sys.executable, os.path.join(root, "examples", "polyhedra",
                                             "prefer_current_shape3d.py"), spoiled, redone],
               check=True)
with open(redone) as f:
    result = f.read().split("\n")

if len(result) != len(spoilt):
    sys.exit(f"{len(result)} lines written, {len(spoilt)} read")
worst = 0.0
for n, (want, got) in enumerate(zip(original, result)):
    if n in rewritten:
        a, b = [float(v) for v in want.split()[1:]], [float(v) for v in got.split()[1:]]
        if want.split()[0] != got.split()[0] or len(a) != len(b):
            sys.exit(f"line {n + 1}: '{got}' for '{want}'")
        worst = max([worst] + [abs(x - y) / max(1.0, abs(x)) for x, y in zip(a, b)])
    elif got != spoilt[n]:
        sys.exit(f"line {n + 1} changed: '{got}' for '{spoilt[n]}'")
print(f"largest relative difference from the generator's lengths, angles and volumes: "
      f"{worst:.3g}")
if worst > 1.0e-12:
    sys.exit("the script's preferred shape differs from the generator's")
