#!/usr/bin/env python3
"""Vertices per cell: the same 16 cells at n = 12 ... 64 vertices, grown with and without refinement.

    bench/vertices_per_cell.py [--lmp build/lmp] [--vertices 12 16 24 32 48 64] [--steps 30]
                               [--phi-stop 0.5] [--budget 0.03] [--quick]
                               [--csv bench/results/vertices_per_cell.csv]
                               [--png bench/results/vertices_per_cell.png]

Each tissue is examples/mesophyll/tissue_N16.data resampled by tools/resample_tissue.py (same
cells, same ring stretching stiffness, bending rigidity and preferred curvature; sigma kept).
Each runs examples/mesophyll/in.mesophyll -var N 16 (default parameter set, one seed) to
phi_patch 0.5 or --steps growth steps, through tools/mesophyll_run.py, in a copy of the input
that reads the stiffness factors d_kl, d_kb of the data file (fix Stiffness) and refines with
fix dpoly/refine rules consistent (-var refine consistent) or not at all (-var refine none). Per run: mean calA against phi_patch, its RMSD from the n = 64 run of the
same refinement and from n = 64 with refinement (on their common phi_patch range,
bench/speed_accuracy.py's measure), z at phi_patch 0.5, growth steps to 0.5, loop time (wall and
CPU of the minimizations) and FIRE iterations. Also the first growth step's change of each
cell's preferred perimeter sum(l0) and of the preferred curvature theta0/lbar of its void-facing
vertices, at n = 16, 32, 64: whether fix mesophyll/grow's rules are resolution-consistent.
Prints tables, writes CSV and PNG, and names the coarsest start (and its cost) whose calA stays
within --budget of n = 64 with refinement; and, at n = 32, the RMSD between runs with other
bond-breaking seeds (--spread-seeds), the floor below which no resolution can be told apart
from another. --quick: 2 growth steps, n = 16 and 32.
Needs python3-numpy and python3-matplotlib.
"""
import argparse
import csv
import math
import os
import shutil
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import mesophyll_run  # noqa: E402
import resample_tissue  # noqa: E402
from speed_accuracy import along_phi, errors, plt  # noqa: E402

SOURCE = os.path.join(ROOT, "examples", "mesophyll", "tissue_N16.data")
# the copy of in.mesophyll: stiffness factors from the data file, FIRE's tmax a variable
# (patched_input() also appends a write_data of the tissue at the end); refinement is -var refine
EDITS = [("read_data       ${tissue} fix Vertices NULL Vertices",
          "read_data       ${tissue} fix Vertices NULL Vertices fix Stiffness NULL Stiffness"),
         ("set             group all d_kl 1.0\nset             group all d_kb 1.0\n", ""),
         ("min_modify      tmax 5", "min_modify      tmax ${tmax}")]
THETA0_MIN = -math.pi / 10    # the default parameter set's, at 32 vertices per cell


def per_vertex_settings(n, scale):
    """-var values that keep the 32-vertex physics at n (scale) or the package's (not scale).
    theta0_min bounds theta0 = kappa0 lbar: the same curvature bound is theta0_min 32/n.
    FIRE's largest step timestep x tmax (0.05) must stay below 2/omega_max, and the bending
    modes' omega_max grows as sqrt(d_kb)/lbar ~ n^1.5: tmax 5 (32/n)^1.5 above 32."""
    if not scale:
        return {"tmax": 5}
    return {"theta0_min": THETA0_MIN * 32 / n, "tmax": 5 * min(1.0, (32 / n) ** 1.5)}


def patched_input(workdir):
    with open(os.path.join(workdir, "in.mesophyll")) as f:
        text = f.read()
    for old, new in EDITS:
        if text.count(old) != 1:
            raise SystemExit(f"in.mesophyll changed: cannot find '{old}' once; update EDITS")
        text = text.replace(old, new)
    with open(os.path.join(workdir, "in.vertices"), "w") as f:
        f.write(text + "write_data      grown.data nocoeff\n")
    return "in.vertices"


def run(lmp, tissue, refine, steps, phi_stop, workdir, settings):
    mesophyll_run.scratch(workdir)
    shutil.copy(tissue, os.path.join(workdir, "tissue_N16.data"))
    result = mesophyll_run.run(lmp, patched_input(workdir), workdir,
                               dict({"N": 16, "steps": steps, "phi_stop": phi_stop,
                                     "refine": refine,
                                     "restart_every": 0}, **settings),
                               example=None, check=False)
    record = {k: np.array(v) for k, v in result.growth[16].items()}
    # a run that stopped with an error keeps the growth steps it recorded
    errors_ = [line for line in result.log.splitlines() if line.startswith("ERROR")]
    record["error"] = errors_[0][:120] if errors_ else ""
    record["wall"] = sum(loop.seconds for loop in result.loops)
    record["cpu"] = sum(loop.seconds * (loop.cpu or 1.0) for loop in result.loops)
    record["iterations"] = sum(iterations for iterations, _ in result.minimizations)
    record["failures"] = len(result.failures)
    grown = os.path.join(workdir, "grown.data")
    record["vertices_end"] = len(resample_tissue.read_sections(grown)[1]["Atoms"]) \
        if os.path.exists(grown) else ""
    return record


def growth_step(lmp, tissue, workdir, settings):
    """What the first growth step (no refinement) does to the rings: mean over cells of the
    change of sum(l0) and of the void-facing fraction; mean change of kappa0 = theta0/lbar over
    void-facing vertices (drift and smoothing) and its RMS over bonded ones (smoothing alone)."""
    run(lmp, tissue, "none", 1, 0.0, workdir, settings)
    before = {v["tag"]: v for ring in resample_tissue.read_tissue(tissue)[1] for v in ring}
    grown = os.path.join(workdir, "grown.data")
    _, rings = resample_tissue.read_tissue(grown)
    bonded = {int(w[i]) for w in resample_tissue.read_sections(grown)[1]["Bonds"]
              if w[1] == "2" for i in (2, 3)}
    d_perimeter, void_fraction, drift, smoothing = [], [], [], []
    for ring in rings:
        d_perimeter.append(sum(v["l0"] - before[v["tag"]]["l0"] for v in ring))
        void_fraction.append(np.mean([v["tag"] not in bonded for v in ring]))
        for k, v in enumerate(ring):
            lbar = 0.5 * (before[ring[k - 1]["tag"]]["l0"] + before[v["tag"]]["l0"])
            d_kappa = (v["theta0"] - before[v["tag"]]["theta0"]) / lbar
            (smoothing if v["tag"] in bonded else drift).append(d_kappa)
    return {"dL0": float(np.mean(d_perimeter)), "void": float(np.mean(void_fraction)),
            "drift": float(np.mean(drift)),
            "smoothing": float(np.sqrt(np.mean(np.square(smoothing))))}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--vertices", type=int, nargs="+", default=[12, 16, 24, 32, 48, 64])
    p.add_argument("--steps", type=int, default=30, help="at most this many growth steps")
    p.add_argument("--phi-stop", type=float, default=0.5, help="stop below this phi_patch")
    p.add_argument("--budget", type=float, default=0.03, help="largest calA RMSD from n = 64")
    p.add_argument("--quick", action="store_true", help="2 growth steps (n = 16 and 32 unless --vertices)")
    p.add_argument("--package-settings", action="store_true",
                   help="theta0_min and FIRE's tmax as the package has them at every n "
                        "(default: scaled with n, see per_vertex_settings)")
    p.add_argument("--spread-seeds", type=int, nargs="*", default=[11, 12],
                   help="other bond-breaking seeds run at n = 32: the calA RMSD between seeds "
                        "at one resolution, the floor against which the budget is read")
    p.add_argument("--csv", default=os.path.join(ROOT, "bench", "results",
                                                 "vertices_per_cell.csv"))
    p.add_argument("--png", default=os.path.join(ROOT, "bench", "results",
                                                 "vertices_per_cell.png"))
    args = p.parse_args()
    if args.quick:
        args.steps = 2
        if args.vertices == p.get_default("vertices"):
            args.vertices = [16, 32]
    lmp = os.path.abspath(args.lmp)
    finest = max(args.vertices)
    records = {}
    growth = {}
    spread = {}    # (seed, refinement): n = 32 runs with other breaking seeds
    with tempfile.TemporaryDirectory() as root:
        for n in args.vertices:
            tissue = os.path.join(root, f"tissue_n{n}.data")
            resample_tissue.main([SOURCE, str(n), tissue, "--lmp", lmp])
            settings = per_vertex_settings(n, not args.package_settings)
            for refine in ("consistent", "none"):
                r = records[n, refine] = run(lmp, tissue, refine, args.steps, args.phi_stop,
                                             os.path.join(root, f"n{n}_{refine}"), settings)
                print(f"n {n:3d} {refine:10s} steps {len(r['step']):3d} phi_patch "
                      f"{r['phi_patch'][-1]:.3f} wall {r['wall']:7.1f} s iterations "
                      f"{r['iterations']:8d} {r['error']}", flush=True)
            if n in (16, 32, 64):
                growth[n] = growth_step(lmp, tissue, os.path.join(root, f"n{n}_grow"),
                                        settings)
            if n == 32:
                for seed in args.spread_seeds:
                    for refine in ("consistent", "none"):
                        spread[seed, refine] = run(
                            lmp, tissue, refine, args.steps, args.phi_stop,
                            os.path.join(root, f"n{n}_{refine}_{seed}"),
                            dict(settings, seed=seed))

    rows = []
    reference = records[finest, "consistent"]
    for (n, refine), r in records.items():
        same = records[finest, refine]
        reached = np.nonzero(r["phi_patch"] <= 0.5)[0]
        row = {"vertices": n, "refinement": refine,
               "calA_rmsd_vs_64_same": errors(r, same)["calA_rmsd"],
               "calA_rmsd_vs_64_refined": errors(r, reference)["calA_rmsd"],
               "z_at_0.5": float(along_phi(r, "z", [max(0.5, r["phi_patch"].min())])[0]),
               "phi_patch_end": float(r["phi_patch"][-1]),
               "steps_to_0.5": int(r["step"][reached[0]]) if len(reached) else "",
               "steps": len(r["step"]), "loop_wall_s": round(r["wall"], 1),
               "loop_cpu_s": round(r["cpu"], 1), "fire_iterations": r["iterations"],
               "vertices_end": r["vertices_end"], "check_failures": r["failures"],
               "error": r["error"]}
        rows.append(row)
    rows.sort(key=lambda row: (row["refinement"], row["vertices"]))
    header = ("   n refinement  RMSD(64 same) RMSD(64 ref)  z@0.5  phi_end  steps->0.5  "
              "wall s   cpu s   iterations")
    print(header)
    for row in rows:
        print(f"{row['vertices']:4d} {row['refinement']:10s} {row['calA_rmsd_vs_64_same']:12.4f} "
              f"{row['calA_rmsd_vs_64_refined']:12.4f} {row['z_at_0.5']:6.2f} "
              f"{row['phi_patch_end']:8.3f} {str(row['steps_to_0.5']):>10s} "
              f"{row['loop_wall_s']:8.1f} {row['loop_cpu_s']:7.1f} {row['fire_iterations']:11d}")
    within = [row for row in rows if row["calA_rmsd_vs_64_refined"] <= args.budget and
              row["vertices"] != finest]
    if within:
        best = min(within, key=lambda row: (row["vertices"], row["loop_cpu_s"]))
        print(f"coarsest start within calA RMSD <= {args.budget} of n = {finest} with refinement: "
              f"n = {best['vertices']}, refinement {best['refinement']} ({best['loop_cpu_s']} s "
              f"CPU, {best['fire_iterations']} iterations; n = {finest}: "
              f"{round(reference['cpu'], 1)} s, {reference['iterations']})")
    else:
        print(f"no start coarser than n = {finest} within calA RMSD <= {args.budget}")

    if spread and 32 in args.vertices:
        print("n = 32, other bond-breaking seeds (the seed-to-seed floor of the RMSD):")
        seed_rows = []
        for (seed, refine), r in sorted(spread.items()):
            rmsd = errors(r, records[32, refine])["calA_rmsd"]
            seed_rows.append({"seed": seed, "refinement": refine, "calA_rmsd_vs_default_seed":
                              rmsd, "phi_patch_end": float(r["phi_patch"][-1])})
            print(f"  seed {seed:6d} {refine:10s} calA RMSD from the default seed {rmsd:.4f}")
        with open(os.path.splitext(args.csv)[0] + "_seeds.csv", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(seed_rows[0].keys()))
            writer.writeheader()
            writer.writerows(seed_rows)

    print("first growth step, no refinement (void: void-facing fraction of the vertices):")
    print("   n   void   d sum(l0)/cell  d sum(l0)/void  mean d kappa0 (void)  "
          "rms d kappa0 (bonded: smoothing)")
    for n, g in sorted(growth.items()):
        print(f"{n:4d} {g['void']:6.3f} {g['dL0']:15.4f} {g['dL0'] / g['void']:15.4f} "
              f"{g['drift']:21.4f} {g['smoothing']:20.5f}")
    if growth:
        with open(os.path.splitext(args.csv)[0] + "_growth.csv", "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["vertices", "void_fraction", "d_sum_l0_per_cell",
                             "mean_d_kappa0_void", "rms_d_kappa0_bonded"])
            for n, g in sorted(growth.items()):
                writer.writerow([n, g["void"], g["dL0"], g["drift"], g["smoothing"]])

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for (n, refine), r in sorted(records.items()):
        left.plot(r["phi_patch"], r["calA"], "-" if refine == "consistent" else "--",
                  color=plt.cm.viridis(args.vertices.index(n) / max(1, len(args.vertices) - 1)),
                  label=f"n {n} {refine}")
    left.invert_xaxis()
    left.set_xlabel(r"$\phi_{patch}$")
    left.set_ylabel(r"mean $\mathcal{A}$")
    left.legend(fontsize=6, ncol=2)
    for refine, marker in (("consistent", "o-"), ("none", "s--")):
        pts = [row for row in rows if row["refinement"] == refine]
        right.plot([row["loop_cpu_s"] for row in pts],
                   [max(row["calA_rmsd_vs_64_refined"], 1e-4) for row in pts], marker,
                   label=refine)
        for row in pts:
            right.annotate(str(row["vertices"]), (row["loop_cpu_s"],
                                                  max(row["calA_rmsd_vs_64_refined"], 1e-4)),
                           fontsize=7, xytext=(3, 3), textcoords="offset points")
    right.axhline(args.budget, color="grey", ls="--", lw=0.8)
    right.set_xscale("log")
    right.set_yscale("log")
    right.set_xlabel("minimization CPU time (s)")
    right.set_ylabel(rf"calA RMSD from n = {finest} with refinement")
    right.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.png, dpi=150)
    print(f"wrote {args.csv} and {args.png}")


if __name__ == "__main__":
    main()
