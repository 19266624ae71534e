#!/usr/bin/env python3
"""Make the 3d data files the tests read, with the package's generator (tools/make_cells3d.py)."""
import os
import subprocess
import sys

generator, outdir = sys.argv[1], sys.argv[2]
os.makedirs(outdir, exist_ok=True)
configs = {
    # two jittered 42-vertex cells across the periodic boundary: forces, virial, MPI, restart
    "cells3d_deformed.data": ["--cells", "2", "--level", "1", "--jitter", "0.08", "--seed", "3",
                              "--shift", "0.3", "--spacing", "1.3"],
    # one regular icosahedron of circumradius 1: analytic energies and relaxation
    "icosahedron.data": ["--cells", "1", "--level", "0", "--spacing", "2.0"],
    # two overlapping cells (across the boundary too) with large vertex spheres, so that
    # neighbours across a face overlap as well: contacts between and within cells
    "cells3d_touching.data": ["--cells", "2", "--level", "1", "--jitter", "0.05", "--seed", "9",
                              "--spacing", "0.9", "--shift", "0.1", "--sigma", "1.0"],
    # three jittered cells, the first overlapping the other two (across the boundary too) by
    # different numbers of vertex pairs: adhesion, contact numbers per cell, breaking
    "cells3d_adhesive.data": ["--cells", "3", "--level", "1", "--jitter", "0.05", "--seed", "4",
                              "--spacing", "0.95", "--box", "5.0", "--shift", "0.35"],
    # two regular icosahedra, the second the first moved by 1.26 (1.2 sigma) in x: hand-made
    # adhesive bonds between counterparts, all stretched alike (breaking at junction edges)
    "two_icosahedra.data": ["--cells", "2", "--level", "0", "--spacing", "0.63", "--box", "6.0"],
    # one 642-vertex cell: data-file lines of full-precision per-edge values
    "icosphere3.data": ["--cells", "1", "--level", "3", "--spacing", "2.0"],
}
for name, args in configs.items():
    subprocess.run([sys.executable, generator, os.path.join(outdir, name)] + args, check=True)
print(f"wrote {len(configs)} data files to {outdir}")
