#!/usr/bin/env python3
"""Engine limit: time per force evaluation per vertex, MESOPHYLL styles against LAMMPS's own.

    bench/engine.py [--lmp build/lmp] [--cells 64] [--steps 2000] [--csv bench/results/engine.csv]

The same atoms, bonds and angles (examples/tissue/tissue_N<cells>.data) under
  mesophyll: fix dpoly/cells + bond_style dpoly/segment + mesophyll/adhesion
             + angle_style dpoly/bending + pair_style dpoly/contact
  lammps:    bond_style harmonic + angle_style harmonic + pair_style soft (cutoff = max sigma)
evaluated 'steps' times at rest (run without an integrator: forces, energies and the virial every
step, no neighbor rebuilds). Prints microseconds per evaluation per vertex and the ratio; the goal
of the package is at most 1.5x. Standard library only.
"""
import argparse
import csv
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_run  # noqa: E402

COMMON = """units lj
dimension 2
atom_style molecular
boundary p p p
fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes
bond_style {bond_style}
angle_style {angle_style}
read_data {data} fix Vertices NULL Vertices extra/special/per/atom 40
special_bonds lj 1.0 1.0 1.0
comm_modify cutoff 3.0
"""
MESOPHYLL = """bond_coeff 1 dpoly/segment 1.0
bond_coeff 2 mesophyll/adhesion 1.0
angle_coeff * 0.4
pair_style dpoly/contact
pair_coeff * * 1.0
fix cells all dpoly/cells eps_a 1.0
"""
LAMMPS = """bond_coeff * 1.0 0.12
angle_coeff * 0.4 168.75
pair_style soft 0.12
pair_coeff * * 1.0
"""
RUN = """thermo_style custom step pe press
thermo {steps}
run {steps}
"""


def time_per_evaluation(lmp, text, steps, workdir, name):
    with open(os.path.join(workdir, f"in.{name}"), "w") as f:
        f.write(text)
    loop = mesophyll_run.run(lmp, f"in.{name}", workdir, log=f"log.{name}",
                             example=None).loops[-1]
    return loop.seconds / loop.steps / loop.atoms * 1e6, loop.atoms


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--cells", type=int, default=64)
    p.add_argument("--steps", type=int, default=2000)
    p.add_argument("--csv", default=os.path.join(ROOT, "bench", "results", "engine.csv"))
    args = p.parse_args()
    lmp = os.path.abspath(args.lmp)
    data = os.path.join(ROOT, "examples", "tissue", f"tissue_N{args.cells}.data")
    with tempfile.TemporaryDirectory() as workdir:
        ours, natoms = time_per_evaluation(
            lmp, COMMON.format(bond_style="hybrid dpoly/segment mesophyll/adhesion",
                               angle_style="dpoly/bending", data=data) + MESOPHYLL +
            RUN.format(steps=args.steps), args.steps, workdir, "mesophyll")
        theirs, _ = time_per_evaluation(
            lmp, COMMON.format(bond_style="harmonic", angle_style="harmonic", data=data) + LAMMPS +
            RUN.format(steps=args.steps), args.steps, workdir, "lammps")
    print(f"{args.cells} cells, {natoms} vertices, {args.steps} force evaluations, 1 rank")
    print(f"MESOPHYLL styles: {ours:.3f} us per evaluation per vertex")
    print(f"LAMMPS harmonic bond + harmonic angle + soft pair: {theirs:.3f} us")
    print(f"ratio {ours / theirs:.2f} (goal <= 1.5)")
    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["cells", "vertices", "evaluations", "mesophyll_us", "lammps_us", "ratio"])
        writer.writerow([args.cells, natoms, args.steps, f"{ours:.4f}", f"{theirs:.4f}",
                         f"{ours / theirs:.3f}"])
    print(f"wrote {args.csv}")


if __name__ == "__main__":
    main()
