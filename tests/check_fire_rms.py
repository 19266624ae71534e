#!/usr/bin/env python3
"""min_style fire/nph's `min_modify rms yes`: a force tolerance per degree of freedom, the same at
every size.

    check_fire_rms.py --lmp BUILD/lmp --example examples/mesophyll [--np N] [--mpirun CMD] ...

The 16-cell tissue (examples/NAME/tissue_N16.data) and its 2 x 2 copy (tools/replicate_tissue.py),
both compressed by 3% so that there is something to relax, are minimized by fire/nph with the
main example's settings. Checked:

1. Fixed box. Every vertex of the copy feels the force of its original, so FIRE moves both alike:
   with rms yes the copy stops at the original's iteration with the original's energy per cell;
   with LAMMPS's 2-norm (rms no) at the same tolerance times sqrt(dof of the original) the
   original stops at that same iteration (the two rules are one rule at this size: the count of
   degrees of freedom is 2 per vertex), while the copy, whose 2-norm is twice the original's,
   must run longer.
2. Fix box/relax. The original relaxed at fixed box, then minimized at 50 times its pressure
   to a loose tolerance, met while the box is still far from it (the box's force is most of the
   root mean square): at the last step the root mean square of the
   vertex forces and the force on the box length, 2 (P - P0) L in 2d, over 2 x vertices + 1
   degrees of freedom, is below the tolerance, and at the step before it is not (thermo every
   step).
Standard library only.
"""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from regression import launch, parse_lmp_arguments, tissue_commands    # noqa: E402

TOOL = os.path.join(os.path.dirname(HERE), "tools", "replicate_tissue.py")
FTOL_RMS = 1.0e-9      # per degree of freedom: loose enough for a test of seconds
# with fix box/relax: so loose that the box is still far from P0_BOX at the stop
FTOL_RMS_BOX = 3.0e-2
P0 = 1.0e-3
# the box case: the tissue relaxed at fixed box, then at 50 times its pressure, so that the box's
# force dominates the root mean square where the minimization stops
P0_BOX = 5.0e-2
MINIMIZER = """min_style fire/nph
timestep 0.01
min_modify tmax 5 {modify}
thermo_style custom step pe press lx fnorm atoms
thermo_modify norm no format float %.17g
thermo 1
minimize 0.0 {ftol!r} 100000 1000000
"""


def minimize(args, workdir, data, modify, ftol, box):
    """Thermo rows (dicts) of one minimization of the compressed tissue in data."""
    after_read = "change_box all x scale 0.97 y scale 0.97 remap\n"
    commands = tissue_commands(data, after_read)
    if box:
        commands += MINIMIZER.format(modify=modify, ftol=FTOL_RMS)
        commands += f"fix relax all box/relax iso {P0_BOX} vmax 1.0e-3\n"
    commands += MINIMIZER.format(modify=modify, ftol=ftol)
    with open(os.path.join(workdir, "in.rms"), "w") as f:
        f.write(commands)
    command, env = launch(args, ["-in", "in.rms", "-log", "none", "-echo", "none"])
    result = subprocess.run(command, cwd=workdir, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"check_fire_rms: lmp failed on {data} ({modify}):\n"
                 f"{result.stdout[-2000:]}{result.stderr[-2000:]}")
    rows, header = [], None
    for line in result.stdout.splitlines():
        words = line.split()
        if words[:2] == ["Step", "PotEng"]:
            header, rows = words, []    # the last minimization's table
        elif words[:1] == ["Loop"]:
            header = None
        elif header and len(words) == len(header):
            rows.append(dict(zip(header, map(float, words))))
    if not rows or "force tolerance" not in result.stdout:
        sys.exit(f"check_fire_rms: {data} ({modify}) did not stop on the force tolerance:\n"
                 f"{result.stdout[-2000:]}")
    return rows


def rms(row, box):
    dof = 2 * row["Atoms"] + (1 if box else 0)
    box_force = 2.0 * (row["Press"] - P0_BOX) * row["Lx"] if box else 0.0
    return math.sqrt((row["Fnorm"] ** 2 + box_force ** 2) / dof)


def main():
    args = parse_lmp_arguments(__doc__, lambda p: p.add_argument("--example", required=True))
    original = os.path.join(os.path.abspath(args.example), "tissue_N16.data")
    failures = []
    with tempfile.TemporaryDirectory() as work:
        copy = os.path.join(work, "tissue_2x2.data")
        subprocess.run([sys.executable, TOOL, original, copy, "--copies", "2", "2"], check=True,
                       stdout=subprocess.DEVNULL)
        runs = {}
        for name, data in [("original", original), ("copy", copy)]:
            runs[name, "rms"] = minimize(args, work, data, "rms yes", FTOL_RMS, box=False)
        dof = 2 * runs["original", "rms"][0]["Atoms"]
        for name, data in [("original", original), ("copy", copy)]:
            runs[name, "two"] = minimize(args, work, data, "rms no", FTOL_RMS * math.sqrt(dof),
                                         box=False)
        its = {key: len(rows) - 1 for key, rows in runs.items()}
        for key, n in sorted(its.items()):
            print(f"fixed box, {key[0]:8s} {'rms yes' if key[1] == 'rms' else 'norm two':8s}: "
                  f"{n} iterations, pe per cell "
                  f"{runs[key][-1]['PotEng'] / (runs[key][-1]['Atoms'] / 32):.12g}")
        if its["copy", "rms"] != its["original", "rms"]:
            failures.append(f"rms yes: the copy stopped after {its['copy', 'rms']} iterations, "
                            f"the original after {its['original', 'rms']}")
        e_original = runs["original", "rms"][-1]["PotEng"]
        e_copy = runs["copy", "rms"][-1]["PotEng"] / 4
        if not abs(e_copy - e_original) <= 1e-9 * abs(e_original):
            failures.append(f"rms yes: energy per original tissue {e_copy!r} (copy) and "
                            f"{e_original!r} differ by more than 1e-9 relative")
        if its["original", "two"] != its["original", "rms"]:
            failures.append(f"the original: norm two at ftol x sqrt({dof:g}) stopped after "
                            f"{its['original', 'two']} iterations, rms yes after "
                            f"{its['original', 'rms']}")
        if not its["copy", "two"] > its["copy", "rms"]:
            failures.append(f"norm two: the copy stopped after {its['copy', 'two']} iterations, "
                            f"not later than with rms yes ({its['copy', 'rms']}): the test "
                            f"cannot tell the rules apart")

        rows = minimize(args, work, original, "rms yes", FTOL_RMS_BOX, box=True)
        last, before = rms(rows[-1], True), rms(rows[-2], True)
        box_force = 2.0 * (rows[-1]["Press"] - P0_BOX) * rows[-1]["Lx"]
        box_share = box_force ** 2 / (rows[-1]["Fnorm"] ** 2 + box_force ** 2)
        print(f"box/relax, original rms yes: {len(rows) - 1} iterations, rms at the last step "
              f"{last:.6g} (box force {100 * box_share:.2g}% of its square), at the step before "
              f"{before:.6g} (tolerance {FTOL_RMS_BOX:g})")
        # the thermo's pressure and length are rounded to 17 digits: a margin of 1e-6 relative
        if not last < FTOL_RMS_BOX * (1 + 1e-6):
            failures.append(f"box/relax: rms {last!r} at the last step is not below "
                            f"{FTOL_RMS_BOX}")
        if not box_share > 0.5:
            failures.append(f"box/relax: the box force is only {box_share:.3g} of the square "
                            f"at the stop: the test cannot see the box term")
        if not before >= FTOL_RMS_BOX * (1 - 1e-6):
            failures.append(f"box/relax: rms {before!r} at the step before the last is below "
                            f"{FTOL_RMS_BOX} already")
    if failures:
        sys.exit("check_fire_rms: " + "; ".join(failures))
    print("check_fire_rms: the rms rule stops the copy with the original, at the same rms")


if __name__ == "__main__":
    main()
