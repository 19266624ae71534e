#!/usr/bin/env python3
"""tools/write_vtk.py --faces (3d cells): the .vtp files of a two-frame dump of hand-made cubes
(tests/make_test_data_slices.py) load back with vtkXMLPolyDataReader with the right counts,
positions and per-cell volume, surface and S^3/(36 pi V^2); a cube across every periodic
boundary is drawn whole inside the box; the slice PNG is written and its outlines (VTK's cutter)
are the cubes' 2 x 2 squares, at a periodic image of the plane too; the 3d rendering
(--render-png) shows both cubes in their colours. Exit 77 (skip) only if a Debian package is
missing."""
import contextlib
import io
import math
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viz_helpers as vh  # noqa: E402

vh.require(["numpy", "vtk", "matplotlib"])
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util import numpy_support as ns  # noqa: E402

import write_vtk  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
BOX = 10.0


def read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    assert r.GetErrorCode() == 0, f"vtkXMLPolyDataReader error on {path}"
    return r.GetOutput()


def arrays(data):
    return {data.GetArrayName(i): ns.vtk_to_numpy(data.GetArray(i))
            for i in range(data.GetNumberOfArrays())}


def atoms_of(data_path):
    """id, mol and unwrapped position of every atom of a data file"""
    import lammps_data
    rows = lammps_data.DataFile(data_path).sections["Atoms"]
    out = []
    for w in rows:
        x = [float(w[3 + d]) + BOX * int(w[6 + d]) for d in range(3)]
        out.append((int(w[0]), int(w[1]), *x))
    return out


def write_dump(path, frames):
    """frames: (timestep, atoms as (id, mol, xu, yu, zu)); rows reversed, as LAMMPS's are unsorted"""
    with open(path, "w") as f:
        for step, atoms in frames:
            f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{len(atoms)}\n"
                    f"ITEM: BOX BOUNDS pp pp pp\n0 {BOX}\n0 {BOX}\n0 {BOX}\n"
                    "ITEM: ATOMS id mol xu yu zu\n")
            for a in reversed(atoms):
                f.write(" ".join(repr(v) for v in a) + "\n")


class WriteVTK3d(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        subprocess.run([sys.executable, os.path.join(HERE, "make_test_data_slices.py"),
                        os.path.join(os.path.dirname(HERE), "tools", "make_cells3d.py"),
                        self.dir], check=True, capture_output=True)
        self.data = os.path.join(self.dir, "two_cubes.data")
        atoms = atoms_of(self.data)
        # frame 2: everything moved by (5, 5, 5) + one box in x: cube 2 straddles every
        # boundary and its unwrapped positions lie a box away
        moved = [(t, m, x + 5.0 + BOX, y + 5.0, z + 5.0) for t, m, x, y, z in atoms]
        self.frames = [(0, atoms), (100, moved)]
        self.dump = os.path.join(self.dir, "cells3d.dump")
        write_dump(self.dump, self.frames)

    def tearDown(self):
        self.tmp.cleanup()

    def test_cells_load_back(self):
        out = os.path.join(self.dir, "vtk", "run")
        png = os.path.join(self.dir, "slice.png")
        with contextlib.redirect_stdout(io.StringIO()):
            rc = write_vtk.main([self.dump, "--faces", self.data, "--out", out,
                                 "--slice-png", png])
        self.assertEqual(rc, 0)
        series = ET.parse(out + "_cells3d.pvd").getroot().find("Collection")
        self.assertEqual([(d.get("timestep"), d.get("file")) for d in series],
                         [("0", "run_cells3d_0000.vtp"), ("100", "run_cells3d_0001.vtp")])
        for k, (step, atoms) in enumerate(self.frames):
            poly = read(os.path.join(self.dir, "vtk", f"run_cells3d_{k:04d}.vtp"))
            self.assertEqual(poly.GetNumberOfPoints(), 16)
            self.assertEqual(poly.GetNumberOfPolys(), 24)
            cd, pd = arrays(poly.GetCellData()), arrays(poly.GetPointData())
            self.assertEqual(sorted(np.unique(cd["mol"]).tolist()), [1, 2])
            np.testing.assert_allclose(cd["volume"], 8.0, rtol=1e-13)
            np.testing.assert_allclose(cd["surface"], 24.0, rtol=1e-13)
            np.testing.assert_allclose(cd["shape"], 6.0 / math.pi, rtol=1e-13)
            self.assertEqual(int(ns.vtk_to_numpy(poly.GetFieldData().GetArray("timestep"))[0]),
                             step)
            xyz = ns.vtk_to_numpy(poly.GetPoints().GetData())
            by_id = {int(t): xyz[r] for r, t in enumerate(pd["id"])}
            for t, m, *x in atoms:
                # each cell whole, moved by whole boxes so that its centre is inside the box
                shift = (by_id[t] - np.array(x)) / BOX
                np.testing.assert_allclose(shift, np.round(shift), atol=1e-12)
            for m in (1, 2):
                centre = np.mean([by_id[t] for t, mm, *_ in atoms if mm == m], axis=0)
                self.assertTrue(np.all((centre >= 0.0) & (centre < BOX)), centre)
        self.assertGreater(os.path.getsize(png), 1000)

    def test_slice_outlines_are_the_squares(self):
        faces = write_vtk.read_faces(self.data)
        self.assertEqual(faces.shape, (24, 3))
        for frame in write_vtk.read_frames3d(self.dump):
            # the plane through the cubes' middles (z = 5 in frame 1, z = 10 = 0 in frame 2)
            offset = 0.5 if frame.timestep == 0 else 0.0
            outlines = write_vtk.slice_outlines(frame, faces, offset)
            self.assertEqual(sorted(m for m, _ in outlines), [1, 2])
            for _, xy in outlines:
                x, y = xy[:, 0], xy[:, 1]
                area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
                perimeter = np.sum(np.hypot(np.diff(x, append=x[0]), np.diff(y, append=y[0])))
                self.assertAlmostEqual(area, 4.0, places=12)
                self.assertAlmostEqual(perimeter, 8.0, places=12)
            # frame 2's cubes, drawn at z in [-1, 1], meet the plane z = 9.5 at its image -0.5
            below = write_vtk.slice_outlines(frame, faces, 0.95)
            self.assertEqual(len(below), 0 if frame.timestep == 0 else 2)

    def test_render_shows_every_cell(self):
        import matplotlib.image
        import matplotlib.pyplot as plt
        png = os.path.join(self.dir, "cells.png")
        with contextlib.redirect_stdout(io.StringIO()):
            rc = write_vtk.main([self.dump, "--faces", self.data, "--out",
                                 os.path.join(self.dir, "vtk", "run"), "--render-png", png])
        self.assertEqual(rc, 0)
        pixels = matplotlib.image.imread(png)[:, :, :3].reshape(-1, 3)
        for mol in (1, 2):  # one colour per cell (tab20), unshaded faces
            colour = np.array(plt.get_cmap("tab20")(mol % 20)[:3])
            seen = np.sum(np.all(np.abs(pixels - colour) < 0.02, axis=1))
            self.assertGreater(seen, 500, f"cube {mol} is not drawn in its colour")

    def test_missing_columns_are_named(self):
        bad = os.path.join(self.dir, "bad.dump")
        with open(self.dump) as f, open(bad, "w") as g:
            g.write(f.read().replace("id mol xu yu zu", "id mol x y z"))
        with self.assertRaisesRegex(ValueError, "no column 'xu'"):
            list(write_vtk.read_frames3d(bad))


if __name__ == "__main__":
    unittest.main()
