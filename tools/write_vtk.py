#!/usr/bin/env python3
"""Write a MESOPHYLL development run as VTK PolyData for ParaView: one .vtp per growth step and
a .pvd series.

    write_vtk.py cells.N64.dump [--bonds bonds.N64.dump] [--growth growth.N64.txt]
                 [--out vtk/N64] [--adhesion-type 2] [--sigma S]

Writes <out>_cells_<k>.vtp for every frame k of the dump and <out>_cells.pvd (open this one in
ParaView: the growth step is its time), and with --bonds <out>_bonds_<k>.vtp and
<out>_bonds.pvd. In the cells files every cell is one polygon (its vertices in ring order,
counter-clockwise, the cell's vertex mean inside the box), with
  cell data:  mol (cell ID), n_vertices, area, perimeter, calA = p^2/(4 pi a), z (distinct cells
              it touches: a vertex pair closer than the mean diameter, or an adhesive bond when
              bonds are known), a0 (with d_a0), void_fraction (fraction of void-facing vertices,
              with c_adhesion or --bonds);
  point data: id, next (the next vertex's ID), sigma (d_sigma; else --sigma or the vertices'
              mean segment lengths, named in the field data sigma_source), l0, theta0, a0,
              bonds and void_facing (1 = no adhesive bond) where the dump or --bonds has them;
  field data: timestep, growth_step, box_lo, box_length, sigma_source and the growth table's
              row (P, phi, phi_patch, calA, z, ...) with --growth.
The bonds files hold every adhesive bond as a line (its second end moved to the first one's
periodic image), with cell data atom1, atom2, cell1, cell2, length and, with sigma, r_over_s.
Draw the vertex disks with ParaView's Glyph filter (2D glyph circle, scale by sigma, factor 1).
Needs python3-vtk9 and python3-numpy (Debian).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesophyll_frames as mf  # noqa: E402

mf.require(["numpy", "scipy", "vtk"])
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util import numpy_support  # noqa: E402


def _array(name, values):
    values = np.ascontiguousarray(values)
    if values.dtype.kind in "iub":
        values = values.astype(np.int64)
    else:
        values = values.astype(np.float64)
    arr = numpy_support.numpy_to_vtk(values, deep=True)
    arr.SetName(name)
    return arr


def _cell_array(connectivity, offsets):
    cells = vtk.vtkCellArray()
    cells.SetData(numpy_support.numpy_to_vtkIdTypeArray(np.asarray(offsets, dtype=np.int64),
                                                        deep=True),
                  numpy_support.numpy_to_vtkIdTypeArray(np.asarray(connectivity, dtype=np.int64),
                                                        deep=True))
    return cells


def cells_polydata(frame, sigma, sigma_source, pairs=None, growth_row=None, growth_step=None):
    """vtkPolyData of one frame's cells (see the module's doc for the fields)."""
    order = np.concatenate(frame.rings)
    xy = frame.pos[order]
    points = vtk.vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(np.column_stack([xy, np.zeros(len(xy))]),
                                              deep=True))
    sizes = np.array([len(r) for r in frame.rings])
    offsets = np.concatenate([[0], np.cumsum(sizes)])
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(_cell_array(np.arange(len(order)), offsets))

    polys = frame.polygons()
    area = np.array([mf.polygon_area(p) for p in polys])
    perim = np.array([mf.polygon_perimeter(p) for p in polys])
    cd = poly.GetCellData()
    cd.AddArray(_array("mol", np.array(frame.cells)))
    cd.AddArray(_array("n_vertices", sizes))
    cd.AddArray(_array("area", area))
    cd.AddArray(_array("perimeter", perim))
    cd.AddArray(_array("calA", perim ** 2 / (4 * np.pi * area)))
    cd.AddArray(_array("z", mf.contact_numbers(frame, sigma, pairs)))

    pd = poly.GetPointData()
    pd.AddArray(_array("id", frame.ids[order]))
    pd.AddArray(_array("next", frame.columns[mf.NEXT][order].astype(np.int64)))
    pd.AddArray(_array("sigma", sigma[order]))
    for names, label in ((mf.L0, "l0"), (mf.THETA0, "theta0"), (mf.A0, "a0")):
        col = frame.column(names)
        if col is not None:
            pd.AddArray(_array(label, col[order]))
    a0 = frame.column(mf.A0)
    if a0 is not None:
        cd.AddArray(_array("a0", np.array([a0[r].mean() for r in frame.rings])))
    bonds = frame.column(mf.ADHESION)
    if bonds is None and pairs is not None:
        bonds = mf.vertex_bond_counts(frame, pairs)
    if bonds is not None:
        bonds = np.asarray(bonds).astype(np.int64)
        pd.AddArray(_array("bonds", bonds[order]))
        pd.AddArray(_array("void_facing", (bonds[order] == 0).astype(np.int64)))
        cd.AddArray(_array("void_fraction", np.array([np.mean(bonds[r] == 0)
                                                      for r in frame.rings])))

    fd = poly.GetFieldData()
    fd.AddArray(_array("timestep", np.array([frame.timestep])))
    fd.AddArray(_array("box_lo", frame.lo))
    fd.AddArray(_array("box_length", frame.length))
    if growth_step is not None:
        fd.AddArray(_array("growth_step", np.array([growth_step])))
    src = vtk.vtkStringArray()
    src.SetName("sigma_source")
    src.InsertNextValue(sigma_source)
    fd.AddArray(src)
    for name, value in (growth_row or {}).items():
        if name != "step":
            fd.AddArray(_array(name, np.array([value])))
    return poly


def bonds_polydata(frame, pairs, sigma=None):
    """vtkPolyData of the adhesive bonds (pairs of row indices) as lines."""
    a, b = pairs[:, 0], pairs[:, 1]
    start = frame.pos[a]
    end = start + frame.minimum_image(frame.pos[b] - frame.pos[a])
    xy = np.empty((2 * len(pairs), 2))
    xy[0::2], xy[1::2] = start, end
    points = vtk.vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(np.column_stack([xy, np.zeros(len(xy))]),
                                              deep=True))
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(_cell_array(np.arange(len(xy)), 2 * np.arange(len(pairs) + 1)))
    cd = poly.GetCellData()
    length = np.hypot(*(end - start).T)
    cd.AddArray(_array("atom1", frame.ids[a]))
    cd.AddArray(_array("atom2", frame.ids[b]))
    cd.AddArray(_array("cell1", frame.mol[a]))
    cd.AddArray(_array("cell2", frame.mol[b]))
    cd.AddArray(_array("length", length))
    if sigma is not None:
        cd.AddArray(_array("r_over_s", length / (0.5 * (sigma[a] + sigma[b]))))
    fd = poly.GetFieldData()
    fd.AddArray(_array("timestep", np.array([frame.timestep])))
    return poly


def write_polydata(path, poly):
    w = vtk.vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(poly)
    w.SetDataModeToBinary()
    if not w.Write():
        raise OSError(f"could not write {path}")


def write_pvd(path, entries):
    """entries: (time, file name relative to the .pvd)."""
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n'
                '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
                '  <Collection>\n')
        for time, name in entries:
            f.write(f'    <DataSet timestep="{time}" group="" part="0" file="{name}"/>\n')
        f.write("  </Collection>\n</VTKFile>\n")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="\n".join(__doc__.splitlines()[2:]))
    p.add_argument("dump", help="per-vertex dump of a run (cells.N*.dump)")
    p.add_argument("--bonds", help="local dump of the bonds (write_dump ... local)")
    p.add_argument("--growth", help="growth table of the run (its rows go to the field data)")
    p.add_argument("--out", default=None, help="prefix of the files (default: vtk/<dump name>)")
    p.add_argument("--adhesion-type", type=int, default=2, help="bond type of adhesion (2)")
    p.add_argument("--sigma", type=float, default=None,
                   help="vertex diameter where the dump has no d_sigma column")
    a = p.parse_args(argv)

    out = a.out or os.path.join("vtk", os.path.splitext(os.path.basename(a.dump))[0])
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    base = os.path.basename(out)
    bond_frames = {}
    if a.bonds:
        bond_frames = {ts: b for ts, b in mf.read_bond_frames(a.bonds)}
    growth = mf.read_growth(a.growth) if a.growth else None
    cells_series, bonds_series = [], []
    missing_bonds = 0
    k = -1
    for k, frame in enumerate(mf.read_frames(a.dump)):
        sigma, source = frame.sigma(a.sigma)
        pairs = None
        if a.bonds:
            if frame.timestep in bond_frames:
                pairs = mf.adhesive_pairs(frame, bond_frames[frame.timestep], a.adhesion_type)
            else:
                missing_bonds += 1
        row, step = None, k + 1
        if growth is not None and k < len(growth["step"]):
            row = {name: float(col[k]) for name, col in growth.items()}
            step = int(row["step"])
        name = f"{base}_cells_{k:04d}.vtp"
        write_polydata(os.path.join(os.path.dirname(out), name),
                       cells_polydata(frame, sigma, source, pairs, row, step))
        cells_series.append((step, name))
        if pairs is not None:
            name = f"{base}_bonds_{k:04d}.vtp"
            write_polydata(os.path.join(os.path.dirname(out), name),
                           bonds_polydata(frame, pairs, sigma))
            bonds_series.append((step, name))
    if k < 0:
        p.error(f"{a.dump}: no complete frame")
    write_pvd(f"{out}_cells.pvd", cells_series)
    print(f"wrote {len(cells_series)} frames: {out}_cells.pvd ({out}_cells_*.vtp)")
    if bonds_series:
        write_pvd(f"{out}_bonds.pvd", bonds_series)
        print(f"wrote {len(bonds_series)} frames: {out}_bonds.pvd ({out}_bonds_*.vtp)")
    if missing_bonds:
        print(f"note: {missing_bonds} frames have no frame of the same timestep in {a.bonds}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
