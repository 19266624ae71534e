#!/usr/bin/env python3
"""Validate the package against the paper: run the development, write doc/validation.md and PNGs.

    tools/validate.py [--lmp build/lmp] [--jobs 2] [--out doc] [--cache DIR] [--quick]
                      [--published [--published-dir validation/published] [--var NAME VALUE]]

Runs examples/mesophyll/in.mesophyll:
  A. the default run (N = 64) with three seeds of bond breaking, with vertex insertion (the
     example's default, as the published code) and without (32 vertices per cell throughout);
  B. the sensitivity sets of potentials/arabidopsis.mesophyll (N = 16, two seeds each, without
     insertion), with as many growth steps as give the default's total growth of a0 (40 x 0.5);
  C. the paper's rules (z counts cells, calA_max 3 without growth above) beside the default
     (N = 64, without insertion).
  D. (--published: only this part) the comparison with the published code: in.mesophyll with
     N = 16 for as many seeds as validation/published/ holds CSVs of the published code with
     insertion, to phi_patch 0.45, against those CSVs (see validation/published/README.md);
     --var NAME VALUE (repeated) runs a variant of the example's default (with --out elsewhere,
     so that doc/validation.md keeps the default's comparison).
Then states, claim by claim of the paper's Fig 2 (listed in the Howto's "The main run"), whether
it holds, with the numbers, and draws the PNGs next to the text. --quick runs a few steps only (to try the script); --cache keeps each
run's record and log in DIR and reuses them. The runs take about an hour on 2 cores. Needs
python3-numpy and python3-matplotlib.
"""
import argparse
import collections
import concurrent.futures
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import mesophyll_run  # noqa: E402  (next to this script)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PHI_MAX = 0.975
SEEDS = [20261122, 11, 12]
SENSITIVITY = ["default", "beta30", "beta300", "soft_bending", "slow_growth", "slowest_growth",
               "low_pressure", "high_pressure"]
DELTA_A = {"slow_growth": 0.01, "slowest_growth": 0.002}
MAX_STEPS = 400    # slow growth stops here, short of the default's total growth (time)
MAXITER = {"paper": 20000}    # the paper's rules do not converge (see the report)
FTOL = {"low_pressure": 1e-13}    # |P - P0| must resolve P0 = 1e-7
P0 = {"low_pressure": 1e-7, "high_pressure": 5e-2}    # the others: 1e-3
KINDS = [("cross themselves", "rings cross themselves"),
         ("interpenetrate", "cells interpenetrate"),
         ("max iterations", "minimizer stopped at max iterations"),
         ("|P - P0|/P0 =", "P off P0 by more than 1e-6")]


def run(lmp, name, cells, pset, seed, steps, refine, workroot, cache, phi_stop="0.3",
        extra=None):
    """Run one development (or take it from the cache); return its growth record. extra: more
    variables of in.mesophyll, {name: value}."""
    work = os.path.join(cache or workroot, name)
    if cache and os.path.exists(os.path.join(work, f"growth.N{cells}.txt")):
        result = mesophyll_run.read(work, returncode=0)
    else:
        result = mesophyll_run.run(
            lmp, "in.mesophyll", work,
            {"N": cells, "set": pset, "seed": seed, "steps": steps, "phi_stop": phi_stop,
             "ftol": FTOL.get(pset, 1e-10), "maxiter": MAXITER.get(pset, 200000),
             "refine": refine, **(extra or {})}, check=False)
    record = {n: np.array(v) for n, v in result.growth[cells].items()}
    record["vertices"] = result.loops[-1].atoms if result.loops else 0
    record["failures"] = [(c.minimum, c.problems) for c in result.failures]
    record["failed_checks"] = len(record["failures"])
    record["exit"] = result.returncode
    return name, record


def failure_kinds(record):
    """What went wrong at the failed minima of a run, in words, with how often."""
    kinds = collections.Counter()
    for _, text in record["failures"]:
        for part in text.split("; "):
            kinds[next((kind for key, kind in KINDS if key in part), part)] += 1
    return ", ".join(f"{kind} ({count})" for kind, count in kinds.most_common())


def verdict_low(lowest, rises):
    trend = "phi never rose" if rises == 0 else f"phi rose in up to {rises} steps"
    if lowest <= 0.5:
        return f"Reaches 0.5 and below; {trend}."
    if lowest <= 0.52:
        return f"Reaches about 0.5 but not below within the steps run; {trend}."
    return f"Does not reach 0.5 within the steps run; {trend}."


def near(record, phi, key):
    k = int(np.argmin(np.abs(record["phi_patch"] - phi)))
    return record[key][k], record["phi_patch"][k]


def summary(record, pset):
    return {
        "steps": len(record["step"]),
        "phi_final": record["phi_patch"][-1],
        "phi_min": record["phi_patch"].min(),
        "dphi_plus": record["dphi_plus"][-1],
        "calA_final": record["calA"][-1],
        "calA_max": record["calA"].max(),
        "max_dP": np.max(np.abs(record["P"] / P0.get(pset, 1e-3) - 1.0)),
        "failed": record["failed_checks"],
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--out", default=os.path.join(ROOT, "doc"))
    p.add_argument("--quick", action="store_true")
    p.add_argument("--cache", default=None, help="keep and reuse each run's record here")
    p.add_argument("--published", action="store_true",
                   help="only the comparison with the published code (part D)")
    p.add_argument("--published-dir", default=os.path.join(ROOT, "validation", "published"))
    p.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                   help="with --published: pass this variable to in.mesophyll as well (e.g. "
                        "--var rules published), to compare a variant of the default")
    args = p.parse_args()
    if args.var and not args.published:
        p.error("--var is only for --published (the other parts run their own settings)")
    lmp = os.path.abspath(args.lmp)
    if args.published:
        return published_comparison(lmp, args)
    steps64 = 3 if args.quick else 40

    jobs = []
    for seed in SEEDS:
        jobs.append((f"refined_N64_{seed}", 64, "default", seed, steps64, "published"))
        jobs.append((f"default_N64_{seed}", 64, "default", seed, steps64, "none"))
    jobs.append(("paper_N64", 64, "paper", SEEDS[0], steps64, "none"))
    for pset in SENSITIVITY:
        steps = min(MAX_STEPS, int(round(40 * 0.5 / DELTA_A.get(pset, 0.5))))
        for seed in SEEDS[:2]:
            jobs.append((f"{pset}_N16_{seed}", 16, pset, seed, 3 if args.quick else steps, "none"))

    runs = {}
    with tempfile.TemporaryDirectory() as workroot:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            futures = [pool.submit(run, lmp, *job, workroot, args.cache) for job in jobs]
            for f in concurrent.futures.as_completed(futures):
                name, record = f.result()
                runs[name] = record
                print(f"{name}: {len(record['step'])} steps, phi_patch "
                      f"{record['phi_patch'][-1]:.3f}", flush=True)
    write_report(runs, args.out, args.quick)


def default_section(records, label):
    """Table and the paper's Fig 2 claims for the default run of three seeds."""
    lines = ["", f"## Default run {label} (N = 64, Table 1, P0 = 1e-3)", "",
             "| seed | steps | phi start -> end (min) | max abs(P/P0 - 1) | calA dip | calA at "
             "phi~0.53 | z at phi~0.5 | delta_phi_plus | vertices end | failed checks |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    rises, calA, z, lowest = [], [], [], []
    for s, r in zip(SEEDS, records):
        calA53, phi53 = near(r, 0.53, "calA")
        z50, phi50 = near(r, 0.50, "z")
        lines.append(f"| {s} | {len(r['step'])} | {r['phi_patch'][0]:.3f} -> "
                     f"{r['phi_patch'][-1]:.3f} ({r['phi_patch'].min():.3f}) | "
                     f"{np.max(np.abs(r['P'] / 1e-3 - 1)):.1e} | {r['calA'].min():.3f} | "
                     f"{calA53:.2f} (phi {phi53:.3f}) | {z50:.2f} (phi {phi50:.3f}) | "
                     f"{r['dphi_plus'][-1]:.4f} | {r['vertices']} | {r['failed_checks']} |")
        rises.append(int((np.diff(r["phi_patch"]) > 0).sum()))
        calA.append(calA53)
        z.append(z50)
        lowest.append(r["phi_patch"].min())
    lines += ["", "Claims of the paper for its Fig 2 (main text; listed in doc/Howto_mesophyll.rst, "
              "section \"The main run\"), one by one:", ""]
    lines.append(f"- *phi falls monotonically from about 0.975 to 0.5 and below while P stays at "
                 f"P0*: the runs start at phi {records[0]['phi_patch'][0]:.3f} (the generated "
                 f"tissue, not 0.975) and reach {min(lowest):.3f} at the lowest; steps "
                 f"at which phi rose: {rises}; P equals P0 to the figures in the "
                 "table. " + verdict_low(min(lowest), max(rises)))
    lines.append(f"- *mean calA starts near 1.15, dips, rises to about 2.1 near phi = 0.53*: "
                 f"starts at {records[0]['calA'][0]:.3f}, dips to "
                 f"{min(r['calA'].min() for r in records):.3f}, and is "
                 f"{', '.join(f'{c:.2f}' for c in calA)} at the minimum nearest 0.53.")
    lines.append(f"- *z near phi = 0.5 is about 4.5-5*: {', '.join(f'{v:.2f}' for v in z)}.")
    return lines


def write_report(runs, out, quick):
    os.makedirs(out, exist_ok=True)
    variants = [("with vertex insertion", "refined", "o-"),
                ("without insertion (32 vertices per cell)", "default", "--")]

    fig, ax = plt.subplots(figsize=(4.8, 3.6))
    for label, prefix, style in variants:
        for s in SEEDS:
            r = runs[f"{prefix}_N64_{s}"]
            ax.plot(PHI_MAX - r["phi_patch"], r["calA"], style, ms=2, lw=1,
                    label=f"{prefix}, seed {s}")
    r = runs["paper_N64"]
    ax.plot(PHI_MAX - r["phi_patch"], r["calA"], "s:", ms=2, label="paper rules")
    ax.set_xlabel(r"$\phi_{max} - \phi$ (patch)")
    ax.set_ylabel(r"mean $\mathcal{A}$")
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "validation_shape.png"), dpi=150)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(4.8, 5), sharex=True)
    for label, prefix, style in variants:
        for s in SEEDS:
            r = runs[f"{prefix}_N64_{s}"]
            top.plot(r["step"], r["phi_patch"], style, ms=2, lw=1, label=f"{prefix}, seed {s}")
            bottom.plot(r["step"], r["P"], style, ms=2, lw=1)
    top.set_ylabel(r"$\phi$ (patch)")
    top.legend(fontsize=6)
    bottom.set_ylabel("P at the minimum")
    bottom.set_xlabel("growth step")
    bottom.ticklabel_format(axis="y", useOffset=False)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "validation_packing.png"), dpi=150)

    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    for pset in SENSITIVITY:
        r = runs[f"{pset}_N16_{SEEDS[0]}"]
        ax.plot(PHI_MAX - r["phi_patch"], r["calA"], "-", label=pset)
    ax.set_xlabel(r"$\phi_{max} - \phi$ (patch)")
    ax.set_ylabel(r"mean $\mathcal{A}$")
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "validation_sensitivity.png"), dpi=150)

    lines = ["# Validation against the paper", "",
             "Regenerated by `tools/validate.py`" + (" (--quick: a few steps only, not a "
                                                     "validation)" if quick else "") +
             "; every number below comes from its runs of `examples/mesophyll/in.mesophyll`. "
             "Seeds are those of bond breaking; each size has one initial tissue "
             "(`examples/tissue`). phi is the patch packing fraction, as in the paper.", "",
             "The main example, `examples/mesophyll/in.mesophyll`, inserts vertices as the "
             "published code does (fix dpoly/refine rules published); the runs "
             "without insertion keep 32 vertices per cell. The sensitivity sets and the rule "
             "sets below run without insertion.", ""]
    for label, prefix, _ in variants:
        lines += default_section([runs[f"{prefix}_N64_{s}"] for s in SEEDS], label)
    lines += ["", "![calA against phi](validation_shape.png) "
              "![phi and P against step](validation_packing.png)"]

    lines += ["", "## Sensitivity (N = 16, two seeds each)", "",
              "Each set changes one parameter of the default (`potentials/arabidopsis.mesophyll`). "
              f"Runs grow a0 by 20 in all (40 steps of 0.5), at most {MAX_STEPS} steps, or stop "
              "when phi falls below 0.3.", "",
              "| set | steps | phi end (min) | delta_phi_plus | calA end (max) | "
              "max abs(P/P0 - 1) | failed checks |", "| --- | --- | --- | --- | --- | --- | --- |"]
    table = {}
    for pset in SENSITIVITY:
        sums = [summary(runs[f"{pset}_N16_{s}"], pset) for s in SEEDS[:2]]
        table[pset] = sums
        def both(fmt):
            return "/".join(fmt(x) for x in sums)
        lines.append(
            f"| {pset} | {both(lambda x: str(x['steps']))} | "
            + both(lambda x: f"{x['phi_final']:.3f} ({x['phi_min']:.3f})") + " | "
            + both(lambda x: f"{x['dphi_plus']:.3f}") + " | "
            + both(lambda x: f"{x['calA_final']:.2f} ({x['calA_max']:.2f})") + " | "
            + both(lambda x: f"{x['max_dP']:.1e}") + " | "
            + both(lambda x: str(x['failed'])) + " |")

    def mean(pset, key):
        return np.mean([x[key] for x in table[pset]])

    d = "default"
    lines += ["", "![calA against phi by set](validation_sensitivity.png)", "",
              "Directions of the paper, one by one (means over the two seeds):", ""]
    for pset, text in [("beta30", "low beta compacts"), ("soft_bending", "low eps_b compacts"),
                       ("slow_growth", "delta_a = 0.01 compacts"),
                       ("high_pressure", "P0 = 5e-2 compacts, with extreme calA")]:
        holds = mean(pset, "dphi_plus") > mean(d, "dphi_plus")
        failed = sum(x["failed"] for x in table[pset])
        caveat = f" ({failed} failed checks in the two runs: see below)" if failed else ""
        lines.append(f"- *{text}*: delta_phi_plus {mean(pset, 'dphi_plus'):.3f} against "
                     f"{mean(d, 'dphi_plus'):.3f} for the default; max calA "
                     f"{mean(pset, 'calA_max'):.2f} against {mean(d, 'calA_max'):.2f}. "
                     + ("Holds" if holds else "Does not hold here") + caveat + ".")
    if max(x["phi_final"] for sums in table.values() for x in sums) > 1.0:
        lines += ["", "phi_patch above 1 (high_pressure): the patch inflates every polygon by its "
                  "vertex radius, so where cells press into each other the overlapping rims count "
                  "twice; the plain polygon packing fraction stays below 1."]

    r, q = runs["default_N64_" + str(SEEDS[0])], runs["paper_N64"]
    lines += ["", "## The two rule sets (N = 64, seed " + str(SEEDS[0]) + ")", "",
              "| rules | steps | phi end (min) | calA end | z end | bonds end | delta_phi_plus "
              "| max abs(P/P0 - 1) | failed checks |",
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for label, x in [("code: z = bonds, calA_max 2.5 isometric", r),
                     ("paper: z = cells, calA_max 3 no growth", q)]:
        lines.append(f"| {label} | {len(x['step'])} | {x['phi_patch'][-1]:.3f} "
                     f"({x['phi_patch'].min():.3f}) | {x['calA'][-1]:.2f} | {x['z'][-1]:.2f} | "
                     f"{int(x['bonds'][-1])} | {x['dphi_plus'][-1]:.4f} | "
                     f"{np.max(np.abs(x['P'] / 1e-3 - 1)):.1e} | {x['failed_checks']} |")
    lines += failure_section(runs)
    path = os.path.join(out, "validation.md")
    rewrite(path, lines)
    print(f"wrote {path} and three PNGs")


def rewrite(path, lines):
    """Write lines (parts A-C) to path, keeping from its old text the sections of AFTER_PART_C,
    the comparison with the published code (part D, --published) and the 3d section, as they
    were."""
    _, kept = split_published_section(path)
    sweeps = "\n".join(s for s in (marked_section(path, begin, end)
                                   for begin, end in AFTER_PART_C) if s)
    threed = marked_section(path, THREED_BEGIN, THREED_END)
    if threed:  # written by hand: split_published_section left it in the text it drops
        kept += threed
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n" + (sweeps + "\n" if sweeps else "") + kept)


PUB_BEGIN, PUB_END = "<!-- published: tools/validate.py --published -->", "<!-- /published -->"
SWEEPS_BEGIN, SWEEPS_END = "<!-- sweeps: tools/sweep_report.py -->", "<!-- /sweeps -->"
# the sections kept, in this order, between part C and part D: tools/sweep_report.py's, then
# those written by hand about its sweeps
AFTER_PART_C = (
    (SWEEPS_BEGIN, SWEEPS_END),
    ("<!-- fig4 stall: validation/fig4_stall, written by hand -->", "<!-- /fig4 stall -->"),
    ("<!-- low bending: validation/published/low_bending.py, written by hand -->",
     "<!-- /low bending -->"),
    ("<!-- low beta: validation/published/low_beta.py, written by hand -->",
     "<!-- /low beta -->"),
    ("<!-- high lambda: validation/published/high_lambda.py, written by hand -->",
     "<!-- /high lambda -->"))
THREED_BEGIN, THREED_END = ("<!-- 3d: examples/polyhedra/in.grow_tissue3d, written by hand -->",
                            "<!-- /3d -->")


def marked_section(path, begin, end):
    """The text of path from the marker begin to the marker end (both kept), or ""."""
    if not os.path.exists(path):
        return ""
    text = open(path).read()
    start, stop = text.find(begin), text.find(end)
    return text[start:stop + len(end)] + "\n" if 0 <= start < stop else ""


def split_published_section(path):
    """(the text of validation.md without part D's section, that section with its markers)."""
    if not os.path.exists(path):
        return "", ""
    with open(path) as f:
        text = f.read()
    start, end = text.find(PUB_BEGIN), text.find(PUB_END)
    if start < 0 or end < start:
        return text, ""
    end += len(PUB_END) + 1
    return text[:start] + text[end:], text[start:end]


def failure_section(runs):
    """Every run with failed checks: how many, the first, and of which kinds."""
    lines = ["", "## Failed checks", "",
             "fix dpoly/check checks every minimum (convergence, abs(P/P0 - 1) <= 1e-6, "
             "inverted or self-crossing rings) and the run goes on with a warning; these runs "
             "had failures:", "",
             "| run | failed minima | first (growth step: what) | kinds (count) |",
             "| --- | --- | --- | --- |"]
    failed = {name: r for name, r in sorted(runs.items()) if r["failed_checks"]}
    for name, r in failed.items():
        step, text = r["failures"][0]
        cell = f"{step}: {text} | {failure_kinds(r)}".replace("|P - P0|", "abs(P - P0)")
        lines.append(f"| {name} | {r['failed_checks']} of {len(r['step'])} | {cell} |")
    if not failed:
        lines.append("| (none) | | | |")
    tangled = [n for n, r in failed.items() if "cross themselves" in failure_kinds(r)]
    stalled = [n for n, r in failed.items() if "max iterations" in failure_kinds(r)]
    if tangled:
        lines += ["", "Rings that cross themselves (" + ", ".join(tangled) + "): lobes of one cell "
                  "fold through each other. Self-repulsion is on (`pair_style dpoly/contact`'s "
                  "default, `self yes`, which in.mesophyll keeps), but it acts between vertex "
                  "disks only: these runs insert no vertices, their void segments grow to "
                  "several vertex diameters, and a lobe can pass through the gap between the "
                  "disks of a long segment. The steps after the first such minimum describe "
                  "tangled cells, and the directions above that rest on these sets carry that "
                  "caveat."]
    if stalled:
        lines += ["", "Minimizations that stopped at the iteration limit (" + ", ".join(stalled) +
                  "): where abs(P/P0 - 1) stays below 1e-6 only the force tolerance was out of "
                  "reach; where it does not, those minima are not at P0 and the run's numbers "
                  "after them are not converged results."]
    return lines


# --- D. the comparison with the published code (--published) --------------------------------

PUB_SEEDS = [20261122, 11, 12, 13, 14]    # the package's seeds, as many as published CSVs
PUB_PHI = [0.9, 0.8, 0.7, 0.6, 0.5]       # matched phi_patch at which calA and z are compared
PUB_STOP = "0.45"
NARROW = 1e-3    # published spread (max - min) at most this fraction of its mean: 'no spread'


def read_csv(path):
    """{column: array} of a CSV of validation/published (run.py wrote it)."""
    with open(path) as f:
        names = f.readline().strip().split(",")
        rows = [[float(w) for w in line.split(",")] for line in f if line.strip()]
    return {n: np.array([r[k] for r in rows]) for k, n in enumerate(names)}


def at_phi(record, key, phi):
    """key interpolated linearly in phi_patch where the run first falls to phi (nan if never, or
    if it starts below): the first crossing, so that a later rise of phi_patch picks no other."""
    f, v = record["phi_patch"], record[key]
    below = np.nonzero(f <= phi)[0]
    if len(below) == 0 or below[0] == 0:
        return np.nan
    k = below[0]
    return v[k - 1] + (v[k] - v[k - 1]) * (phi - f[k - 1]) / (f[k] - f[k - 1])


def steps_to(record, phi):
    """Growth steps done before the first minimum with phi_patch <= phi (nan if none)."""
    below = np.nonzero(record["phi_patch"] <= phi)[0]
    return record["growth_steps"][below[0]] if len(below) else np.nan


def spread(values):
    """(mean, min, max) over seeds of the values that exist."""
    v = np.array(values, float)
    v = v[~np.isnan(v)]
    return (np.nan, np.nan, np.nan) if len(v) == 0 else (v.mean(), v.min(), v.max())


def published_comparison(lmp, args):
    """Part D: package (in.mesophyll, N = 16, to phi_patch 0.45) against the published code's
    CSVs, at matched phi_patch and per growth step; spread = min..max over seeds."""
    import glob
    paths = sorted(glob.glob(os.path.join(args.published_dir, "N16_insert_seed*.csv")))
    if not paths:
        raise SystemExit(f"no N16_insert_seed*.csv in {args.published_dir}")
    pub = {os.path.basename(q)[len("N16_insert_seed"):-4]: read_csv(q) for q in paths}
    seeds = PUB_SEEDS[:len(pub)]
    steps = 3 if args.quick else 80
    pkg = {}
    with tempfile.TemporaryDirectory() as workroot:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            tag = "".join(f"_{n}{v}" for n, v in args.var).replace("/", "")
            futures = [pool.submit(run, lmp, f"published_pkg_N16{tag}_{s}", 16, "default", s,
                                   steps, "published", workroot, args.cache, PUB_STOP,
                                   dict(args.var)) for s in seeds]
            for f in concurrent.futures.as_completed(futures):
                name, r = f.result()
                r["growth_steps"] = r["step"] - 1    # row k of in.mesophyll: k - 1 growths
                pkg[name] = r
                print(f"{name}: {len(r['step'])} minima, phi_patch {r['phi_patch'][-1]:.3f}",
                      flush=True)
    pkg = [pkg[f"published_pkg_N16{tag}_{s}"] for s in seeds]
    pubs = list(pub.values())
    write_published_report(pkg, pubs, seeds, sorted(pub), args.out, args.quick, args.var)


def checks_lines(pkg, pubs, narrow):
    """What fix dpoly/check found in both codes' states, and which rows no package can match
    by chance: those where the published seeds (almost) agree."""
    minima = sum(len(r["step"]) for r in pkg)
    failed = sum(r["failed_checks"] for r in pkg)
    apart = sum(1 for r in pkg for _, text in r["failures"] if "interpenetrate" in text)
    lines = [f"fix dpoly/check at the package's minima: {failed} of {minima} failed, {apart} of "
             "them with interpenetrating cells."]
    checked = [r for r in pubs if "interpenetrating_pairs" in r]
    if checked:
        bad = [int(np.count_nonzero(r["interpenetrating_pairs"])) for r in checked]
        first = sorted({int(r["growth_steps"][np.nonzero(r["interpenetrating_pairs"])[0][0]])
                        for r in checked if np.count_nonzero(r["interpenetrating_pairs"])})
        lines[-1] += (f" The same check on the published code's frames (column "
                      f"interpenetrating_pairs, in {len(checked)} of {len(pubs)} CSVs): "
                      f"{sum(bad)} of {sum(len(r['growth_steps']) for r in checked)} frames have "
                      f"interpenetrating cells (per checked seed: {', '.join(map(str, bad))})" +
                      (f", the first after {' or '.join(map(str, first))} growth steps." if first
                       else "."))
    else:
        lines[-1] += (" The CSVs of the published code have no interpenetrating_pairs column "
                      "(made before run.py wrote it); validation/published/README.md (\"The runs "
                      "here\") has the published frames checked since.")
    if narrow:
        lines += ["", f"Rows where the published seeds agree to {NARROW:.1%} of their mean or "
                  "better, so that the package is inside only if it ends in (nearly) the same "
                  "states: " +
                  "; ".join(f"{label} ({'inside' if inside == 'yes' else 'outside'})"
                            for label, inside in narrow) + ". Why the published seeds agree "
                  "there and what matching those rows would take: validation/published/README.md."]
    return lines


def write_published_report(pkg, pubs, seeds, pub_seeds, out, quick, variables=()):
    os.makedirs(out, exist_ok=True)

    tally = collections.defaultdict(collections.Counter)    # {table: {yes/no/n/a: rows}}
    narrow = []    # rows whose published seeds (almost) agree: (label, inside)

    def row(label, pkg_values, pub_values, fmt, table):
        m, lo, hi = spread(pkg_values)
        pm, plo, phi_ = spread(pub_values)
        inside = "n/a" if np.isnan(m) or np.isnan(pm) else ("yes" if plo <= m <= phi_ else "no")
        tally[table][inside] += 1
        if inside != "n/a" and phi_ - plo <= NARROW * abs(pm):
            narrow.append((label, inside))
        return (f"| {label} | {fmt(pm)} ({fmt(plo)}..{fmt(phi_)}) | {fmt(m)} ({fmt(lo)}..{fmt(hi)})"
                f" | {inside} |")

    f3 = lambda v: "-" if np.isnan(v) else f"{v:.4f}"  # noqa: E731
    f1 = lambda v: "-" if np.isnan(v) else f"{v:.1f}"  # noqa: E731
    head = ["| quantity | published: mean (min..max) | package: mean (min..max) | "
            "package mean inside published min..max |", "| --- | --- | --- | --- |"]
    lines = ["## Comparison with the published code (N = 16)" + (" (--quick)" if quick else ""),
             "",
             f"Published code: jacktreado/dpm readInMesoNetwork2D, {len(pubs)} seeds "
             f"({', '.join(pub_seeds)}), with its vertex insertion, from the CSVs of "
             "validation/published (README.md there says how they were made). Package: "
             "examples/mesophyll/in.mesophyll -var N 16" +
             "".join(f" -var {n} {v}" for n, v in variables) + f", {len(seeds)} seeds "
             f"({', '.join(map(str, seeds))}), as it is in this checkout, stopped at phi_patch "
             f"{PUB_STOP}. Both from tissue_N16.data, both measured by compute dpoly/tissue. "
             "Spread = min..max over seeds (no seed of one code corresponds to one of the "
             "other: their random streams differ). growth steps = growth steps done before "
             "the minimum; after 0 growth steps the published code's state is its fixed-box relaxation of "
             "the input (its frame 0), the package's its first minimum at P0. Which settings of "
             "the package close the gap after the first growth step, with a table of the "
             "variants tried: validation/published/README.md (growth_step/).", "", "At matched phi_patch (linear interpolation at the first "
             "crossing):", ""] + head
    for phi in PUB_PHI:
        for key in ("calA", "z"):
            lines.append(row(f"{key} at phi_patch {phi}", [at_phi(r, key, phi) for r in pkg],
                             [at_phi(r, key, phi) for r in pubs], f3, "matched"))
    lines.append(row("growth steps to phi_patch <= 0.5", [steps_to(r, 0.5) for r in pkg],
                     [steps_to(r, 0.5) for r in pubs], f1, "steps"))
    last = int(max(max(r["growth_steps"]) for r in pubs))
    lines += ["", "Per growth step (runs that have the step):", ""] + head
    for k in range(last + 1):
        for key in ("phi_patch", "calA", "z"):
            def at(r):
                hit = np.nonzero(r["growth_steps"] == k)[0]
                return r[key][hit[0]] if len(hit) else np.nan
            lines.append(row(f"{key} after {k} growth steps", [at(r) for r in pkg],
                             [at(r) for r in pubs], f3, "per step"))

    def inside(table):
        return f"{tally[table]['yes']} of {tally[table]['yes'] + tally[table]['no']}"
    summary_line = (f"Package mean inside the published min..max: calA and z at matched phi_patch "
                    f"{inside('matched')}, growth steps to phi_patch <= 0.5 {inside('steps')}, "
                    f"phi_patch, calA and z per growth step {inside('per step')}.")
    lines += ["", summary_line, ""] + checks_lines(pkg, pubs, narrow) + [
              "", "![calA and z against phi_patch, both codes](published_comparison.png)"]
    print(summary_line)

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for ax, key, label in [(axes[0], "calA", r"mean $\mathcal{A}$"),
                           (axes[1], "z", r"mean $z$")]:
        for runs, colour, name in [(pubs, "C3", "published"), (pkg, "C0", "package")]:
            for r in runs:
                ax.plot(r["phi_patch"], r[key], "-", color=colour, lw=0.6, alpha=0.6)
            grid = np.linspace(0.45, 0.93, 49)
            mean = np.nanmean([[at_phi(r, key, g) for g in grid] for r in runs], axis=0)
            ax.plot(grid, mean, "-", color=colour, lw=2.5, label=f"{name} (mean of {len(runs)})")
        ax.set_xlabel(r"$\phi_{patch}$")
        ax.set_ylabel(label)
        ax.invert_xaxis()
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "published_comparison.png"), dpi=150)
    # part D's section of validation.md, replaced in place (appended the first time)
    path = os.path.join(out, "validation.md")
    rest, _ = split_published_section(path)
    with open(path, "w") as f:
        f.write(rest.rstrip("\n") + "\n\n" + PUB_BEGIN + "\n" + "\n".join(lines) + "\n" +
                PUB_END + "\n")
    print(f"wrote the published code's section of {path} and published_comparison.png")


if __name__ == "__main__":
    main()
