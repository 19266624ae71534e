#!/usr/bin/env python3
"""The tools on a real run: examples/mesophyll/in.mesophyll_short (16 cells, 3 growth steps) in a
scratch copy, once with the plain dump (positions and ring order) and once with the shipped
per-vertex columns and a bond dump the tools can use (a local dump and its compute added). The cells read from the
dump must give the growth table's phi and mean calA (compute dpoly/tissue's values at the
minimum, printed to 6 digits), the rasterized polygons the same to pixel accuracy, and, with
the bonds, the same mean contact number z.

    test_tools_on_run.py --lmp build/lmp --example examples/mesophyll

Exit 77 (skip) only if a Debian package is missing."""
import argparse
import contextlib
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viz_helpers as vh  # noqa: E402

vh.require(["numpy", "scipy", "skimage", "vtk"])
import numpy as np  # noqa: E402

import image_metrics as im  # noqa: E402
import mesophyll_frames as mf  # noqa: E402
import write_vtk  # noqa: E402

COMPUTES = "compute         bonds all property/local batom1 batom2 btype\n"
PLAIN = "write_dump      all custom cells.N${N}.dump id mol xu yu c_vertex[3] modify append yes\n"
BOND_DUMP = ("write_dump      all local bonds.N${N}.dump index c_bonds[1] c_bonds[2] c_bonds[3] "
             "modify append yes\n")
# the cells' write_dump command, continuation lines ('&') included
DUMP_LINE = re.compile(r"^write_dump\s+all custom cells\.N\$\{N\}\.dump(?:[^\n]*&\n)*[^\n]*\n",
                       re.M)

failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def edit_input(path, extended):
    """A copy of in.mesophyll with the plain dump (positions and ring order only), or with the
    shipped per-vertex columns and a second, local dump of the bonds."""
    with open(path) as f:
        text = f.read()
    line = DUMP_LINE.search(text)
    if line is None or "d_sigma" not in line.group(0):
        raise SystemExit(f"{path}: no 'write_dump all custom cells.N${{N}}.dump ... d_sigma' line")
    if extended:
        text = text[:line.end()] + BOND_DUMP + text[line.end():]
        text = re.sub(r"^(label\s+growth\s*)$", COMPUTES + r"\1", text, count=1, flags=re.M)
    else:
        text = text[:line.start()] + PLAIN + text[line.end():]
    with open(path, "w") as f:
        f.write(text)


def run_lammps(lmp, folder):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    r = subprocess.run([lmp, "-in", "in.mesophyll_short", "-log", "log.test", "-screen", "none"],
                       cwd=folder, env=env, capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        raise SystemExit(f"lmp failed in {folder}:\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}")


def check_run(folder, extended):
    tag = "extended dump" if extended else "plain dump"
    growth = mf.read_growth(os.path.join(folder, "growth.N16.txt"))
    frames = list(mf.read_frames(os.path.join(folder, "cells.N16.dump")))
    check(len(frames) == len(growth["step"]) == 3, f"{tag}: 3 frames, 3 growth rows")
    bonds = None
    if extended:
        bonds = dict(mf.read_bond_frames(os.path.join(folder, "bonds.N16.dump")))
        check(sorted(bonds) == [f.timestep for f in frames], f"{tag}: a bond frame per frame")
    for k, frame in enumerate(frames):
        sigma, source = frame.sigma()
        check((source == "d_sigma") == extended, f"{tag} {k}: sigma from {source}")
        pairs = mf.adhesive_pairs(frame, bonds[frame.timestep]) if extended else None
        sim = im.simulation_values(frame, sigma, bonds[frame.timestep] if extended else None)
        check(abs(sim["phi"] - growth["phi"][k]) < 2e-6,
              f"{tag} {k}: phi {sim['phi']:.6f} = growth table {growth['phi'][k]:.6f}")
        calA = float(np.mean(sim["calA"]))
        check(abs(calA - growth["calA"][k]) < 2e-6,
              f"{tag} {k}: mean calA {calA:.6f} = growth table {growth['calA'][k]:.6f}")
        if extended:
            # the dump is written after the breaking pass, the growth table at the minimum
            # before it: a bond broken as the last between two cells lowers the mean by 2/16
            check(abs(np.mean(sim["z"]) - growth["z"][k]) < 0.13,
                  f"{tag} {k}: mean z {np.mean(sim['z']):.4f} = growth table {growth['z'][k]:.4f}")
            counts = mf.vertex_bond_counts(frame, pairs)
            check((counts == frame.column(mf.ADHESION)).all(),
                  f"{tag} {k}: bonds per vertex from the bond dump = c_adhesion")
    # the last frame rasterized as polygons at about 150 pixels per cell diameter
    frame = frames[-1]
    polys, sig, labs, sigma, _ = im.frame_cells(frame)
    px = float(frame.length[0]) / 500
    labels = im.rasterize(polys, sig, labs, frame.lo, frame.length, px, "polygon")
    m = im.measure_labels(labels, px, periodic=True, pores=False)
    calA = np.mean([c["calA"] for c in m["cells"]])
    check(len(m["cells"]) == 16, f"{tag}: 16 cells in the image")
    check(abs(m["porosity"] - (1 - growth["phi"][-1])) < 0.002,
          f"{tag}: image porosity {m['porosity']:.4f}, 1 - phi {1 - growth['phi'][-1]:.4f}")
    check(abs(calA / growth["calA"][-1] - 1) < 0.01,
          f"{tag}: image mean calA {calA:.4f}, growth table {growth['calA'][-1]:.4f}")
    # VTK files of the run
    out = os.path.join(folder, "vtk", "run")
    args = [os.path.join(folder, "cells.N16.dump"), "--out", out,
            "--growth", os.path.join(folder, "growth.N16.txt")]
    if extended:
        args += ["--bonds", os.path.join(folder, "bonds.N16.dump")]
    with contextlib.redirect_stdout(io.StringIO()):
        write_vtk.main(args)
    import vtk
    from vtk.util import numpy_support as ns
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(out + "_cells_0002.vtp")
    r.Update()
    cd = r.GetOutput().GetCellData()
    vcal = ns.vtk_to_numpy(cd.GetArray("calA")).mean()
    check(abs(vcal - growth["calA"][-1]) < 2e-6, f"{tag}: VTK mean calA {vcal:.6f}")
    if extended:
        check(cd.GetArray("void_fraction") is not None and cd.GetArray("a0") is not None,
              f"{tag}: VTK has void_fraction and a0")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--example", required=True)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for extended in (False, True):
            folder = os.path.join(tmp, "extended" if extended else "plain")
            shutil.copytree(a.example, folder)
            edit_input(os.path.join(folder, "in.mesophyll"), extended)
            run_lammps(os.path.abspath(a.lmp), folder)
            check_run(folder, extended)
    print(f"{len(failures)} failed" if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
