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

3d cells (deformable polyhedra): with --faces DATA the dump is a dump of the vertices of 3d cells
(columns id mol xu yu zu, unwrapped) and DATA the data file they were read from (its Angles are
the faces, counter-clockwise from outside):

    write_vtk.py cells3d.dump --faces cells3d.data [--out vtk/cells3d]
                 [--slice-png slice.png] [--slice-offset 0.5] [--render-png cells.png]

writes <out>_cells3d_<k>.vtp per frame and <out>_cells3d.pvd: every face a triangle, each cell
moved by whole box lengths so that its vertex mean is inside the box, with
  cell data:  mol, and of the triangle's cell volume, surface and shape = S^3/(36 pi V^2);
  point data: id, mol;
  field data: timestep, box_lo, box_length.
--slice-png draws the last frame's cross-sections by the plane z = zlo + offset Lz (VTK's own
cutter, on every periodic image of the plane), one colour per cell, over the box.
--render-png draws the last frame's cells in 3d (their faces, one colour per cell, each cell
whole with its vertex mean in the box, the box's edges) with matplotlib: VTK's own rendering
needs an X server, which a headless machine lacks, while the .vtp files render in ParaView.
Needs python3-vtk9 and python3-numpy (Debian); python3-matplotlib for --slice-png and
--render-png.
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


def read_faces(data_path):
    """The faces of 3d cells from a data file's Angles section: (m, 3) atom IDs."""
    import lammps_data
    data = lammps_data.DataFile(data_path)
    if "Angles" not in data.sections:
        raise SystemExit(f"{data_path}: no Angles section (the faces of 3d cells)")
    return np.array([[int(w) for w in words[2:5]] for words in data.sections["Angles"]],
                    dtype=np.int64)


class Frame3d:
    """One dump frame of 3d cells: box lo and lengths, vertex IDs, cells and unwrapped positions,
    each cell moved by whole box lengths so that its vertex mean is inside the box."""

    def __init__(self, timestep, bounds, columns, rows):
        self.timestep = timestep
        self.lo = np.array([b[0] for b in bounds])
        self.length = np.array([b[1] - b[0] for b in bounds])
        for need in ("id", "mol", "xu", "yu", "zu"):
            if need not in columns:
                raise ValueError(f"dump frame at step {timestep} has no column '{need}' "
                                 f"(columns: {' '.join(columns)}); dump id mol xu yu zu")
        data = np.array([r.split() for r in rows], dtype=float).reshape(len(rows), len(columns))
        col = {name: data[:, j] for j, name in enumerate(columns)}
        self.ids = col["id"].astype(np.int64)
        self.mol = col["mol"].astype(np.int64)
        self.pos = np.column_stack([col["xu"], col["yu"], col["zu"]])
        for m in np.unique(self.mol):
            rows_of_cell = self.mol == m
            centre = self.pos[rows_of_cell].mean(axis=0)
            self.pos[rows_of_cell] -= np.floor((centre - self.lo) / self.length) * self.length
        self.row_of = {int(t): r for r, t in enumerate(self.ids)}

    def face_rows(self, faces):
        try:
            return np.vectorize(lambda t: self.row_of[int(t)])(faces)
        except KeyError as missing:
            raise ValueError(f"step {self.timestep}: face vertex {missing} is not in the dump")


def read_frames3d(path):
    for block in mf._dump_blocks(path):
        yield Frame3d(*block)


def cell_measures(frame, face_rows):
    """Per face: its cell's volume (divergence theorem), surface area and S^3/(36 pi V^2)."""
    a, b, c = (frame.pos[face_rows[:, k]] for k in range(3))
    face_volume = np.einsum("ij,ij->i", a, np.cross(b, c)) / 6.0
    face_area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    cell = frame.mol[face_rows[:, 1]]
    volume, surface = {}, {}
    for m in np.unique(cell):
        volume[m] = face_volume[cell == m].sum()
        surface[m] = face_area[cell == m].sum()
    v = np.array([volume[m] for m in cell])
    s = np.array([surface[m] for m in cell])
    return cell, v, s, s ** 3 / (36.0 * np.pi * v ** 2)


def cells3d_polydata(frame, faces):
    """vtkPolyData of one frame's 3d cells, every face a triangle (see the module's doc)."""
    rows = frame.face_rows(faces)
    points = vtk.vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(frame.pos), deep=True))
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(_cell_array(rows.ravel(), np.arange(0, 3 * len(rows) + 1, 3)))
    cell, volume, surface, shape = cell_measures(frame, rows)
    cd = poly.GetCellData()
    cd.AddArray(_array("mol", cell))
    cd.AddArray(_array("volume", volume))
    cd.AddArray(_array("surface", surface))
    cd.AddArray(_array("shape", shape))
    pd = poly.GetPointData()
    pd.AddArray(_array("id", frame.ids))
    pd.AddArray(_array("mol", frame.mol))
    fd = poly.GetFieldData()
    fd.AddArray(_array("timestep", np.array([frame.timestep])))
    fd.AddArray(_array("box_lo", frame.lo))
    fd.AddArray(_array("box_length", frame.length))
    return poly


def slice_outlines(frame, faces, offset):
    """Cross-sections of every cell by the plane z = zlo + offset Lz and its periodic images:
    a list of (cell, closed (n, 2) outline), cut and chained by VTK (vtkCutter, vtkStripper)."""
    rows = frame.face_rows(faces)
    cell_of_face = frame.mol[rows[:, 1]]
    height = frame.lo[2] + offset * frame.length[2]
    outlines = []
    for m in np.unique(cell_of_face):
        one = vtk.vtkPolyData()
        points = vtk.vtkPoints()
        points.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(frame.pos), deep=True))
        one.SetPoints(points)
        mine = rows[cell_of_face == m]
        one.SetPolys(_cell_array(mine.ravel(), np.arange(0, 3 * len(mine) + 1, 3)))
        zmin, zmax = frame.pos[mine.ravel(), 2].min(), frame.pos[mine.ravel(), 2].max()
        for image in range(int(np.floor((zmin - height) / frame.length[2])),
                           int(np.floor((zmax - height) / frame.length[2])) + 1):
            plane = vtk.vtkPlane()
            plane.SetOrigin(0.0, 0.0, height + image * frame.length[2])
            plane.SetNormal(0.0, 0.0, 1.0)
            cutter = vtk.vtkCutter()
            cutter.SetCutFunction(plane)
            cutter.SetInputData(one)
            stripper = vtk.vtkStripper()
            stripper.SetInputConnection(cutter.GetOutputPort())
            stripper.JoinContiguousSegmentsOn()
            stripper.Update()
            out = stripper.GetOutput()
            if out.GetNumberOfPoints() == 0:
                continue
            xyz = numpy_support.vtk_to_numpy(out.GetPoints().GetData())
            lines = out.GetLines()
            lines.InitTraversal()
            ids = vtk.vtkIdList()
            while lines.GetNextCell(ids):
                loop = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
                if len(loop) > 1 and loop[0] == loop[-1]:
                    loop = loop[:-1]
                outlines.append((int(m), xyz[loop, :2].copy()))
    return outlines


def slice_png(path, frame, outlines, offset):
    """The outlines over the box, one colour per cell, with their periodic images."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Polygon
    from matplotlib.path import Path
    fig, ax = plt.subplots(figsize=(6, 6 * frame.length[1] / frame.length[0]))
    colours = plt.get_cmap("tab20")

    def is_hole(k):
        # VTK's outlines carry no orientation: an outline inside an odd number of the same
        # cell's other outlines is a hole (a cup cut through its well), drawn in white
        cell, xy = outlines[k]
        inside = sum(Path(other).contains_point(xy[0]) for m, (c, other) in enumerate(outlines)
                     if m != k and c == cell)
        return inside % 2 == 1

    # outer outlines first, so that the holes are drawn over them
    order = sorted(range(len(outlines)), key=is_hole)
    for k in order:
        cell, xy = outlines[k]
        face = "white" if is_hole(k) else colours(cell % 20)
        for i in (-1, 0, 1):
            for j in (-1, 0, 1):
                shift = np.array([i * frame.length[0], j * frame.length[1]])
                ax.add_patch(Polygon(xy + shift, closed=True, facecolor=face,
                                     edgecolor="black", linewidth=0.6, alpha=0.85))
    ax.set_xlim(frame.lo[0], frame.lo[0] + frame.length[0])
    ax.set_ylim(frame.lo[1], frame.lo[1] + frame.length[1])
    ax.set_aspect("equal")
    ax.set_title(f"step {frame.timestep}: cross-sections at z = zlo + {offset:g} Lz "
                 f"({len(outlines)} outlines)")
    fig.savefig(path, dpi=150, bbox_inches="tight")
    plt.close(fig)


def render_png(path, frame, faces):
    """The cells' faces in 3d, one colour per cell, from a fixed view, with the box's edges."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    rows = frame.face_rows(faces)
    cell = frame.mol[rows[:, 1]]
    colours = plt.get_cmap("tab20")
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    faces3d = Poly3DCollection(frame.pos[rows], facecolors=[colours(m % 20) for m in cell],
                               edgecolors=(0, 0, 0, 0.25), linewidths=0.2)
    ax.add_collection3d(faces3d)
    lo, hi = frame.lo, frame.lo + frame.length
    for d in range(3):  # the twelve edges of the box
        for u in (lo[(d + 1) % 3], hi[(d + 1) % 3]):
            for v in (lo[(d + 2) % 3], hi[(d + 2) % 3]):
                ends = np.zeros((2, 3))
                ends[:, d] = (lo[d], hi[d])
                ends[:, (d + 1) % 3] = u
                ends[:, (d + 2) % 3] = v
                ax.plot(*ends.T, color="black", linewidth=0.8)
    reach = frame.pos.min(axis=0), frame.pos.max(axis=0)
    for d, axis in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
        axis(min(lo[d], reach[0][d]), max(hi[d], reach[1][d]))
    ax.set_box_aspect(tuple(max(hi[d], reach[1][d]) - min(lo[d], reach[0][d]) for d in range(3)))
    ax.view_init(elev=25, azim=-60)
    ax.set_axis_off()
    ax.set_title(f"step {frame.timestep}: {len(np.unique(frame.mol))} cells")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)


def main3d(a, p):
    faces = read_faces(a.faces)
    out = a.out or os.path.join("vtk", os.path.splitext(os.path.basename(a.dump))[0])
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    base = os.path.basename(out)
    series, frame = [], None
    for k, frame in enumerate(read_frames3d(a.dump)):
        name = f"{base}_cells3d_{k:04d}.vtp"
        write_polydata(os.path.join(os.path.dirname(out), name), cells3d_polydata(frame, faces))
        series.append((frame.timestep, name))
    if frame is None:
        p.error(f"{a.dump}: no complete frame")
    write_pvd(f"{out}_cells3d.pvd", series)
    print(f"wrote {len(series)} frames: {out}_cells3d.pvd ({out}_cells3d_*.vtp)")
    if a.slice_png:
        outlines = slice_outlines(frame, faces, a.slice_offset)
        slice_png(a.slice_png, frame, outlines, a.slice_offset)
        print(f"wrote {a.slice_png}: {len(outlines)} cross-sections of step {frame.timestep}")
    if a.render_png:
        render_png(a.render_png, frame, faces)
        print(f"wrote {a.render_png}: the cells of step {frame.timestep} in 3d")
    return 0


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
    p.add_argument("--faces", default=None,
                   help="3d cells: the data file whose Angles are the faces (dump: id mol xu yu zu)")
    p.add_argument("--slice-png", default=None,
                   help="3d cells: PNG of the last frame's cross-sections by a plane z = const")
    p.add_argument("--render-png", default=None,
                   help="3d cells: PNG of the last frame's cells drawn in 3d (matplotlib)")
    p.add_argument("--slice-offset", type=float, default=0.5,
                   help="3d cells: height of that plane above zlo, in box heights (default 0.5)")
    a = p.parse_args(argv)
    if a.faces:
        if not 0.0 <= a.slice_offset < 1.0:
            p.error(f"--slice-offset must be in [0, 1), got {a.slice_offset}")
        return main3d(a, p)

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
