#!/usr/bin/env python3
"""Draw a MESOPHYLL development run: what examples/mesophyll/in.mesophyll writes.

    plot_mesophyll.py growth.N64.txt cells.N64.dump [--phi 0.9 0.7 0.5] [--out mesophyll]

Writes three PNGs next to --out:
  <out>_shape.png      mean calA against phi_max - phi_patch (phi_max = 0.975, as the paper)
  <out>_packing.png    phi, phi_patch and P against growth step
  <out>_snapshots.png  the tissue at the minima whose phi_patch is nearest each --phi value:
                       cells filled and coloured by calA, the periodic box drawn
The growth file has one line per growth step (step P phi phi_patch calA z bonds dphi_plus
iterations); the dump has one frame per growth step with columns id mol xu yu c_vertex[3], the
last being the next vertex along each ring. Needs python3-numpy and python3-matplotlib.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

PHI_MAX = 0.975


def read_growth(path):
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    data = np.loadtxt(path, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def read_frames(path):
    """Yield (box lo, box length, {atom id: (mol, x, y, next id)}) for every dump frame."""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if not line.startswith("ITEM: TIMESTEP"):
            continue
        next(lines)
        next(lines)
        natoms = int(next(lines))
        next(lines)
        bounds = [list(map(float, next(lines).split()[:2])) for _ in range(3)]
        columns = next(lines).split()[2:]
        col = {name: k for k, name in enumerate(columns)}
        atoms = {}
        for _ in range(natoms):
            w = next(lines).split()
            atoms[int(w[col["id"]])] = (int(w[col["mol"]]), float(w[col["xu"]]),
                                        float(w[col["yu"]]), int(float(w[col["c_vertex[3]"]])))
        lo = np.array([bounds[0][0], bounds[1][0]])
        length = np.array([bounds[0][1] - bounds[0][0], bounds[1][1] - bounds[1][0]])
        yield lo, length, atoms


def rings(atoms):
    """Each cell's vertices in ring order, as an (n, 2) array of unwrapped positions."""
    by_cell = {}
    for tag, (mol, _, _, _) in atoms.items():
        by_cell.setdefault(mol, tag)
    polygons = []
    for start in by_cell.values():
        order, tag = [], start
        while True:
            order.append(atoms[tag][1:3])
            tag = atoms[tag][3]
            if tag == start or len(order) > len(atoms):
                break
        polygons.append(np.array(order))
    return polygons


def shape_parameter(poly):
    x, y = poly[:, 0], poly[:, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    perimeter = np.sum(np.hypot(np.roll(x, -1) - x, np.roll(y, -1) - y))
    return perimeter ** 2 / (4 * np.pi * area)


def draw_tissue(ax, lo, length, polygons, norm, cmap):
    """Each cell and its periodic images that reach into the box, clipped to it."""
    shapes, colours = [], []
    for poly in polygons:
        centre = poly.mean(axis=0)
        shift = np.floor((centre - lo) / length) * length    # bring the cell into the box
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                shapes.append(poly - shift + np.array([dx, dy]) * length)
                colours.append(shape_parameter(poly))
    cells = PolyCollection(shapes, array=np.array(colours), cmap=cmap, norm=norm,
                           edgecolors="k", linewidths=0.3)
    ax.add_collection(cells)
    box = plt.Rectangle(lo, length[0], length[1], fill=False, edgecolor="k", linewidth=1.2)
    ax.add_patch(box)
    cells.set_clip_path(box)
    ax.set_xlim(lo[0], lo[0] + length[0])
    ax.set_ylim(lo[1], lo[1] + length[1])
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    return cells


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("growth")
    p.add_argument("dump")
    p.add_argument("--phi", type=float, nargs="+", default=[0.9, 0.7, 0.5],
                   help="phi_patch of the snapshots (nearest minimum)")
    p.add_argument("--out", default="mesophyll", help="prefix of the PNG files")
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
    bottom.plot(g["step"], g["P"], "o-", ms=3)
    bottom.set_xlabel("growth step")
    bottom.set_ylabel("P at the minimum")
    bottom.ticklabel_format(axis="y", useOffset=False)
    fig.tight_layout()
    fig.savefig(f"{args.out}_packing.png", dpi=150)

    frames = list(read_frames(args.dump))
    chosen = [int(np.argmin(np.abs(g["phi_patch"][:len(frames)] - phi))) for phi in args.phi]
    fig, axes = plt.subplots(1, len(chosen), figsize=(3.2 * len(chosen) + 0.8, 3.4))
    axes = np.atleast_1d(axes)
    norm = matplotlib.colors.Normalize(vmin=1.0, vmax=max(3.0, float(g["calA"].max())))
    for ax, k in zip(axes, chosen):
        lo, length, atoms = frames[k]
        cells = draw_tissue(ax, lo, length, rings(atoms), norm, "viridis")
        ax.set_title(f"step {int(g['step'][k])}, " + r"$\phi$" + f" = {g['phi_patch'][k]:.2f}")
    fig.colorbar(cells, ax=axes.tolist(), label=r"$\mathcal{A}$", shrink=0.8)
    fig.savefig(f"{args.out}_snapshots.png", dpi=150)
    print(f"wrote {args.out}_shape.png, {args.out}_packing.png, {args.out}_snapshots.png")


if __name__ == "__main__":
    main()
