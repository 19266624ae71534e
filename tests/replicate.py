#!/usr/bin/env python3
"""A replicated tissue is the same tissue: energy per cell, pressure and tissue measures equal.

    replicate.py --lmp BUILD/lmp --example examples/mesophyll [--np N] [--mpirun CMD] ...

Copies examples/NAME/tissue_N16.data 2 x 2 and 3 x 1 times with tools/replicate_tissue.py,
evaluates the original and each copy with `run 0` (the main example's styles, Table 1
coefficients), both compressed by 3% (at the relaxed tissue the energies are so small, about 1e-10
per cell, that the round-off of shifted positions changes their ninth digit), and compares: energy per cell and its parts (bonds: segments and adhesion; bending;
contacts; areas), pressure, phi, phi_patch, mean calA and z, bonds per cell, to 1e-10 relative
(and 1e-20 absolute: the bending energy, zero at the tissue's preferred angles, is round-off).
A bond joined to the wrong copy of its partner is a segment half a box long and moves the
energy by orders of magnitude; a wrong image flag breaks a ring (fix dpoly/cells stops).
Standard library only.
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from regression import launch, parse_lmp_arguments, tissue_commands    # noqa: E402

TOOL = os.path.join(os.path.dirname(HERE), "tools", "replicate_tissue.py")
RTOL = 1e-10
ATOL = 1e-20
# after the tissue, compressed by 3% (see the docstring): the values compared
MEASURE = """compute tissue all dpoly/tissue
thermo_style custom step pe press ebond eangle evdwl f_cells c_tissue[1] c_tissue[2] c_tissue[3] c_tissue[4] c_tissue[5] c_tissue[6]
thermo_modify norm no format float %.17g
run 0 post no
"""
NAMES = ["pe", "press", "bond", "angle", "pair", "fix", "phi", "phi_patch", "calA", "z",
         "bonds", "cells"]
PER_CELL = {"pe", "bond", "angle", "pair", "fix", "bonds"}    # extensive: divided by cells


def evaluate(args, workdir, data):
    with open(os.path.join(workdir, "in.eval"), "w") as f:
        f.write(tissue_commands(data, "change_box all x scale 0.97 y scale 0.97 remap\n") + MEASURE)
    command, env = launch(args, ["-in", "in.eval", "-log", "none", "-echo", "none"])
    result = subprocess.run(command, cwd=workdir, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"replicate: lmp failed on {data}:\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
    lines = result.stdout.splitlines()
    header = next(k for k, line in enumerate(lines) if line.split()[:2] == ["Step", "PotEng"])
    values = [float(v) for v in lines[header + 1].split()[1:]]
    measured = dict(zip(NAMES, values))
    for name in PER_CELL:
        measured[name] /= measured["cells"]
    return measured


def main():
    args = parse_lmp_arguments(__doc__, lambda p: p.add_argument("--example", required=True))
    original = os.path.join(os.path.abspath(args.example), "tissue_N16.data")
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        reference = evaluate(args, work, original)
        for nx, ny in [(2, 2), (3, 1)]:
            copy = os.path.join(work, f"tissue_{nx}x{ny}.data")
            subprocess.run([sys.executable, TOOL, original, copy, "--copies", str(nx), str(ny)],
                           check=True)
            measured = evaluate(args, work, copy)
            if measured["cells"] != reference["cells"] * nx * ny:
                print(f"{nx}x{ny}: {measured['cells']:g} cells, expected "
                      f"{reference['cells'] * nx * ny:g}")
                failures += 1
            for name in NAMES[:-1]:
                a, b = reference[name], measured[name]
                ok = abs(a - b) <= RTOL * max(abs(a), abs(b)) + ATOL
                failures += not ok
                print(f"{nx}x{ny} {name:9s} original {a:.15g} copy {b:.15g}"
                      f"{'' if ok else '   <-- differs'}")
    if failures:
        sys.exit(f"replicate: {failures} values differ by more than {RTOL:g} relative")
    print("replicate: the copies equal the original")


if __name__ == "__main__":
    main()
