#!/usr/bin/env python3
"""Does low beta compact? Whole trajectories at Fig 5's base and low beta: the published code
against the package, from the same tissue.

    low_beta.py BINARY [--lmp build/lmp] [--work DIR] [--out low_beta.csv] [--seeds 1 2 3]
                [--jobs 2] [--resume]

--resume: a run that finished in DIR with the same command is read, not run again (a comparison
stopped and started again picks up where it was); only after no change to the binaries or the
inputs. A run that fails stops the comparison.

BINARY is the driver build.sh made. From tissue_N16.data (through make_input.py), with Fig 5's
base set (eps_b 0.4, theta0_min -3 pi/20) at P0 = 1e-5 (the pressure of fig5_late.sweep) and
beta 100 (the base) or 30 (the paper's "low beta compacts"), each run going on until phi_patch
falls to 0.3 or for 40 growth steps (fig5_late.sweep's rule), for each seed:

  * published: the driver (run.py --phi-stop 0.3 --steps 40), every frame measured by
    in.measure;
  * package_published_rules: in.mesophyll with the driver's cycle (rules published,
    break_start 2, steer mass);
  * package_sweep: in.mesophyll as fig5_late.sweep runs it (its defaults).

The seeds of the two codes draw from different generators: no seed of one corresponds to one of
the other. Per run, from the phi_patch of its recorded states (the published code's frames, the
package's minima): delta_phi_plus, the sum of the rises of phi_patch from one state to the next
(the same definition for both codes), the number of states that rose and the largest rise, and
the states in which fix dpoly/check finds cells whose outlines overlap (counted from 0, the
first state: 1 is the first minimum after growth), and the run's seconds (the driver: the sum of
its frames' wall_s; the package: LAMMPS's loop time).
"""
import os
import re
import sys

import same_tissue

BETAS = ("100", "30")
PHI_STOP, STEPS = "0.3", "40"
COLUMNS = ["beta", "code", "seed", "states", "phi_patch_end", "delta_phi_plus", "rises",
           "largest_rise", "states_interpenetrating", "first_interpenetrating_state",
           "seconds", "phi_patch_per_state"]
CHECK = re.compile(r"^fix dpoly/check: minimum (\d+) ")
LOOP = re.compile(r"^Loop time of (\S+)")


def compaction(phi):
    """(delta_phi_plus, rises, largest rise) of a sequence of phi_patch values."""
    rises = [b - a for a, b in zip(phi, phi[1:]) if b > a]
    return sum(rises), len(rises), max(rises, default=0.0)


def published(binary, lmp, work, beta, seed, resume):
    """phi_patch and the interpenetrating pairs of each frame of the driver's run, and its
    seconds."""
    rows = same_tissue.published(binary, lmp, work, f"published_beta{beta}_seed{seed}", seed,
                                 ["--phi-stop", PHI_STOP, "--steps", STEPS,
                                  "--set", f"betaEff={beta}"], resume)
    return ([float(r["phi_patch"]) for r in rows],
            [int(r["interpenetrating_pairs"]) for r in rows],
            sum(float(r["wall_s"]) for r in rows))


def package(lmp, work, beta, seed, mode, resume):
    """phi_patch and the interpenetrating pairs of each minimum of in.mesophyll's run, and its
    loop time."""
    folder = same_tissue.package(lmp, work, f"{mode}_beta{beta}_seed{seed}", mode,
                                 {"beta": beta, "steps": STEPS, "phi_stop": PHI_STOP,
                                  "seed": seed}, resume)
    with open(os.path.join(folder, "growth.N16.txt")) as f:
        header = f.readline().lstrip("# ").split()
        phi = [float(line.split()[header.index("phi_patch")]) for line in f if line.strip()]
    pairs, seconds = {}, 0.0
    for line in open(os.path.join(folder, "log.lammps")):
        m = CHECK.match(line)
        if LOOP.match(line):
            seconds += float(LOOP.match(line).group(1))
        if m:
            pairs[int(m.group(1))] = same_tissue.pairs_in(line)[0]
    if sorted(pairs) != list(range(1, len(phi) + 1)):
        sys.exit(f"{folder}: fix dpoly/check checked minima {sorted(pairs)}, the growth table "
                 f"has {len(phi)}")
    return phi, [pairs[k] for k in sorted(pairs)], seconds


def row(beta, code, seed, phi, pairs, seconds):
    plus, rises, largest = compaction(phi)
    bad = [k for k, n in enumerate(pairs) if n > 0]
    return [beta, code, seed, len(phi), f"{phi[-1]:.6f}", f"{plus:.6f}", rises,
            f"{largest:.6f}", len(bad), bad[0] if bad else "", f"{seconds:.1f}",
            " ".join(f"{x:.4f}" for x in phi)]


def summary(rows):
    """One line per (beta, code): runs, delta_phi_plus mean +- standard error, the runs with a
    rise, the mean number of states and the runs with interpenetrating cells."""
    lines = []
    for beta in dict.fromkeys(r[0] for r in rows):
        for code in dict.fromkeys(r[1] for r in rows):
            group = [r for r in rows if r[0] == beta and r[1] == code]
            plus = [float(r[5]) for r in group]
            n, mean = len(plus), sum(plus) / len(plus)
            se = (sum((x - mean) ** 2 for x in plus) / (n - 1) / n) ** 0.5 if n > 1 else 0.0
            lines.append(f"beta {beta:>3} {code:23} runs {n}  delta_phi_plus {mean:.4f} +- "
                         f"{se:.4f}  runs with a rise {sum(int(r[6]) > 0 for r in group)}  "
                         f"states {sum(int(r[3]) for r in group) / n:.1f}  runs with "
                         f"interpenetrating cells {sum(int(r[8]) > 0 for r in group)}")
    return lines


def main():
    p = same_tissue.arguments(__doc__, "low_beta")
    p.add_argument("--seeds", nargs="+", default=["1", "2", "3"])
    p.add_argument("--jobs", type=int, default=2, help="runs at a time (one core each)")
    p.add_argument("--resume", action="store_true",
                   help="read the runs that finished in --work with the same command")
    a = p.parse_args()
    if a.jobs < 1:
        p.error(f"--jobs must be at least 1, got {a.jobs}")
    lmp, binary = os.path.abspath(a.lmp), os.path.abspath(a.binary)
    same_tissue.driver_input(a.work)
    # seed by seed, so that a comparison stopped early has both betas of its first seeds
    tasks = [(beta, code, seed) for seed in a.seeds for beta in BETAS
             for code in ["published"] + list(same_tissue.PACKAGE_MODES)]

    def one(task):
        beta, code, seed = task
        if code == "published":
            result = published(binary, lmp, a.work, beta, seed, a.resume)
        else:
            result = package(lmp, a.work, beta, seed, code, a.resume)
        print(f"beta {beta} seed {seed} {code}: done", flush=True)
        return row(beta, code, seed, *result)

    rows = same_tissue.run_all(a.jobs, one, tasks)
    same_tissue.write_csv(a.out, COLUMNS, rows)
    width = max(len(c) for c in same_tissue.PACKAGE_MODES)
    print(f"{'beta':4} {'code':{width}} seed states phi_end dphi+   rises interpenetrating")
    for r in rows:
        print(f"{r[0]:4} {r[1]:{width}} {r[2]:4} {r[3]:6} {float(r[4]):.4f}  {float(r[5]):.4f}"
              f"  {r[6]:5} {r[8]}")
    print("\n".join(summary(rows)))
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
