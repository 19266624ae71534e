#!/usr/bin/env python3
"""Draw a MESOPHYLL development run: what examples/mesophyll/in.mesophyll writes.

    plot_mesophyll.py growth.N64.txt cells.N64.dump [--phi 0.9 0.7 0.5] [--out mesophyll]
                      [--P0 1e-3] [--sigma S] [--no-disks]

Writes three PNGs next to --out:
  <out>_shape.png      mean calA against phi_max - phi_patch (phi_max = 0.975, as the paper)
  <out>_packing.png    phi and phi_patch against growth step, and |P/P0 - 1| on a log axis
                       (P0 = --P0; a deviation of exactly 0 is drawn at 1e-13)
  <out>_snapshots.png  the tissue at the minima whose phi_patch is nearest each --phi value:
                       cells filled and coloured by calA with their vertex disks (diameter from
                       the dump's d_sigma column; without it --sigma or each vertex's mean
                       segment length), the periodic box drawn
The growth file has one line per growth step (step P phi phi_patch calA z bonds dphi_plus
iterations); the dump has one frame per growth step with columns id mol xu yu c_vertex[3], the
last being the next vertex along each ring, and optionally d_sigma and other per-vertex columns.
Needs python3-numpy and python3-matplotlib.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesophyll_frames as mf  # noqa: E402

mf.require(["numpy", "matplotlib"])
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection, PolyCollection  # noqa: E402

PHI_MAX = 0.975
P_FLOOR = 1e-13      # |P/P0 - 1| drawn here when it is 0 to the growth table's 12 digits

read_growth = mf.read_growth
read_frames = mf.read_frames
shape_parameter = mf.shape_parameter


def pressure_deviation(P, P0):
    """|P/P0 - 1|, with exact zeros raised to P_FLOOR (for a log axis)."""
    return np.maximum(np.abs(np.asarray(P) / P0 - 1.0), P_FLOOR)


def draw_pressure(ax, steps, P, P0, **style):
    ax.semilogy(steps, pressure_deviation(P, P0), **style)
    ax.set_ylabel(r"$|P/P_0 - 1|$")
    ax.set_ylim(bottom=P_FLOOR / 2)


def periodic_shifts(poly, radius, lo, length):
    """Shifts (multiples of the box) of the periodic images of a cell that reach into the box."""
    a, b = poly.min(axis=0) - radius, poly.max(axis=0) + radius
    out = []
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            s = np.array([dx, dy]) * length
            if (a + s < lo + length).all() and (b + s > lo).all():
                out.append(s)
    return out


def draw_tissue(ax, lo, length, polygons, norm, cmap, sigmas=None, colours=None, scaled=False,
                edge=0.3, limits=None):
    """Each cell and its periodic images that reach into the box, clipped to the box; with
    sigmas (one array of diameters per cell) also its vertex disks, in the cell's colour.

    scaled: draw in box units ((x - lo) / length: the tissue frame, a box that stays put);
    colours: each cell's value for the colour map (default its shape parameter)."""
    lo, length = np.asarray(lo, dtype=float), np.asarray(length, dtype=float)
    if colours is None:
        colours = [shape_parameter(p) for p in polygons]
    shapes, values, centres, widths, heights, disk_values = [], [], [], [], [], []
    for k, poly in enumerate(polygons):
        radius = 0.5 * float(np.max(sigmas[k])) if sigmas is not None else 0.0
        for s in periodic_shifts(poly, radius, lo, length):
            xy = poly + s
            if scaled:
                xy = (xy - lo) / length
            shapes.append(xy)
            values.append(colours[k])
            if sigmas is not None:
                centres.append(xy)
                d = np.asarray(sigmas[k], dtype=float)
                widths.append(d / length[0] if scaled else d)
                heights.append(d / length[1] if scaled else d)
                disk_values.append(np.full(len(xy), colours[k]))
    blo, blen = (np.zeros(2), np.ones(2)) if scaled else (lo, length)
    box = plt.Rectangle(blo, blen[0], blen[1], fill=False, edgecolor="k", linewidth=1.2,
                        zorder=3)
    ax.add_patch(box)
    cells = PolyCollection(shapes, array=np.array(values), cmap=cmap, norm=norm,
                           edgecolors="k", linewidths=edge, zorder=2)
    ax.add_collection(cells)
    cells.set_clip_path(box)
    if sigmas is not None and centres:
        disks = EllipseCollection(np.concatenate(widths), np.concatenate(heights),
                                  np.zeros(sum(len(c) for c in centres)), units="xy",
                                  offsets=np.vstack(centres), offset_transform=ax.transData,
                                  array=np.concatenate(disk_values), cmap=cmap, norm=norm,
                                  edgecolors="k", linewidths=0.15 * edge, zorder=1)
        ax.add_collection(disks)
        disks.set_clip_path(box)
    if limits is None:
        limits = (blo[0], blo[0] + blen[0], blo[1], blo[1] + blen[1])
    ax.set_xlim(limits[0], limits[1])
    ax.set_ylim(limits[2], limits[3])
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    return cells


def frame_sigmas(frame, default=None):
    sigma, source = frame.sigma(default)
    return [sigma[r] for r in frame.rings], source


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("growth")
    p.add_argument("dump")
    p.add_argument("--phi", type=float, nargs="+", default=[0.9, 0.7, 0.5],
                   help="phi_patch of the snapshots (nearest minimum)")
    p.add_argument("--out", default="mesophyll", help="prefix of the PNG files")
    p.add_argument("--P0", type=float, default=1.0e-3,
                   help="target pressure of the run (default 1e-3, the main run's)")
    p.add_argument("--sigma", type=float, default=None,
                   help="vertex diameter where the dump has no d_sigma column (default: each "
                        "vertex's mean segment length)")
    p.add_argument("--no-disks", action="store_true", help="draw the polygons only")
    args = p.parse_args()

    g = read_growth(args.growth)

    fig, ax = plt.subplots(figsize=(4.5, 3.5))
    ax.plot(PHI_MAX - g["phi_patch"], g["calA"], "o-", ms=3)
    ax.set_xlabel(r"$\phi_{max} - \phi$ (patch)")
    ax.set_ylabel(r"mean $\mathcal{A}$")
    fig.tight_layout()
    fig.savefig(f"{args.out}_shape.png", dpi=150)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(4.5, 5), sharex=True)
    top.plot(g["step"], g["phi_patch"], "o-", ms=3, label=r"$\phi$ patch")
    top.plot(g["step"], g["phi"], "s-", ms=3, label=r"$\phi$ polygons")
    top.set_ylabel(r"$\phi$")
    top.legend()
    draw_pressure(bottom, g["step"], g["P"], args.P0, marker="o", ms=3)
    bottom.set_xlabel("growth step")
    bottom.set_title(f"pressure at the minimum ($P_0$ = {args.P0:g}; "
                     f"0 drawn at {P_FLOOR:g})", fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{args.out}_packing.png", dpi=150)

    frames = list(read_frames(args.dump))
    chosen = [int(np.argmin(np.abs(g["phi_patch"][:len(frames)] - phi))) for phi in args.phi]
    fig, axes = plt.subplots(1, len(chosen), figsize=(3.2 * len(chosen) + 0.8, 3.4))
    axes = np.atleast_1d(axes)
    norm = matplotlib.colors.Normalize(vmin=1.0, vmax=max(3.0, float(g["calA"].max())))
    source = None
    for ax, k in zip(axes, chosen):
        frame = frames[k]
        sigmas, source = frame_sigmas(frame, args.sigma)
        cells = draw_tissue(ax, frame.lo, frame.length, frame.polygons(), norm, "viridis",
                            sigmas=None if args.no_disks else sigmas)
        ax.set_title(f"step {int(g['step'][k])}, " + r"$\phi$" + f" = {g['phi_patch'][k]:.2f}")
    fig.colorbar(cells, ax=axes.tolist(), label=r"$\mathcal{A}$", shrink=0.8)
    fig.savefig(f"{args.out}_snapshots.png", dpi=150)
    if not args.no_disks:
        print(f"vertex disks: {source}")
    print(f"wrote {args.out}_shape.png, {args.out}_packing.png, {args.out}_snapshots.png")


if __name__ == "__main__":
    main()
