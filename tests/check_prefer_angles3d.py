#!/usr/bin/env python3
"""Check tools/prefer_current_angles3d.py against tools/make_cells3d.py, standard library only.

    check_prefer_angles3d.py TOOLS_DIR SCRATCH_DIR

make_cells3d.py writes jittered cells across the periodic boundary whose preferred bending angles
are those of the written geometry; with every EdgeAngles value set to 0, the tool must bring back
each edge's angle (to round-off: it unwraps the written positions) and leave every other line as
it was. Exits 1 with the first difference.
"""
import os
import subprocess
import sys

tools, scratch = sys.argv[1], sys.argv[2]
os.makedirs(scratch, exist_ok=True)
made, zeroed, redone = (os.path.join(scratch, n) for n in
                        ("angles3d_made.data", "angles3d_zeroed.data", "angles3d_redone.data"))
subprocess.run([sys.executable, os.path.join(tools, "make_cells3d.py"), made, "--cells", "2",
                "--level", "1", "--jitter", "0.08", "--seed", "3", "--shift", "0.3",
                "--spacing", "1.3"], check=True)


def section_rows(lines, title):
    start = next(n for n, line in enumerate(lines) if line.startswith(title)) + 2
    end = start
    while end < len(lines) and lines[end].strip():
        end += 1
    return start, end


with open(made) as f:
    original = f.read().split("\n")
start, end = section_rows(original, "EdgeAngles")
zero = list(original)
for n in range(start, end):
    w = zero[n].split()
    zero[n] = " ".join([w[0]] + ["0.0" if float(v) != 0.0 else v for v in w[1:]])
with open(zeroed, "w") as f:
    f.write("\n".join(zero))
subprocess.run([sys.executable, os.path.join(tools, "prefer_current_angles3d.py"), zeroed, redone],
               check=True)
with open(redone) as f:
    result = f.read().split("\n")

if len(result) != len(zero):
    sys.exit(f"{len(result)} lines written, {len(zero)} read")
worst = 0.0
for n, (want, got) in enumerate(zip(original, result)):
    if start <= n < end:
        a, b = [float(v) for v in want.split()[1:]], [float(v) for v in got.split()[1:]]
        if want.split()[0] != got.split()[0] or len(a) != len(b):
            sys.exit(f"EdgeAngles line {n + 1}: '{got}' for '{want}'")
        worst = max([worst] + [abs(x - y) for x, y in zip(a, b)])
    elif got != zero[n]:
        sys.exit(f"line {n + 1} changed: '{got}' for '{zero[n]}'")
print(f"largest difference from the generator's angles: {worst:.3g}")
if worst > 1.0e-12:
    sys.exit("the tool's angles differ from the generator's")
