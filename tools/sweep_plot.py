#!/usr/bin/env python3
"""Figures of a summarized sweep (tools/sweep.py summary DIR first), in the style of the paper's
Figs 4-6.

    tools/sweep_plot.py heatmaps DIR --x lambda --y delta_a [--mark 1.5,0.1 ...] [-o PNG]
        2 x 2 heatmaps over two grid axes (one tile per grid value, evenly spaced, ticks at the
        values) of the ensemble means of delta_A early and late, delta_phi_plus and z near
        phi_patch = 0.5, on a log colour scale; --mark rings points (x,y) of the grid such as
        the caption's highlighted ones.
    tools/sweep_plot.py curves DIR [--point LABEL ...] [--reference FILE] [-o PNG]
        mean calA against porosity 0.975 - phi_patch per grid point (default: every point), in
        porosity bins (--bin, default 0.025): each run's growth steps in a bin averaged, then
        the mean over the runs and their standard deviation as a band (where two runs or more
        reach the bin), the reference points as markers.
    tools/sweep_plot.py against DIR --x P0 [-o PNG]
        delta_A early and late and delta_phi_plus against one grid axis (log), ensemble mean
        with the standard deviation as error bars.
Each heatmap tile and each point of `against` is labelled with its accepted runs over its runs,
and the runs whose checks failed (rings crossed, non-finite values): those are shown as
failed, never drawn as data.

Only runs with status ok enter, with --accept unconverged those too (the others are counted
in the titles). Writes a PNG (default DIR/<kind>.png) and the numbers drawn as a CSV beside it
(heatmaps and against: per tile or point also all its runs and its failed ones).
Needs python3-numpy and python3-matplotlib.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesophyll_frames  # noqa: E402  (re-runs this with Debian's python3 if it lacks these)

mesophyll_frames.require(["numpy", "matplotlib"])
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sweep  # noqa: E402
import mesophyll_run  # noqa: E402

QUANTITIES = [("delta_A_early", r"$\Delta_A$ early"), ("delta_A_late", r"$\Delta_A$ late"),
              ("delta_phi_plus", r"$\Delta\phi_+$"), ("z_half", r"$z$ near $\phi = 0.5$")]


def read_summary(folder):
    path = os.path.join(folder, "summary.csv")
    if not os.path.exists(path):
        sys.exit(f"{path} does not exist: run tools/sweep.py summary {folder} first")
    rows = list(csv.DictReader(open(path)))
    if not rows:
        sys.exit(f"{path} lists no runs: plan and run the sweep, then summarize it")
    return rows


def number(text):
    return float(text) if text not in ("", None) else np.nan


ACCEPT = {"ok"}    # statuses that enter the ensembles (--accept adds unconverged)


def excluded(rows):
    bad = [r for r in rows if r["status"] not in ACCEPT]
    if not bad:
        return f"{len(rows)} runs, all ok"
    kinds = {}
    for r in bad:
        kinds[r["status"]] = kinds.get(r["status"], 0) + 1
    return f"{len(rows)} runs; left out: " + ", ".join(f"{n} {k}" for k, n in kinds.items())


def ensemble(rows, keys, quantity):
    """{values of keys: (mean, std, n)} over the runs with status ok."""
    groups = {}
    for r in rows:
        if r["status"] in ACCEPT:
            groups.setdefault(tuple(number(r[k]) for k in keys), []).append(number(r[quantity]))
    out = {}
    for key, values in groups.items():
        values = np.array([v for v in values if np.isfinite(v)])
        out[key] = (values.mean() if len(values) else np.nan,
                    values.std(ddof=1) if len(values) > 1 else np.nan, len(values))
    return out


def run_counts(rows, keys):
    """{values of keys: (accepted runs, all runs, runs whose checks failed)}: what each tile
    or point of a figure stands on, failed runs shown as such rather than left out silently."""
    counts = {}
    for r in rows:
        key = tuple(number(r[k]) for k in keys)
        ok, total, failed = counts.get(key, (0, 0, 0))
        counts[key] = (ok + (r["status"] in ACCEPT), total + 1, failed + (r["status"] == "failed"))
    return counts


def count_label(ok, total, failed):
    return f"{ok}/{total}" + (f"\n{failed} failed" if failed else "")


def tick_label(value):
    return f"{value:g}"


def tile_of(xs, ys, mark):
    """(column, row) of the tile of a --mark 'x,y', or None (with a note) if it is off the grid."""
    x, y = (float(v) for v in mark.split(","))
    i = [k for k, v in enumerate(xs) if np.isclose(v, x)]
    j = [k for k, v in enumerate(ys) if np.isclose(v, y)]
    if not (i and j):
        print(f"sweep_plot: marked point {mark} is not a point of the grid: not drawn")
        return None
    return i[0], j[0]


def heatmaps(args, rows):
    for axis in (args.x, args.y):
        if axis not in rows[0]:
            sys.exit(f"the sweep has no grid axis '{axis}' (summary.csv columns: "
                     f"{', '.join(rows[0])})")
    xs = sorted({number(r[args.x]) for r in rows if r[args.x]})
    ys = sorted({number(r[args.y]) for r in rows if r[args.y]})
    fig, axes = plt.subplots(2, 2, figsize=(10, 8.4), constrained_layout=True)
    marked = [tile_of(xs, ys, mark) for mark in args.mark]
    table = []
    counts = run_counts(rows, [args.x, args.y])
    for ax, (quantity, title) in zip(axes.flat, QUANTITIES):
        stats = ensemble(rows, [args.x, args.y], quantity)
        grid = np.full((len(ys), len(xs)), np.nan)
        for (x, y), (mean, std, n) in stats.items():
            if x in xs and y in ys:
                grid[ys.index(y), xs.index(x)] = mean
            table.append([quantity, x, y, mean, std, n, *counts[x, y][1:]])
        positive = grid[np.isfinite(grid) & (grid > 0)]
        norm = mcolors.LogNorm(positive.min(), positive.max()) if positive.size else None
        shown = np.ma.masked_where(~np.isfinite(grid) | (grid <= 0), grid)
        cmap = plt.get_cmap("viridis").copy()
        cmap.set_bad("lightgrey")
        ax.set_facecolor("lightgrey")
        # one tile per grid value, evenly spaced: on a log axis the tiles of close values,
        # 0.5 and 0.75, are too thin for their labels
        mesh = ax.pcolormesh(np.arange(len(xs) + 1) - 0.5, np.arange(len(ys) + 1) - 0.5, shown,
                             norm=norm, cmap=cmap)
        if positive.size:
            fig.colorbar(mesh, ax=ax)
        ax.set_xticks(range(len(xs)), [tick_label(x) for x in xs])
        ax.set_yticks(range(len(ys)), [tick_label(y) for y in ys])
        ax.set_xlabel(args.x)
        ax.set_ylabel(args.y)
        ax.set_title(title)
        for i, j in filter(None, marked):
            ax.plot(i, j, "o", mfc="none", mec="red", ms=12, mew=2)
        for (x, y), tile_counts in counts.items():
            if x in xs and y in ys:
                # in the middle of its tile; below the ring of a marked point
                tile = (xs.index(x), ys.index(y))
                ax.annotate(count_label(*tile_counts), tile, ha="center", va="center",
                            fontsize=7 if len(xs) <= 7 else 6, color="black",
                            xytext=(0, -12 if tile in marked else 0),
                            textcoords="offset points")
    fig.suptitle(f"{os.path.basename(os.path.abspath(args.dir))}: ensemble means "
                 f"({excluded(rows)})\ngrey: no ok run or a value <= 0; "
                 f"per tile: ok runs / runs (and failed runs)", fontsize=10)
    return fig, ["quantity", args.x, args.y, "mean", "std", "runs", "all_runs", "failed"], table


def curves(args, rows):
    points = args.point or list(dict.fromkeys(r["point"] for r in rows))
    reference = sweep.read_reference(args.reference, 0.25)
    bins = np.arange(0.0, 1.0 + args.bin, args.bin)
    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    table = []
    for label in points:
        samples = [[] for _ in bins[:-1]]    # per bin: each run's mean calA in it
        runs = [r for r in rows if r["point"] == label]
        if not runs:
            sys.exit(f"no point '{label}' in the sweep (points: "
                     f"{', '.join(dict.fromkeys(r['point'] for r in rows))})")
        for r in runs:
            if r["status"] not in ACCEPT:
                continue
            growth = mesophyll_run.growth_table(os.path.join(
                args.dir, "runs", r["run"], f"growth.N{r['N']}.txt"))
            porosity = sweep.PHI_MAX - np.array(growth["phi_patch"])
            index = np.searchsorted(bins, porosity, side="right") - 1
            calA = np.array(growth["calA"])
            for k in set(index[(index >= 0) & (index < len(samples))]):
                samples[k].append(calA[index == k].mean())
        centres, means, stds = [], [], []
        for k, values in enumerate(samples):
            if values:
                centres.append((bins[k] + bins[k + 1]) / 2)
                means.append(np.mean(values))
                stds.append(np.std(values, ddof=1) if len(values) > 1 else np.nan)
                table.append([label, centres[-1], means[-1], stds[-1], len(values)])
        centres, means, stds = map(np.array, (centres, means, stds))
        ok = sum(r["status"] in ACCEPT for r in runs)
        line, = ax.plot(centres, means, "-", label=f"{label} ({ok} of {len(runs)} runs)")
        ax.fill_between(centres, means - stds, means + stds, color=line.get_color(), alpha=0.25)
    ax.plot([p for p, _, _ in reference], [c for _, c, _ in reference], "ks",
            label=f"reference: {os.path.basename(args.reference)}")
    ax.set_xlabel(r"porosity $\phi_{max} - \phi_{patch}$ ($\phi_{max}$ = 0.975)")
    ax.set_ylabel(r"mean $\mathcal{A}$ (band: standard deviation)")
    ax.legend(fontsize=8)
    return fig, ["point", "porosity", "calA_mean", "calA_std", "samples"], table


def against(args, rows):
    if args.x not in rows[0]:
        sys.exit(f"the sweep has no grid axis '{args.x}'")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
    table = []
    counts = run_counts(rows, [args.x])
    # every grid value in view, also one without an accepted run (only its label drawn)
    grid = [x for (x,) in counts if np.isfinite(x) and x > 0]
    for ax, quantities in zip(axes, (QUANTITIES[:2], QUANTITIES[2:3])):
        for quantity, title in quantities:
            stats = sorted(ensemble(rows, [args.x], quantity).items())
            x = np.array([k[0] for k, _ in stats])
            mean = np.array([s[0] for _, s in stats])
            std = np.array([s[1] for _, s in stats])
            ax.errorbar(x, mean, yerr=np.nan_to_num(std), marker="o", capsize=3, label=title)
            table += [[quantity, k[0], *s, *counts[k][1:]] for k, s in stats]
        # every other label a line higher: neighbours on the log axis (5e-2, 1e-1) would overlap
        for k, ((x,), point_counts) in enumerate(sorted(counts.items())):
            if np.isfinite(x):
                ax.annotate(count_label(*point_counts), (x, 0), xycoords=("data", "axes fraction"),
                            ha="center", va="bottom", fontsize=7, xytext=(0, 3 + 9 * (k % 2)),
                            textcoords="offset points")
        ax.set_xscale("log")
        if grid:
            ax.set_xlim(min(grid) / 2, max(grid) * 2)
        ax.set_xlabel(args.x)
        ax.legend()
    fig.suptitle(f"{os.path.basename(os.path.abspath(args.dir))}: mean and standard deviation "
                 f"over seeds and tissues\n({excluded(rows)}); labels: ok runs / runs",
                 fontsize=10)
    return fig, ["quantity", args.x, "mean", "std", "runs", "all_runs", "failed"], table


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="kind", required=True)
    q = sub.add_parser("heatmaps")
    q.add_argument("--x", required=True)
    q.add_argument("--y", required=True)
    q.add_argument("--mark", action="append", default=[], help="x,y of a highlighted point")
    q = sub.add_parser("curves")
    q.add_argument("--point", action="append", help="a point label of runs.csv (repeatable)")
    q.add_argument("--reference", default=sweep.DEFAULT_REFERENCE)
    q.add_argument("--bin", type=float, default=0.025, help="porosity bin width")
    q = sub.add_parser("against")
    q.add_argument("--x", required=True)
    for q in sub.choices.values():
        q.add_argument("dir")
        q.add_argument("--accept", action="append", default=[], choices=["unconverged"],
                       help="let runs of this status enter too (default: ok only)")
        q.add_argument("-o", "--output", default=None)
    args = p.parse_args()
    ACCEPT.update(args.accept)
    rows = read_summary(args.dir)
    fig, header, table = {"heatmaps": heatmaps, "curves": curves, "against": against}[
        args.kind](args, rows)
    out = args.output or os.path.join(args.dir, f"{args.kind}.png")
    fig.savefig(out, dpi=120)
    with open(os.path.splitext(out)[0] + ".csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(table)
    print(f"wrote {out} and {os.path.splitext(out)[0]}.csv")


if __name__ == "__main__":
    main()
