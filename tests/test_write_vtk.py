#!/usr/bin/env python3
"""tools/write_vtk.py: the .vtp files of a synthetic two-frame run load back with
vtkXMLPolyDataReader and hold the values put in (geometry, per-cell and per-vertex fields,
bonds as lines across the periodic edge), the .pvd lists them; a dump without the optional
columns gives files without those fields. Exit 77 (skip) only if a Debian package is missing."""
import contextlib
import io
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viz_helpers as vh  # noqa: E402

vh.require(["numpy", "scipy", "vtk"])
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util import numpy_support as ns  # noqa: E402

import write_vtk  # noqa: E402

LO, HI = (0.0, 0.0), (10.0, 8.0)
N = 10                                   # vertices per ring


def read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    self_check = r.GetErrorCode()
    assert self_check == 0, f"vtkXMLPolyDataReader error {self_check} on {path}"
    return r.GetOutput()


def arrays(data):
    return {data.GetArrayName(i): ns.vtk_to_numpy(data.GetArray(i))
            for i in range(data.GetNumberOfArrays()) if data.GetArray(i) is not None}


def run(args):
    with contextlib.redirect_stdout(io.StringIO()) as text:
        rc = write_vtk.main(args)
    return rc, text.getvalue()


class WriteVTK(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        # cell 1 (radius 1, its vertex 1 leftmost) sits across x = 0; cell 2 (radius 1.5, its
        # vertex 11 rightmost) at the right edge, 0.15 from vertex 1 across the periodic edge;
        # 1 and 11 are bonded. Frame 2: the same with radii 10% larger.
        self.frames, self.bond_frames = [], []
        for k, scale in enumerate((1.0, 1.1)):
            c1 = vh.regular_ring(N, 1.0 * scale, (0.5, 4.0), phase=np.pi)
            c1 = np.mod(c1, [10.0, 8.0])                        # written wrapped
            left = 0.5 - 1.0 * scale
            c2 = vh.regular_ring(N, 1.5 * scale, (left - 0.15 + 10.0 - 1.5 * scale, 4.0))
            adh = np.zeros(N, dtype=int)
            adh[0] = 1
            values1 = {"d_sigma": 0.2, "d_l0": np.linspace(0.5, 0.6, N),
                       "d_theta0": np.linspace(-0.1, 0.3, N), "d_a0": 3.0 + k,
                       "c_adhesion": adh}
            values2 = {"d_sigma": np.full(N, 0.25), "d_l0": np.full(N, 0.9),
                       "d_theta0": np.full(N, 0.6), "d_a0": 7.0 + k, "c_adhesion": adh}
            self.frames.append((100 * (k + 1), LO, HI, [(c1, values1), (c2, values2)]))
            self.bond_frames.append((100 * (k + 1), LO, HI, [(1, 11, 2), (1, 2, 1), (11, 12, 1)]))
        self.cols = ("d_sigma", "d_l0", "d_theta0", "d_a0", "c_adhesion")
        self.dump = os.path.join(self.dir, "cells.dump")
        self.bonds = os.path.join(self.dir, "bonds.dump")
        self.growth = os.path.join(self.dir, "growth.txt")
        vh.write_dump(self.dump, self.frames, self.cols)
        vh.write_bond_dump(self.bonds, self.bond_frames)
        with open(self.growth, "w") as f:
            f.write("# step P phi phi_patch calA z bonds dphi_plus iterations\n"
                    "1 0.001 0.2 0.25 1.07 1 2 0 100\n2 0.001 0.24 0.3 1.07 1 2 0 120\n")

    def tearDown(self):
        self.tmp.cleanup()

    def test_values_load_back(self):
        out = os.path.join(self.dir, "vtk", "run")
        rc, _ = run([self.dump, "--bonds", self.bonds, "--growth", self.growth, "--out", out])
        self.assertEqual(rc, 0)
        series = ET.parse(out + "_cells.pvd").getroot().find("Collection")
        entries = [(d.get("timestep"), d.get("file")) for d in series]
        self.assertEqual(entries, [("1", "run_cells_0000.vtp"), ("2", "run_cells_0001.vtp")])
        for k, (_, _, _, cells) in enumerate(self.frames):
            poly = read(os.path.join(self.dir, "vtk", f"run_cells_{k:04d}.vtp"))
            self.assertEqual(poly.GetNumberOfPoints(), 2 * N)
            self.assertEqual(poly.GetNumberOfPolys(), 2)
            cd, pd = arrays(poly.GetCellData()), arrays(poly.GetPointData())
            fd = poly.GetFieldData()
            scale = 1.1 if k else 1.0
            radii = np.array([1.0, 1.5]) * scale
            area = 0.5 * N * radii ** 2 * np.sin(2 * np.pi / N)
            perim = 2 * N * radii * np.sin(np.pi / N)
            np.testing.assert_array_equal(cd["mol"], [1, 2])
            np.testing.assert_array_equal(cd["n_vertices"], [N, N])
            np.testing.assert_allclose(cd["area"], area, rtol=1e-8)
            np.testing.assert_allclose(cd["perimeter"], perim, rtol=1e-8)
            np.testing.assert_allclose(cd["calA"], N * np.tan(np.pi / N) / np.pi, rtol=1e-8)
            np.testing.assert_array_equal(cd["z"], [1, 1])
            np.testing.assert_allclose(cd["a0"], [3.0 + k, 7.0 + k])
            np.testing.assert_allclose(cd["void_fraction"], [(N - 1) / N] * 2)
            # per vertex, in ring order: ids 1..10, 11..20
            np.testing.assert_array_equal(pd["id"], np.arange(1, 2 * N + 1))
            np.testing.assert_array_equal(pd["next"][:N], np.roll(np.arange(1, N + 1), -1))
            np.testing.assert_allclose(pd["sigma"], [0.2] * N + [0.25] * N)
            np.testing.assert_allclose(pd["l0"][:N], cells[0][1]["d_l0"], rtol=1e-9)
            np.testing.assert_allclose(pd["theta0"][:N], cells[0][1]["d_theta0"], rtol=1e-9)
            np.testing.assert_array_equal(pd["void_facing"], ([0] + [1] * (N - 1)) * 2)
            # the ring is contiguous and its vertex mean inside the box
            pts = ns.vtk_to_numpy(poly.GetPoints().GetData())
            ring = pts[:N, :2]
            self.assertLess(np.abs(np.diff(ring, axis=0)).max(), 1.0)
            self.assertTrue(0 <= ring[:, 0].mean() < 10.0)
            self.assertEqual(fd.GetArray("growth_step").GetValue(0), k + 1)
            self.assertAlmostEqual(fd.GetArray("phi").GetValue(0), (0.2, 0.24)[k])
            np.testing.assert_allclose(ns.vtk_to_numpy(fd.GetArray("box_length")), [10, 8])
            self.assertEqual(fd.GetAbstractArray("sigma_source").GetValue(0), "d_sigma")
            # the adhesive bond: one line, 0.15 long, across the periodic edge
            bonds = read(os.path.join(self.dir, "vtk", f"run_bonds_{k:04d}.vtp"))
            self.assertEqual(bonds.GetNumberOfLines(), 1)
            bd = arrays(bonds.GetCellData())
            np.testing.assert_array_equal(bd["atom1"], [1])
            np.testing.assert_array_equal(bd["atom2"], [11])
            np.testing.assert_array_equal(bd["cell1"], [1])
            np.testing.assert_array_equal(bd["cell2"], [2])
            np.testing.assert_allclose(bd["length"], [0.15], rtol=1e-6)
            np.testing.assert_allclose(bd["r_over_s"], [0.15 / 0.225], rtol=1e-6)
            ends = ns.vtk_to_numpy(bonds.GetPoints().GetData())[:, :2]
            np.testing.assert_allclose(np.hypot(*(ends[1] - ends[0])), 0.15, rtol=1e-6)

    def test_plain_dump(self):
        # the dump of today's in.mesophyll: id mol xu yu c_vertex[3] only
        plain = os.path.join(self.dir, "plain.dump")
        vh.write_dump(plain, self.frames, extra=())
        out = os.path.join(self.dir, "plain")
        rc, _ = run([plain, "--out", out])
        self.assertEqual(rc, 0)
        poly = read(out + "_cells_0001.vtp")
        cd, pd = arrays(poly.GetCellData()), arrays(poly.GetPointData())
        self.assertEqual(set(cd), {"mol", "n_vertices", "area", "perimeter", "calA", "z"})
        self.assertEqual(set(pd), {"id", "next", "sigma"})
        src = poly.GetFieldData().GetAbstractArray("sigma_source").GetValue(0)
        self.assertIn("segment", src)
        self.assertFalse(os.path.exists(out + "_bonds.pvd"))
        # with bonds from the local dump instead of c_adhesion
        rc, _ = run([plain, "--bonds", self.bonds, "--sigma", "0.2", "--out", out])
        pd = arrays(read(out + "_cells_0000.vtp").GetPointData())
        np.testing.assert_array_equal(pd["bonds"], ([1] + [0] * (N - 1)) * 2)
        np.testing.assert_allclose(pd["sigma"], 0.2)


if __name__ == "__main__":
    unittest.main(verbosity=2)
