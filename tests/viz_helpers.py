"""Helpers of the Python tests of tools/: import the tools, skip (exit 77) when a Debian package
is missing, write small synthetic dumps with known geometry."""
import os
import sys

TOOLS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools")
sys.path.insert(0, TOOLS)

SKIP = 77       # ctest's SKIP_RETURN_CODE for these tests
os.environ["MESOPHYLL_MISSING_EXIT"] = str(SKIP)    # also for mesophyll_frames's own check


def require(modules):
    """Exit with ctest's skip code, naming the Debian packages, if a module is missing (after
    trying Debian's /usr/bin/python3, as the tools do)."""
    import mesophyll_frames as mf
    mf.require(modules, exit_code=SKIP)


def regular_ring(n, radius, centre, phase=0.0):
    import numpy as np
    t = phase + 2 * np.pi * np.arange(n) / n
    return np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


def write_dump(path, frames, extra=("d_sigma",)):
    """Write a LAMMPS custom dump with columns id mol xu yu c_vertex[3] and the extra columns.

    frames: list of (timestep, lo, hi, cells) with cells a list of (ring (n, 2) array,
    {extra column: value or per-vertex array}). Atom IDs run through the rings in order;
    rows are written in a shuffled order, as LAMMPS's are not sorted."""
    import numpy as np
    rng = np.random.default_rng(5)
    with open(path, "w") as f:
        for timestep, lo, hi, cells in frames:
            rows, tag = [], 1
            for mol, (ring, values) in enumerate(cells, start=1):
                n = len(ring)
                for k in range(n):
                    nxt = tag + (k + 1) % n - k
                    vals = []
                    for name in extra:
                        v = values[name]
                        vals.append(float(v[k]) if np.ndim(v) else float(v))
                    rows.append(f"{tag} {mol} {ring[k, 0]:.10g} {ring[k, 1]:.10g} {nxt} "
                                + " ".join(f"{v:.10g}" for v in vals))
                    tag += 1
            order = rng.permutation(len(rows))
            f.write(f"ITEM: TIMESTEP\n{timestep}\nITEM: NUMBER OF ATOMS\n{len(rows)}\n"
                    "ITEM: BOX BOUNDS pp pp pp\n"
                    f"{lo[0]} {hi[0]}\n{lo[1]} {hi[1]}\n-0.5 0.5\n"
                    "ITEM: ATOMS id mol xu yu c_vertex[3] " + " ".join(extra) + "\n")
            f.write("\n".join(rows[k] for k in order) + "\n")


def write_bond_dump(path, frames):
    """Local dump of bonds: frames = list of (timestep, lo, hi, [(atom1, atom2, type), ...])."""
    with open(path, "w") as f:
        for timestep, lo, hi, bonds in frames:
            f.write(f"ITEM: TIMESTEP\n{timestep}\nITEM: NUMBER OF ENTRIES\n{len(bonds)}\n"
                    "ITEM: BOX BOUNDS pp pp pp\n"
                    f"{lo[0]} {hi[0]}\n{lo[1]} {hi[1]}\n-0.5 0.5\n"
                    "ITEM: ENTRIES index c_bonds[1] c_bonds[2] c_bonds[3]\n")
            for k, (a, b, t) in enumerate(bonds, start=1):
                f.write(f"{k} {a} {b} {t}\n")
