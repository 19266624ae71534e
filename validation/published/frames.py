"""Tissue states in the two formats: the package's LAMMPS data files and the published code's.

A Tissue is what both formats share: a square periodic box, and per cell its vertices in ring
order (counter-clockwise, as both codes need for their signed turning angle) with unwrapped
positions, radius r, preferred segment length l0 (of the segment to the next vertex), preferred
turning angle theta0 and the cell's preferred area a0; plus the adhesive bonds as pairs of global
vertex indices (cells one after another, each in ring order: the published code's numbering).

The package's d_sigma is a vertex diameter (contact at r < (sigma_i + sigma_j)/2, see
doc/pair_dpoly_contact.rst), the published code's r a radius (contact at r < r_i + r_j):
r = sigma/2. Both codes take theta = atan2(d1 x d2, d1 . d2) with d1 = x_i - x_prev,
d2 = x_next - x_i (doc/angle_dpoly_bending.rst; meso2D::mesoShapeForces), so theta0 carries
over unchanged when the ring order does.
"""
import collections
import math

import numpy as np

Cell = collections.namedtuple("Cell", "x y r l0 theta0 a0")
Tissue = collections.namedtuple("Tissue", "L cells bonds")
SECTIONS = {"Masses", "Atoms", "Velocities", "Bonds", "Angles", "Vertices"}


def _sections(path):
    """Header lines and {section name: rows of numbers} of a LAMMPS data file."""
    header, sections, name = [], {}, None
    with open(path) as f:
        next(f)    # the title line
        for line in f:
            words = line.split("#")[0].split()
            if not words:
                continue
            if words[0] in SECTIONS:
                name = words[0]
                sections[name] = []
            elif name is None:
                header.append(words)
            else:
                sections[name].append([float(w) for w in words])
    return header, sections


def read_data(path):
    """Tissue of a package data file: rings from the angles (prev, vertex, next), cells in
    molecule order, each ring from its smallest atom ID; box shifted to start at 0."""
    header, s = _sections(path)
    lo = {w[-1][0]: (float(w[0]), float(w[1])) for w in header if w[-1] in ("xhi", "yhi")}
    (xlo, xhi), (ylo, yhi) = lo["x"], lo["y"]
    assert abs((xhi - xlo) - (yhi - ylo)) < 1e-12, "the published code needs a square box"
    L = xhi - xlo
    atoms = {int(a[0]): a for a in s["Atoms"]}
    vert = {int(v[0]): v for v in s["Vertices"]}
    nxt = {int(a[2]): int(a[3]) for a in s["Angles"]}
    by_cell = collections.defaultdict(list)
    for i, a in atoms.items():
        by_cell[int(a[1])].append(i)
    order, cells = [], []
    for mol in sorted(by_cell):
        ring = [min(by_cell[mol])]
        while nxt[ring[-1]] != ring[0]:
            ring.append(nxt[ring[-1]])
        assert sorted(ring) == sorted(by_cell[mol]), f"cell {mol} is not one ring"
        order += ring
        a = np.array([atoms[i] for i in ring])
        v = np.array([vert[i] for i in ring])
        x = a[:, 3] + a[:, 6] * L - xlo    # unwrapped with the image flags
        y = a[:, 4] + a[:, 7] * L - ylo
        cells.append(Cell(x, y, 0.5 * v[:, 1], v[:, 2], v[:, 3], v[0, 4]))
    index = {i: g for g, i in enumerate(order)}
    bonds = sorted(tuple(sorted((index[int(b[2])], index[int(b[3])])))
                   for b in s["Bonds"] if int(b[1]) == 2)
    return Tissue(L, cells, bonds)


def overlaps(tissue):
    """Pairs of vertices of different cells closer than r_i + r_j (nearest image): the bonds
    the published code makes from a state (meso2D::initializeMesophyllBondNetwork)."""
    x = np.concatenate([c.x for c in tissue.cells])
    y = np.concatenate([c.y for c in tissue.cells])
    r = np.concatenate([c.r for c in tissue.cells])
    cell = np.concatenate([np.full(len(c.x), k) for k, c in enumerate(tissue.cells)])
    pairs = []
    for g in range(len(x)):
        dx = x[g + 1:] - x[g]
        dy = y[g + 1:] - y[g]
        dx -= tissue.L * np.round(dx / tissue.L)
        dy -= tissue.L * np.round(dy / tissue.L)
        hit = (np.hypot(dx, dy) < r[g] + r[g + 1:]) & (cell[g + 1:] != cell[g])
        pairs += [(g, g + 1 + h) for h in np.nonzero(hit)[0]]
    return pairs


def _area_perimeter(c):
    xn, yn = np.roll(c.x, -1), np.roll(c.y, -1)
    return 0.5 * np.sum(c.x * yn - xn * c.y), np.sum(np.hypot(xn - c.x, yn - c.y))


def write_published(tissue, path, kb):
    """The published code's input (read by its constructor meso2D(string&, int)): NEWFR, NUMCL,
    PACKF, BOXSZ, STRSS, then per cell CINFO nv zc a0 area perimeter and per vertex
    VINFO cell vertex x y r l0 theta0 kb zv. Only nv, a0, x, y, r, l0, theta0, kb are read; the
    code makes its own bonds from overlaps."""
    z = collections.Counter(g for b in tissue.bonds for g in b)
    area = sum(_area_perimeter(c)[0] for c in tissue.cells)
    lines = ["NEWFR", f"NUMCL {len(tissue.cells)}", f"PACKF {area / tissue.L ** 2:.16g}",
             f"BOXSZ {tissue.L:.16g} {tissue.L:.16g}", "STRSS 0 0 0"]
    g = 0
    for k, c in enumerate(tissue.cells):
        a, p = _area_perimeter(c)
        zc = sum(z[h] for h in range(g, g + len(c.x)))
        lines.append(f"CINFO {len(c.x)} {zc} {c.a0:.16g} {a:.16g} {p:.16g}")
        for v in range(len(c.x)):
            lines.append(f"VINFO {k} {v} {c.x[v]:.16g} {c.y[v]:.16g} {c.r[v]:.16g} "
                         f"{c.l0[v]:.16g} {c.theta0[v]:.16g} {kb:.16g} {z[g]}")
            g += 1
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def read_frames(path):
    """Frames the published code prints (meso2D::printMesoNetworkCTCS2D): yields Tissue per
    NEWFR ... ENDFR block. Bonds come as indices NVTOT*gi + gj - (gi+1)(gi+2)/2 (gi < gj) of its
    pair list; positions of a cell are unwrapped from its first vertex."""
    block = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "NEWFR":
                block = []
            elif words[0] == "ENDFR":
                yield _frame(block)
            else:
                block.append(words)


def _frame(block):
    head = {w[0]: w[1:] for w in block if w[0] not in ("CINFO", "VINFO")}
    L = float(head["BOXSZ"][0])
    assert abs(L - float(head["BOXSZ"][1])) < 1e-9 * L
    cells, rows, a0 = [], [], None

    def close():
        if rows:
            v = np.array(rows)
            cells.append(Cell(v[:, 0], v[:, 1], v[:, 2], v[:, 3], v[:, 4], a0))

    for w in block:
        if w[0] == "CINFO":
            close()
            rows, a0 = [], float(w[3])
        elif w[0] == "VINFO":
            rows.append([float(u) for u in w[3:8]])
    close()
    n = sum(len(c.x) for c in cells)
    gi = np.arange(n)
    offset = n * gi - (gi + 1) * (gi + 2) // 2
    keys = np.array([int(k) for k in head.get("CTCTS", [])], dtype=np.int64)
    first = np.searchsorted(offset + gi + 1, keys, side="right") - 1
    bonds = list(zip(first.tolist(), (keys - offset[first]).tolist()))
    return Tissue(L, cells, bonds)


def write_data(tissue, path, title="from the published code's frame"):
    """A package data file of a Tissue (atoms 1..n in the published numbering, cells as
    molecules 1..N, box [0, L)): ring bonds type 1 from each vertex to the next, adhesive bonds
    type 2, one angle (prev, vertex, next) per vertex, and the section of fix property/atom
    d_sigma d_l0 d_theta0 d_a0, with sigma = 2 r. Each ring is whole through its image flags."""
    L = tissue.L
    atoms, ring, angles, verts = [], [], [], []
    g = 0
    for k, c in enumerate(tissue.cells):
        n = len(c.x)
        sx, sy = math.floor(c.x[0] / L), math.floor(c.y[0] / L)
        for v in range(n):
            ux, uy = c.x[v] - sx * L, c.y[v] - sy * L
            ix, iy = math.floor(ux / L), math.floor(uy / L)
            atoms.append(f"{g + v + 1} {k + 1} 1 {ux - ix * L:.16g} {uy - iy * L:.16g} 0 "
                         f"{ix} {iy} 0")
            ring.append((g + v, g + (v + 1) % n))
            angles.append((g + (v - 1) % n, g + v, g + (v + 1) % n))
            verts.append(f"{g + v + 1} {2 * c.r[v]:.16g} {c.l0[v]:.16g} {c.theta0[v]:.16g} "
                         f"{c.a0:.16g}")
        g += n
    bonds = [(1, a, b) for a, b in ring] + [(2, a, b) for a, b in tissue.bonds]
    text = [title, "", f"{g} atoms", "1 atom types", f"{len(bonds)} bonds", "2 bond types",
            f"{g} angles", "1 angle types", "", f"0 {L:.16g} xlo xhi", f"0 {L:.16g} ylo yhi",
            "-0.5 0.5 zlo zhi", "", "Masses", "", "1 1", "", "Atoms # molecular", ""] + atoms
    text += ["", "Bonds", ""] + [f"{k + 1} {t} {a + 1} {b + 1}" for k, (t, a, b) in
                                 enumerate(bonds)]
    text += ["", "Angles", ""] + [f"{k + 1} 1 {a + 1} {b + 1} {c + 1}" for k, (a, b, c) in
                                  enumerate(angles)]
    text += ["", "Vertices # d_sigma d_l0 d_theta0 d_a0", ""] + verts
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")


def turning_angles(c):
    """Signed turning angle at each vertex, as both codes define it."""
    x, y = c.x, c.y
    d1x, d1y = x - np.roll(x, 1), y - np.roll(y, 1)
    d2x, d2y = np.roll(x, -1) - x, np.roll(y, -1) - y
    return np.arctan2(d1x * d2y - d1y * d2x, d1x * d2x + d1y * d2y)
