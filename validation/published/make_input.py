#!/usr/bin/env python3
"""Convert a package data file (examples/mesophyll/tissue_N16.data, ...) into the published
code's input file, the same tissue: positions, ring order, radii r = sigma/2, l0, theta0, a0, box.

    make_input.py DATA OUT [--kb 0.4] [--radius-factor 1.00001]

The published code reads no bond list: its constructor and initializeMesophyllBondNetwork()
bond every pair of vertices of different cells that overlap, r < r_i + r_j. The data files hold
bonds that were made that way and then relaxed to just touching: in tissue_N16.data 25 of the
314 sit at r/s between 1 and 1 + 5e-6, so at the exact radii the published code would start with
289. The radii are therefore written times --radius-factor (default 1 + 1e-5, far below any
effect on the mechanics), which makes the published rule give exactly the file's 314 bonds for
N16. The script prints the counts at both radii and whether the sets are equal; run.py checks
the bonds the published code itself printed in its first frame.

kb (the bending stiffness per vertex, written into every VINFO line) is overwritten by the
driver's kb0 argument (meso2D::setkbi) anyway; theta0 by the driver's t0ToCurrent(), which sets
it to the current angles, as the data files already have it (checked below).
"""
import argparse

import numpy as np

import frames


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("data")
    p.add_argument("out")
    p.add_argument("--kb", type=float, default=0.4, help="eps_b of the package's default set")
    p.add_argument("--radius-factor", type=float, default=1.00001)
    a = p.parse_args()

    t = frames.read_data(a.data)
    data = set(t.bonds)
    exact = set(frames.overlaps(t))
    t = t._replace(cells=[c._replace(r=c.r * a.radius_factor) for c in t.cells])
    scaled = set(frames.overlaps(t))
    dtheta = max(np.max(np.abs(frames.turning_angles(c) - c.theta0)) for c in t.cells)
    print(f"{a.data}: {len(t.cells)} cells, {sum(len(c.x) for c in t.cells)} vertices, "
          f"box {t.L:.10g}, max |theta - theta0| {dtheta:.1e}")
    print(f"adhesive bonds in the data file: {len(data)}")
    print(f"pairs the published rule bonds at r = sigma/2: {len(exact)} "
          f"(not in the file {len(exact - data)}, missing {len(data - exact)})")
    print(f"pairs it bonds at r = {a.radius_factor:g} sigma/2: {len(scaled)} "
          f"(not in the file {len(scaled - data)}, missing {len(data - scaled)})"
          + (": the same set" if scaled == data else ""))
    frames.write_published(t._replace(bonds=sorted(scaled)), a.out, a.kb)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
