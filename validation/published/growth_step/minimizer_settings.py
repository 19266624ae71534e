#!/usr/bin/env python3
"""Which minimum one growth step ends in, by min_style fire/nph setting, against the published code.

    minimizer_settings.py --lmp build/lmp [--frames validation/published/growth_step]
                          [--csv OUT.csv] [--variant NAME KEY=VALUE ... ] ...

From the published code's relaxed tissue (published_frame_0.data) the package grows once with
fix mesophyll/grow rules published (the published code's own growth step, equal to its frame 1's
sigma, l0, theta0 and a0 to 3e-7: ctest mesophyll.published_growth), then minimizes the enthalpy
U + P0 A at P0 = 1e-3 with fix box/relax iso and min_style fire/nph under each variant's
settings, and measures the minimum with compute dpoly/tissue: phi_patch, mean calA, mean z, box
area, enthalpy and FIRE iterations. The published code's own minimum (published_frame_1.data,
the same grown state minimized by its mesoEnthalpyFIRE) is measured the same way, as the
target. Keys of a variant (defaults: in.mesophyll's settings): timestep, tmax, tmin, alpha0,
boxmass, steer (min_modify), vmax (fix box/relax). Without --variant the built-in list runs. Each
variant is one lmp run on one rank (seconds). Standard library only.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from regression import tissue_commands    # noqa: E402

P0 = 1.0e-3
DEFAULT = {"timestep": "0.01", "tmax": "5", "tmin": "0.02", "alpha0": "0.25", "boxmass": "1",
           "steer": "force", "vmax": "1.0e-3"}
# The published mesoEnthalpyFIRE after this growth step: dt = 0.01 x the smallest of 1, min l0
# and min radius (0.0725 here), growing to 20 dt, shrinking to 0.1 dt, alpha0 0.2; the box area V
# moves with mass 1, i.e. the box length L with mass 4V = 4 x 34.5 = 138, which is boxmass
# 138 / (M/6) = 1.6 for M = 512 vertices of mass 1; the box strain per step is not capped; its
# steering is mass-weighted (steer mass).
PUBLISHED_LIKE = {"timestep": "7.25e-4", "tmax": "20", "tmin": "0.1", "alpha0": "0.2",
                  "boxmass": "1.6", "steer": "mass", "vmax": "1.0"}
MASS = {"steer": "mass"}    # -var steer mass of in.mesophyll
VARIANTS = [
    ("in.mesophyll (steer force)", {}),
    ("steer force, boxmass 0.1", {"boxmass": "0.1"}),
    ("steer force, boxmass 10", {"boxmass": "10"}),
    ("steer force, boxmass 100", {"boxmass": "100"}),
    ("steer force, vmax 1e-4", {"vmax": "1.0e-4"}),
    ("steer force, vmax 1e-2", {"vmax": "1.0e-2"}),
    ("steer force, timestep 0.001", {"timestep": "0.001"}),
    ("steer force, timestep 0.001 tmax 20", {"timestep": "0.001", "tmax": "20"}),
    ("steer force, as published otherwise", dict(PUBLISHED_LIKE, steer="force")),
    ("steer mass", MASS),
    ("steer mass, boxmass 1.6", dict(MASS, boxmass="1.6")),
    ("steer mass, vmax 1e-2", dict(MASS, vmax="1.0e-2")),
    ("steer mass, as published", PUBLISHED_LIKE),
]

GROW = """fix grow all mesophyll/grow delta_a 0.5 lambda 5 c_L 0.5 c_B 4 &
    theta0_min -0.3141592653589793 rules published
# at frame 0's own pressure (the atoms hardly move); fix dpoly/cells grows the cells after it
fix relax all box/relax iso 4.7963078e-05 vmax 1.0e-3
min_style fire/nph
timestep 0.01
min_modify tmax 5
minimize 0.0 1.0e-10 200000 2000000
unfix grow
unfix relax
variable start equal $(step)
fix relax all box/relax iso {P0} vmax {vmax}
timestep {timestep}
min_modify tmax {tmax} tmin {tmin} alpha0 {alpha0} boxmass {boxmass} steer {steer}
compute tissue all dpoly/tissue
thermo 100000
minimize 0.0 1.0e-10 2000000 20000000
"""
MEASURE = """compute tissue all dpoly/tissue
variable start equal $(step)
run 0
"""
RESULT = """print "RESULT $(c_tissue[2]:%.6f) $(c_tissue[3]:%.6f) $(c_tissue[4]:%.4f) \
$(vol:%.12g) $(pe+{P0}*vol:%.12g) $(step-v_start)"
"""
COLUMNS = ["variant", "phi_patch", "calA", "z", "box_area", "enthalpy", "iterations"]


def run(lmp, commands, work, launch=None):
    """Run commands in work; return the RESULT line's numbers (COLUMNS[1:]). launch(arguments)
    gives (command line, environment) for lmp's arguments (default: lmp on one rank)."""
    with open(os.path.join(work, "in.step"), "w") as f:
        f.write(commands)
    arguments = ["-in", "in.step", "-log", "log.step", "-echo", "none"]
    command, env = launch(arguments) if launch else ([lmp] + arguments, None)
    out = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True)
    line = next((w for w in out.stdout.splitlines() if w.startswith("RESULT")), None)
    if out.returncode != 0 or line is None:
        sys.exit(f"minimizer_settings: lmp failed in {work}:\n{out.stdout[-2000:]}"
                 f"{out.stderr[-2000:]}")
    return [float(w) for w in line.split()[1:]]


def published_minimum(lmp, frames, work, launch=None):
    """The published code's minimum after its first growth step (frame 1), measured."""
    return run(lmp, tissue_commands(os.path.join(frames, "published_frame_1.data")) +
               MEASURE + RESULT.format(P0=P0), work, launch)


def package_minimum(lmp, frames, changes, work, launch=None):
    """Frame 0 grown by rules published and minimized with in.mesophyll's settings but for
    changes ({key: value}), measured."""
    unknown = set(changes) - set(DEFAULT)
    if unknown:
        sys.exit(f"minimizer_settings: unknown setting {sorted(unknown)}")
    commands = (tissue_commands(os.path.join(frames, "published_frame_0.data")) +
                GROW.format(P0=P0, **dict(DEFAULT, **changes)) + RESULT.format(P0=P0))
    return run(lmp, commands, work, launch)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--frames", default=HERE)
    p.add_argument("--csv", default=None, help="write the table here as well")
    p.add_argument("--variant", nargs="+", action="append", metavar="NAME KEY=VALUE",
                   help="a variant: its name, then settings that differ from in.mesophyll's")
    args = p.parse_args()
    lmp = os.path.abspath(args.lmp)
    frames = os.path.abspath(args.frames)
    variants = VARIANTS
    if args.variant:
        variants = [(v[0], dict(kv.split("=", 1) for kv in v[1:])) for v in args.variant]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        rows.append(["published code (frame 1)"] + published_minimum(lmp, frames, work))
        for name, changes in variants:
            rows.append([name] + package_minimum(lmp, frames, changes, work))
            print(" ".join(str(v) for v in rows[-1]), flush=True)
    print("\n| " + " | ".join(COLUMNS) + " |\n|" + " --- |" * len(COLUMNS))
    for r in rows:
        print(f"| {r[0]} | {r[1]:.4f} | {r[2]:.4f} | {r[3]:.3f} | {r[4]:.3f} | {r[5]:.6f} | "
              f"{int(r[6])} |")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(COLUMNS)
            w.writerows(rows)


if __name__ == "__main__":
    main()
