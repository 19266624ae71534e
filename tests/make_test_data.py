#!/usr/bin/env python3
"""Make the data files the tests read, with the package's own generator (tools/make_cells.py)."""
import os
import subprocess
import sys

generator, outdir = sys.argv[1], sys.argv[2]
os.makedirs(outdir, exist_ok=True)
configs = {
    # deformed rings that cross the periodic boundary: forces, virial, MPI, restart
    "deformed.data": ["--cells", "4", "--vertices", "12", "--jitter", "0.15", "--seed", "7",
                      "--shift", "0.3", "--spacing", "1.1"],
    # one regular ring: analytic energies and relaxation
    "single.data": ["--cells", "1", "--vertices", "16", "--spacing", "3.0"],
    # touching cells whose vertex disks overlap, for adhesion and breaking, in order and shuffled
    # (spacing above 1 + jitter: the outlines do not cross); one ring for contacts
    "overlapping.data": ["--cells", "9", "--vertices", "16", "--spacing", "1.03", "--jitter",
                         "0.02", "--seed", "5", "--shift", "0.2", "--bond-types", "2"],
    "overlapping_shuffled.data": ["--cells", "9", "--vertices", "16", "--spacing", "1.03",
                                  "--jitter", "0.02", "--seed", "5", "--shift", "0.2",
                                  "--bond-types", "2", "--shuffle", "11"],
    "single_contacts.data": ["--cells", "1", "--vertices", "16", "--spacing", "3.0",
                             "--bond-types", "2"],
    # triangles, whose segments (1.5) outreach the communication cutoff of in.relax_cells
    "triangles.data": ["--cells", "9", "--vertices", "3"],
}
configs["ring12.mol"] = ["--molecule", "--vertices", "12"]    # a molecule template
for name, args in configs.items():
    subprocess.run([sys.executable, generator, os.path.join(outdir, name)] + args, check=True)
print(f"wrote {len(configs)} data files to {outdir}")
