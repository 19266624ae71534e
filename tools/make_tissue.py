#!/usr/bin/env python3
"""Make a confluent initial tissue fast: rings seeded in a Voronoi tessellation, packed by fire/nph.

    tools/make_tissue.py tissue.data --cells 64 [--seed 1] [--vertices 32] [--calA0 1.14]
                         [--polydispersity 0] [--pressure 1e-6] [--pack-pressure 3e-4]
                         [--pack-rate 3e-3] [--start-phi 0.6] [--lloyd 1] [--lmp build/lmp]
                         [--np 1] [--mpirun CMD] [--mpirun-flags FLAGS] [--rings-only]

examples/tissue/in.make_tissue packs regular rings from a dilute box in about a hundred 1%
compressions, each relaxed to a force tolerance (about 2.3 million FIRE iterations for 16
cells). This tool starts next to contact and packs in one enthalpy minimization:

1. Seeds. N points at random in a periodic square box (numpy's generator from --seed), moved
   --lloyd times to the centroids of their periodic Voronoi regions (Lloyd's algorithm): one
   step keeps the disorder of a random packing but parts seeds that fell close together (20
   steps make the seeds nearly hexagonal, and the tissue tiles the plane with z = 6).
2. Rings. In each region, moved inward by half the cell's vertex diameter along every edge (so
   the disks of two neighbours cannot overlap), the disk about the region's centroid whose part
   inside the region has the cell's area a0; its outline is resampled at n vertices of equal
   arc length, counter-clockwise, from a random phase. The box holds the cells at packing
   fraction --start-phi (sum a0 / box area). Per vertex the state of the package's initial
   cells: a0, p0 from calA0 (relative to the regular n-gon), l0 = sigma = p0/n,
   theta0 = 2 pi/n. --polydispersity D draws sqrt(a0) log-normally (standard deviation D of
   its logarithm), scaled to a mean of 1 (the unit of length); the regions are alike, so a big
   cell may fill its region with less than its a0 and start compressed.
3. Relaxation (examples/tissue/in.relax_tissue, unless --rings-only): fire/nph with fix
   box/relax iso at the packing pressure --pack-pressure, bending off, until 5000 FIRE
   iterations compact the box by less than --pack-rate of its area, the cells touching (mean
   z >= 3); then the initial state as
   in.make_tissue defines it: every overlapping vertex pair of different cells bonded
   (adhere_cells), theta0 = the current angles, relaxation with bending on at the target
   pressure --pressure (P_jam) to the force tolerance (fix dpoly/check stops a relaxation that
   misses it), theta0 again; write_data. The progress lines (pressure, packing, compaction per
   chunk) are printed as LAMMPS writes them.

The defaults (--pack-pressure 3e-4, --pack-rate 3e-3, --lloyd 1) were chosen so that the tissues
match in.make_tissue's (bench/tissue_generator.py). Randomness comes from --seed alone, never
from the number of MPI ranks; the relaxation draws nothing. With --np N > 1 the relaxation runs
under the launcher of tools/mpi_launcher.py (--mpirun and --mpirun-flags, else $MESOPHYLL_MPIRUN
and $MESOPHYLL_MPIRUN_FLAGS, else Debian's Open MPI: mpirun -np N --oversubscribe). Needs
python3-numpy and python3-scipy (Debian).
"""
import argparse
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mesophyll_frames  # noqa: E402

mesophyll_frames.require(["numpy", "scipy"])
import numpy as np  # noqa: E402
from scipy.spatial import Voronoi  # noqa: E402

import make_cells  # noqa: E402
import mpi_launcher  # noqa: E402

RELAX_INPUT = os.path.join(ROOT, "examples", "tissue", "in.relax_tissue")
# the 3 x 3 periodic images of the seeds: the regions of the middle copy are closed and whole
IMAGES = np.array([(a, b) for a in (-1, 0, 1) for b in (-1, 0, 1)], dtype=float)


def polygon_centroid(p):
    x, y = p[:, 0], p[:, 1]
    cross = x * np.roll(y, -1) - np.roll(x, -1) * y
    a = 0.5 * cross.sum()
    return np.array([((x + np.roll(x, -1)) * cross).sum(),
                     ((y + np.roll(y, -1)) * cross).sum()]) / (6.0 * a)


def voronoi_regions(seeds, box):
    """The periodic Voronoi region of every seed, a counter-clockwise convex polygon (unwrapped,
    around its seed)."""
    n = len(seeds)
    points = np.concatenate([seeds + box * shift for shift in IMAGES])
    middle = int(np.flatnonzero((IMAGES == 0).all(axis=1))[0])
    vor = Voronoi(points)
    regions = []
    for k in range(middle * n, (middle + 1) * n):
        region = vor.regions[vor.point_region[k]]
        if not region or -1 in region:
            raise SystemExit("make_tissue: a Voronoi region is open; too few cells for the box")
        poly = vor.vertices[region]
        angle = np.arctan2(poly[:, 1] - points[k, 1], poly[:, 0] - points[k, 0])
        regions.append(poly[np.argsort(angle)])
    return regions


def lloyd(seeds, box, iterations):
    """Lloyd's algorithm: every seed moves to its region's centroid, wrapped into the box."""
    for _ in range(iterations):
        seeds = np.array([polygon_centroid(r) for r in voronoi_regions(seeds, box)]) % box
    return seeds


def inset(polygon, d):
    """A convex CCW polygon with every edge moved inward by d (clipped half plane by half plane)."""
    result = polygon
    for a, b in zip(polygon, np.roll(polygon, -1, axis=0)):
        t = b - a
        normal = np.array([-t[1], t[0]]) / np.hypot(*t)    # inward for CCW order
        inside = (result - a) @ normal - d                     # >= 0: kept
        clipped = []
        for k in range(len(result)):
            p, q = result[k], result[(k + 1) % len(result)]
            sp, sq = inside[k], inside[(k + 1) % len(result)]
            if sp >= 0:
                clipped.append(p)
            if (sp >= 0) != (sq >= 0):
                clipped.append(p + (q - p) * sp / (sp - sq))
        if len(clipped) < 3:
            raise SystemExit("make_tissue: a Voronoi region is narrower than a vertex diameter; "
                             "raise --start-phi's box (lower --start-phi) or use more --lloyd")
        result = np.array(clipped)
    return result


ANGLES = np.linspace(0.0, 2.0 * np.pi, 2048, endpoint=False)


def radial_distance(polygon, centre):
    """Distance from centre (inside the convex polygon) to its boundary along each of ANGLES."""
    u = np.column_stack([np.cos(ANGLES), np.sin(ANGLES)])
    a, b = polygon, np.roll(polygon, -1, axis=0)
    t = b - a
    outward = np.column_stack([t[:, 1], -t[:, 0]]) / np.hypot(t[:, 0], t[:, 1])[:, None]
    offset = np.einsum("ij,ij->i", outward, a - centre)          # > 0: centre inside
    along = u @ outward.T                                          # (angles, edges)
    with np.errstate(divide="ignore"):
        reach = np.where(along > 1e-12, offset[None, :] / along, np.inf)
    return reach.min(axis=1)


def disk_in_region(polygon, area):
    """The disk about the region's centroid whose part inside the (convex) region has the given
    area, as a polygon on ANGLES; the whole region where it is smaller than that area."""
    centre = polygon_centroid(polygon)
    wall = radial_distance(polygon, centre)
    dtheta = ANGLES[1] - ANGLES[0]

    def cut_area(radius):
        return 0.5 * float(np.sum(np.minimum(wall, radius) ** 2)) * dtheta

    lo, hi = 0.0, float(wall.max())
    if cut_area(hi) > area:
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if cut_area(mid) < area else (lo, mid)
    r = np.minimum(wall, hi)
    return centre + np.column_stack([r * np.cos(ANGLES), r * np.sin(ANGLES)])


def resample(polygon, n, phase):
    """n points at equal arc length along a closed polygon, the first at fraction phase of it."""
    closed = np.vstack([polygon, polygon[:1]])
    pieces = np.hypot(*np.diff(closed, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(pieces)])
    targets = (phase + np.arange(n) / n) % 1.0 * s[-1]
    return np.column_stack([np.interp(targets, s, closed[:, 0]),
                            np.interp(targets, s, closed[:, 1])])


def cell_areas(cells, polydispersity, rng):
    """Preferred areas a0: sqrt(a0) log-normal with spread polydispersity, mean sqrt(a0) = 1."""
    if polydispersity == 0:
        return np.ones(cells)
    size = np.exp(polydispersity * rng.standard_normal(cells))
    return (size / size.mean()) ** 2


def build(args):
    rng = np.random.default_rng(args.seed)
    n = args.vertices
    a0 = cell_areas(args.cells, args.polydispersity, rng)
    regular = n * math.tan(math.pi / n) / math.pi
    p0 = np.sqrt(4.0 * math.pi * a0 * args.calA0 * regular)
    sigma = p0 / n
    box = math.sqrt(a0.sum() / args.start_phi)
    seeds = lloyd(rng.uniform(0.0, box, size=(args.cells, 2)), box, args.lloyd)
    phases = rng.uniform(0.0, 1.0, size=args.cells)
    rings = []
    for region, area, s, phase in zip(voronoi_regions(seeds, box), a0, sigma, phases):
        # the rings of two neighbours keep a vertex diameter apart: each stays sigma/2 inside
        rings.append(resample(disk_in_region(inset(region, 0.5 * s), area), n, phase))
    atoms, bonds, angles, state = [], [], [], []
    for c, ring in enumerate(rings):
        first = len(atoms) + 1
        l0 = float(sigma[c])
        for x, y in ring:
            ix, iy = math.floor(x / box), math.floor(y / box)
            atoms.append((len(atoms) + 1, c + 1, x - ix * box, y - iy * box, ix, iy))
            state.append((l0, l0, 2.0 * math.pi / n, float(a0[c])))
        for k in range(n):
            prev, here, nxt = first + (k - 1) % n, first + k, first + (k + 1) % n
            bonds.append((here, nxt))
            angles.append((prev, here, nxt))
    return box, atoms, bonds, angles, state


def relax(args, rings, output):
    """Run in.relax_tissue on the rings; print its progress lines; return the summary line."""
    variables = {"rings": os.path.abspath(rings), "out": os.path.abspath(output),
                 "P_jam": repr(args.pressure), "ftol": repr(args.ftol),
                 "P_pack": repr(args.pack_pressure), "pack_rate": repr(args.pack_rate)}
    command = [args.lmp, "-in", RELAX_INPUT, "-echo", "none",
               "-log", os.path.abspath(args.log) if args.log else "none"]
    for name, value in variables.items():
        command += ["-var", name, value]
    command, env = mpi_launcher.command(args.np, command, args.mpirun, args.mpirun_flags)
    summary = None
    with subprocess.Popen(command, cwd=os.path.dirname(os.path.abspath(output)), env=env, text=True,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT) as lmp:
        tail = []
        for line in lmp.stdout:
            tail = (tail + [line])[-30:]
            if line.startswith("make_tissue:"):    # the progress lines of in.relax_tissue
                print(line.rstrip(), flush=True)
                if line.startswith("make_tissue: tissue"):
                    summary = line.strip()
            elif args.verbose:
                print("  " + line.rstrip(), flush=True)
        lmp.wait()
    if lmp.returncode != 0:
        raise SystemExit(f"make_tissue: LAMMPS failed (exit code {lmp.returncode}):\n"
                         + "".join(tail))
    return summary


def check_arguments(p, args):
    if args.cells < 4:
        p.error(f"--cells must be at least 4 (a cell must not touch its own periodic image), "
                f"got {args.cells}")
    if args.vertices < 8:
        p.error(f"--vertices must be at least 8, got {args.vertices}")
    if not 1.0 <= args.calA0 < 10.0:
        p.error(f"--calA0 is relative to the regular n-gon and must lie in [1, 10), "
                f"got {args.calA0}")
    if not 0.0 <= args.polydispersity <= 0.5:
        p.error(f"--polydispersity must lie in [0, 0.5], got {args.polydispersity}")
    if not (args.pressure > 0.0 and math.isfinite(args.pressure)):
        p.error(f"--pressure (the target, jamming pressure) must be positive, got {args.pressure}")
    if not 0.05 <= args.start_phi <= 0.95:
        p.error(f"--start-phi must lie in [0.05, 0.95], got {args.start_phi}")
    if not (args.pack_pressure > 0.0 and math.isfinite(args.pack_pressure)):
        p.error(f"--pack-pressure must be positive, got {args.pack_pressure}")
    if not 0.0 < args.pack_rate < 1.0:
        p.error(f"--pack-rate must lie in (0, 1), got {args.pack_rate}")
    if args.lloyd < 0:
        p.error(f"--lloyd must be >= 0, got {args.lloyd}")
    if args.seed < 0:
        p.error(f"--seed must be >= 0, got {args.seed}")
    if args.np < 1:
        p.error(f"--np must be >= 1, got {args.np}")
    if not (args.ftol > 0.0):
        p.error(f"--ftol must be positive, got {args.ftol}")
    if not args.rings_only:
        if args.lmp is None:
            args.lmp = os.path.join(ROOT, "build", "lmp")
        if not os.access(args.lmp, os.X_OK):
            p.error(f"--lmp {args.lmp}: no LAMMPS executable there (build it with "
                    "tools/setup.sh, or give --rings-only)")
        args.lmp = os.path.abspath(args.lmp)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output", help="data file to write")
    p.add_argument("--cells", type=int, required=True, help="number of cells (at least 4)")
    p.add_argument("--vertices", type=int, default=32, help="vertices per cell (default 32)")
    p.add_argument("--calA0", type=float, default=1.14,
                   help="preferred shape parameter relative to the regular n-gon (default 1.14)")
    p.add_argument("--polydispersity", type=float, default=0.0,
                   help="standard deviation of ln sqrt(a0) (default 0: all cells alike)")
    p.add_argument("--pressure", type=float, default=1.0e-6,
                   help="target (jamming) pressure (default 1e-6)")
    p.add_argument("--seed", type=int, default=1, help="random seed (default 1)")
    p.add_argument("--start-phi", type=float, default=0.6,
                   help="packing fraction (sum a0 / box area) of the seeded rings (default 0.6)")
    p.add_argument("--lloyd", type=int, default=1,
                   help="Lloyd iterations of the seeds (default 1; more make the tissue ordered: "
                        "20 tile it hexagonally, z = 6)")
    p.add_argument("--rings-only", action="store_true",
                   help="write the seeded rings and stop (no LAMMPS relaxation)")
    p.add_argument("--lmp", default=None, help="LAMMPS executable (default build/lmp)")
    p.add_argument("--np", type=int, default=1, help="MPI ranks for the relaxation (default 1)")
    p.add_argument("--mpirun", default=None,
                   help="MPI launcher command (default $MESOPHYLL_MPIRUN, else mpirun)")
    p.add_argument("--mpirun-flags", default=None,
                   help="launcher flags after the rank count (default $MESOPHYLL_MPIRUN_FLAGS, "
                        "else --oversubscribe for Open MPI, none for others)")
    p.add_argument("--ftol", type=float, default=1.0e-10,
                   help="force tolerance of the minimizations (default 1e-10)")
    p.add_argument("--pack-pressure", type=float, default=3.0e-4,
                   help="pressure of the packing stage, bending off (default 3e-4)")
    p.add_argument("--pack-rate", type=float, default=3.0e-3,
                   help="the packing ends when 5000 FIRE iterations compact the box area by less "
                        "than this fraction (default 3e-3)")
    p.add_argument("--log", default=None, help="LAMMPS log file (default none)")
    p.add_argument("--verbose", action="store_true", help="print all of LAMMPS's output")
    args = p.parse_args()
    check_arguments(p, args)

    start = time.perf_counter()
    box, atoms, bonds, angles, state = build(args)
    comment = (f"{args.cells} cells of {args.vertices} vertices seeded in a centroidal Voronoi "
               f"tessellation, seed {args.seed} (MESOPHYLL tools/make_tissue.py)")
    rings = args.output if args.rings_only else args.output + ".rings"
    make_cells.write(rings, box, atoms, bonds, angles, state, comment, bond_types=2)
    print(f"make_tissue: {args.cells} rings of {args.vertices} vertices in a box of "
          f"{box:.4f} ({time.perf_counter() - start:.2f} s)", flush=True)
    if args.rings_only:
        return
    try:
        summary = relax(args, rings, args.output)
    finally:
        os.remove(rings)
    if summary is None:
        raise SystemExit("make_tissue: LAMMPS ended without its summary line")
    print(f"make_tissue: wrote {args.output} in {time.perf_counter() - start:.1f} s", flush=True)


if __name__ == "__main__":
    main()
