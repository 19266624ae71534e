#!/usr/bin/env python3
"""Fig 6's highest pressure in the published code: does it collapse ring segments, stall, or grow
cells as long as the box, as the package's runs at P0 = 1e-1 do?

    high_pressure.py BINARY [--lmp build/lmp] [--work DIR] [--out high_pressure.csv]
                     [--seeds 1 2] [--limit SECONDS] [--jobs 2]

BINARY is the driver build.sh made. From tissue_N16.data (through make_input.py), with Fig 6's
base set (eps_b 0.4, beta 100, delta_a 0.5, lambda 5, theta0_min -3 pi/20) at P0 = 1e-1,
fig6.sweep's stop (phi_patch 0.3 or 40 growth steps) and, since the driver's FIRE would iterate a
stalled minimization for days, a wall-time limit per run (run.py --limit). Every printed frame is
measured by in.measure (phi_patch, calA, interpenetrating pairs) and, here, from its ring
geometry: the largest extent of a cell along x or y over the box length (the package stops a
run at 1, where a cell would meet its own periodic image; the driver does not check it), and
the shortest ring segment over its preferred length (the package's stalled minima at 1e-1 had
one at 0.001-0.02). The package's side is in doc/Howto_sweep.rst (Measured): fig6.sweep's
protocol from this tissue at 1e-1, seed 1, stopped in its 33rd minimization with a cell longer
than the box; from 32-cell tissues no run at 1e-1 was accepted.
"""
import os

import numpy as np

import frames
import same_tissue

P0 = same_tissue.FIGURES["fig6"][1]
PHI_STOP, STEPS = "0.3", "40"
COLUMNS = ["seed", "growth_steps", "phi_patch", "calA", "vertices", "iterations", "wall_s",
           "interpenetrating_pairs", "largest_span_over_box", "span_cell",
           "shortest_segment_over_l0", "shortest_cell", "stopped_at_limit"]


def ring_geometry(tissue):
    """(largest cell extent along x or y over the box length, its cell, shortest segment length
    over its preferred length, its cell); cells numbered from 1 as the package's molecules. The
    ring is followed segment by segment, each by its nearest periodic image, so a cell longer
    than half the box keeps its true extent."""
    span, span_cell, short, short_cell = 0.0, 0, np.inf, 0
    for k, c in enumerate(tissue.cells, start=1):
        d = np.stack([np.roll(c.x, -1) - c.x, np.roll(c.y, -1) - c.y])
        d -= tissue.L * np.round(d / tissue.L)
        ring = np.cumsum(d[:, :-1], axis=1)
        extent = max(np.ptp(np.append(ring[0], 0.0)), np.ptp(np.append(ring[1], 0.0)))
        if extent / tissue.L > span:
            span, span_cell = extent / tissue.L, k
        ratio = np.min(np.hypot(d[0], d[1]) / c.l0)
        if ratio < short:
            short, short_cell = ratio, k
    return span, span_cell, short, short_cell


def run(binary, lmp, work, seed, limit):
    folder = f"published_P0_{P0}_seed{seed}"
    rows = same_tissue.published(binary, lmp, work, folder, seed,
                                 ["--phi-stop", PHI_STOP, "--steps", STEPS, "--limit", str(limit)],
                                 figure="fig6")
    steps_file = open(os.path.join(work, folder, "steps.txt")).read()
    stopped = "stopped at the --limit" in steps_file
    tissues = list(frames.read_frames(os.path.join(work, folder, "pos.txt")))
    out = []
    for r, t in zip(rows, tissues):
        span, span_cell, short, short_cell = ring_geometry(t)
        out.append([seed, r["growth_steps"], r["phi_patch"], r["calA"], r["vertices"],
                    r["iterations"], r["wall_s"], r["interpenetrating_pairs"], f"{span:.4f}",
                    span_cell, f"{short:.4g}", short_cell, ""])
    if out:
        out[-1][-1] = "yes" if stopped else "no"
    print(f"seed {seed}: {len(out)} frames", flush=True)
    return out


def main():
    p = same_tissue.arguments(__doc__, "high_pressure")
    p.add_argument("--seeds", nargs="+", default=["1", "2"])
    p.add_argument("--limit", type=float, default=2400.0,
                   help="seconds of wall time per run before the driver is stopped")
    p.add_argument("--jobs", type=int, default=2, help="runs at a time (one core each)")
    a = p.parse_args()
    if a.jobs < 1 or a.limit <= 0:
        p.error(f"--jobs must be at least 1 and --limit positive, got {a.jobs} and {a.limit:g}")
    lmp, binary = os.path.abspath(a.lmp), os.path.abspath(a.binary)
    same_tissue.driver_input(a.work)
    results = same_tissue.run_all(a.jobs, lambda s: run(binary, lmp, a.work, s, a.limit),
                                  a.seeds)
    rows = [r for result in results for r in result]
    same_tissue.write_csv(a.out, COLUMNS, rows)
    print("seed step phi_patch calA  vertices iterations span/L (cell) shortest l/l0 (cell)")
    for r in rows:
        print(f"{r[0]:4} {r[1]:4} {float(r[2]):.4f}    {float(r[3]):.3f} {r[4]:8} {r[5]:10} "
              f"{r[8]} ({r[9]})   {r[10]} ({r[11]}) {r[12]}")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
