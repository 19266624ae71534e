#!/usr/bin/env python3
"""LAMMPS's balance command between minimizations of a MESOPHYLL tissue: atoms move to other
ranks and the package carries on with the same energy, pressure and minimum.

    check_balance.py --lmp BUILD/lmp --np N [launcher options of regression.py]

The 16-cell tissue (examples/mesophyll/tissue_N16.data, main example's styles, fix box/relax and
fire/nph) is minimized, then `balance 1.0 x 0.3` (with 2 ranks or more: rank 0 takes 30% of the
box, so vertices change rank) or `balance 1.0 shift xy 10 1.0`, then `run 0` and a second
minimization after a growth of every cell's a0 by 5%. Against the same input without the balance
command: the thermo rows after the balance (energy, pressure, area, packing) agree to 1e-10
relative and the second minimum to 1e-8 (FIRE's path sums forces in another order when the
atoms sit on other ranks), the bond count exactly, and the balance did move atoms (its
imbalance line before and after, or the per-rank atom counts, differ) on more than one rank.
`fix balance` is not tried: LAMMPS does not invoke it during minimization, the package's only
dynamics (Howto, "Running on a cluster").
"""
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from regression import launch, parse_lmp_arguments, thermo_blocks, tissue_commands  # noqa: E402

TISSUE = os.path.join(ROOT, "examples", "mesophyll", "tissue_N16.data")
COLUMNS = ["PotEng", "Press", "Volume", "c_tissue[1]", "c_tissue[2]"]
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def script(balance):
    return tissue_commands(TISSUE) + f"""
fix relax all box/relax iso 1.0e-3 vmax 1.0e-3
compute tissue all dpoly/tissue
thermo_style custom step pe press vol c_tissue[1] c_tissue[2] c_tissue[5]
thermo_modify norm no format float %20.15g
min_style fire/nph
timestep 0.01
min_modify tmax 5
minimize 0.0 1.0e-10 20000 200000
{balance}
run 0 post no
variable grown atom d_a0*1.05
set group all d_a0 v_grown
minimize 0.0 1.0e-10 20000 200000
"""


def run(args, work, name, balance):
    path = os.path.join(work, f"in.{name}")
    with open(path, "w") as f:
        f.write(script(balance))
    log = os.path.join(work, f"log.{name}")
    command, env = launch(args, ["-in", path, "-log", log, "-screen", "none"])
    result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"check_balance: {name} failed (exit {result.returncode}):\n"
                 f"{result.stdout[-3000:]}{result.stderr[-3000:]}")
    return log


def main():
    args = parse_lmp_arguments(__doc__)
    cut = "balance 1.0 x 0.3" if args.np > 1 else "balance 1.0 shift xy 10 1.0"
    with tempfile.TemporaryDirectory() as work:
        plain = thermo_blocks(run(args, work, "plain", ""))
        log = run(args, work, "balanced", cut)
        balanced = thermo_blocks(log)
        text = open(log).read()
    check(len(plain) == len(balanced) == 3, f"three thermo tables each ({len(balanced)})")
    for block, rtol in ((1, 1e-10), (2, 1e-8)):
        (cols_a, rows_a), (cols_b, rows_b) = plain[block], balanced[block]
        for name in COLUMNS:
            a, b = rows_a[-1][cols_a.index(name)], rows_b[-1][cols_b.index(name)]
            check(abs(a - b) <= rtol * abs(a),
                  f"{'after balance' if block == 1 else 'second minimum'}: {name} "
                  f"{b!r} vs {a!r} without balance (rtol {rtol:g})")
        bonds = (rows_a[-1][cols_a.index("c_tissue[5]")], rows_b[-1][cols_b.index("c_tissue[5]")])
        check(bonds[0] == bonds[1], f"bonds {bonds[1]} vs {bonds[0]}")
    if args.np > 1:
        # balance prints "  initial/final imbalance factor  = X Y"
        m = re.search(r"initial/final imbalance factor\s*=\s*([0-9.]+)\s+([0-9.]+)", text)
        factors = [float(v) for v in m.groups()] if m else []
        check(len(factors) == 2 and abs(factors[0] - factors[1]) > 0.05,
              f"the balance moved atoms between ranks (imbalance {factors})")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print(f"balance between minimizations on {args.np} rank(s): the same tissue")


if __name__ == "__main__":
    main()
