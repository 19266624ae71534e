"""Reading what a MESOPHYLL development run writes, for the drawing and measuring tools.

Shared by tools/plot_mesophyll.py, image_metrics.py, write_vtk.py and make_movie.py:

* read_growth(path): the growth table growth.N*.txt as {column name: array};
* read_frames(path): the frames of a per-vertex dump such as cells.N*.dump (write_dump ... custom
  id mol xu yu c_vertex[3], optionally d_sigma d_l0 d_theta0 d_a0 c_adhesion); every frame is a
  Frame with its box, its columns and its cells as rings;
* read_bond_frames(path): the frames of a local dump of the bonds (write_dump ... local index
  c_bonds[1] c_bonds[2] c_bonds[3], compute bonds all property/local batom1 batom2 btype);
* cell geometry (area, perimeter, shape parameter) and the contacts between cells.

Importing this module needs only the standard library and numpy; require() re-runs a tool with
Debian's /usr/bin/python3 when the interpreter that started it lacks Debian's packages (a python3
earlier on PATH, e.g. a pyenv one, does not see python3-skimage or python3-vtk9).
"""
import importlib
import os
import sys

DEBIAN_PYTHON = "/usr/bin/python3"

# Debian package of each module the tools import
DEBIAN_PACKAGES = {"numpy": "python3-numpy", "scipy": "python3-scipy",
                   "matplotlib": "python3-matplotlib", "skimage": "python3-skimage",
                   "vtk": "python3-vtk9", "PIL": "python3-pil"}


def missing_modules(modules):
    missing = []
    for name in modules:
        try:
            importlib.import_module(name)
        except ImportError:
            missing.append(name)
    return missing


def require(modules, exit_code=None):
    """Make sure the modules import; otherwise re-run this script with Debian's python3 if that
    is another interpreter (it sees the python3-* packages), else say which Debian packages are
    missing and exit with exit_code (default $MESOPHYLL_MISSING_EXIT or 2; the tests set 77,
    ctest's skip code)."""
    if exit_code is None:
        exit_code = int(os.environ.get("MESOPHYLL_MISSING_EXIT", "2"))
    missing = missing_modules(modules)
    if not missing:
        return
    here = os.path.realpath(sys.executable or "")
    if (os.path.exists(DEBIAN_PYTHON) and here != os.path.realpath(DEBIAN_PYTHON)
            and not os.environ.get("MESOPHYLL_NO_REEXEC")):
        os.environ["MESOPHYLL_NO_REEXEC"] = "1"    # once: no loop if Debian's lacks them too
        os.execv(DEBIAN_PYTHON, [DEBIAN_PYTHON] + sys.argv)
    packages = " ".join(DEBIAN_PACKAGES.get(m, m) for m in missing)
    print(f"{os.path.basename(sys.argv[0])}: missing Python modules {', '.join(missing)} "
          f"(Debian: apt-get install {packages})", file=sys.stderr)
    sys.exit(exit_code)


require(["numpy"])
import numpy as np  # noqa: E402

NEXT = "c_vertex[3]"                  # the next vertex along the ring (compute dpoly/vertex)
SIGMA = ("d_sigma", "sigma")          # vertex diameter
L0 = ("d_l0", "l0")                   # preferred length of the segment to the next vertex
THETA0 = ("d_theta0", "theta0")       # preferred turning angle
A0 = ("d_a0", "a0")                   # the cell's preferred area (the same on all its vertices)
ADHESION = ("c_adhesion", "adhesion")  # adhesive bonds of the vertex (0 = void-facing)


def read_growth(path):
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    data = np.loadtxt(path, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def _dump_blocks(path):
    """Yield (timestep, box bounds [[lo, hi] x 3], column names, rows as a list of strings)."""
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if not lines[k].startswith("ITEM: TIMESTEP"):
            k += 1
            continue
        timestep = int(lines[k + 1])
        count = int(lines[k + 3])
        bounds = [list(map(float, lines[k + 5 + d].split()[:2])) for d in range(3)]
        columns = lines[k + 8].split()[2:]
        rows = lines[k + 9:k + 9 + count]
        if len(rows) < count:
            break                      # a frame cut short (a run still writing): leave it out
        yield timestep, bounds, columns, rows
        k += 9 + count


class Frame:
    """One dump frame: box lo and length (2D), the columns as arrays (one row per vertex), and
    the cells as rings of row indices in ring order (counter-clockwise, from c_vertex[3])."""

    def __init__(self, timestep, bounds, columns, rows):
        self.timestep = timestep
        self.lo = np.array([bounds[0][0], bounds[1][0]])
        self.length = np.array([bounds[0][1] - bounds[0][0], bounds[1][1] - bounds[1][0]])
        data = np.array([r.split() for r in rows], dtype=float).reshape(len(rows), len(columns))
        self.columns = {name: data[:, j] for j, name in enumerate(columns)}
        for need in ("id", "mol", NEXT):
            if need not in self.columns:
                raise ValueError(f"dump frame at step {timestep} has no column '{need}' "
                                 f"(columns: {' '.join(columns)})")
        self.ids = self.columns["id"].astype(np.int64)
        self.mol = self.columns["mol"].astype(np.int64)
        xname = "xu" if "xu" in self.columns else "x"
        yname = "yu" if "yu" in self.columns else "y"
        self.raw = np.column_stack([self.columns[xname], self.columns[yname]])
        self.row_of = {int(t): r for r, t in enumerate(self.ids)}
        self._rings()

    def column(self, names):
        """The first of the named columns the dump has, or None."""
        for name in names:
            if name in self.columns:
                return self.columns[name]
        return None

    def minimum_image(self, d):
        return d - np.round(d / self.length) * self.length

    def _rings(self):
        nxt = self.columns[NEXT].astype(np.int64)
        seen = np.zeros(len(self.ids), dtype=bool)
        self.cells, self.rings = [], []
        self.pos = np.empty_like(self.raw)     # rings made contiguous, each cell's mean in the box
        for start in np.argsort(self.ids, kind="stable"):
            if seen[start] or nxt[start] == 0:
                continue
            ring = [start]
            seen[start] = True
            while True:
                r = self.row_of.get(int(nxt[ring[-1]]))
                if r is None:
                    raise ValueError(f"step {self.timestep}: vertex {self.ids[ring[-1]]} names a "
                                     f"next vertex {nxt[ring[-1]]} that is not in the frame")
                if r == start:
                    break
                if seen[r] or len(ring) > len(self.ids):
                    raise ValueError(f"step {self.timestep}: the ring through vertex "
                                     f"{self.ids[start]} does not close")
                ring.append(r)
                seen[r] = True
            ring = np.array(ring)
            steps = self.minimum_image(np.diff(self.raw[ring], axis=0))
            xy = self.raw[ring[0]] + np.vstack([[0.0, 0.0], np.cumsum(steps, axis=0)])
            centre = xy.mean(axis=0)
            xy -= np.floor((centre - self.lo) / self.length) * self.length
            self.pos[ring] = xy
            self.rings.append(ring)
            self.cells.append(int(self.mol[start]))

    def polygons(self):
        return [self.pos[ring] for ring in self.rings]

    def sigma(self, default=None):
        """Vertex diameters: the dump's d_sigma column; without it `default` (a number) or, if
        None, each vertex's mean length of its two ring segments (the DP convention that
        neighbouring disks touch: sigma = l0 in the shipped tissues). Returns (array, source)."""
        s = self.column(SIGMA)
        if s is not None:
            return s.copy(), "d_sigma"
        if default is not None:
            return np.full(len(self.ids), float(default)), f"--sigma {default}"
        out = np.empty(len(self.ids))
        for ring in self.rings:
            seg = np.hypot(*(np.roll(self.pos[ring], -1, axis=0) - self.pos[ring]).T)
            out[ring] = 0.5 * (seg + np.roll(seg, 1))
        return out, "mean of the two segment lengths (no d_sigma column)"


def read_frames(path):
    for block in _dump_blocks(path):
        yield Frame(*block)


def read_bond_frames(path):
    """Yield (timestep, (m, 3) int array of atom1 atom2 type) for every frame of a local dump."""
    for timestep, _, columns, rows in _dump_blocks(path):
        data = np.array([r.split() for r in rows], dtype=float).reshape(len(rows), len(columns))
        names = [c for c in columns if c != "index"]
        cols = [columns.index(c) for c in names[:3]]
        yield timestep, data[:, cols].astype(np.int64)


def polygon_area(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def polygon_perimeter(xy):
    return float(np.sum(np.hypot(*(np.roll(xy, -1, axis=0) - xy).T)))


def shape_parameter(xy):
    return polygon_perimeter(xy) ** 2 / (4 * np.pi * polygon_area(xy))


def adhesive_pairs(frame, bonds, adhesion_type=2):
    """The adhesive bonds of one bond frame as pairs of row indices of `frame` (bonds of other
    types, and bonds naming a vertex not in the frame, left out)."""
    if bonds is None:
        return np.zeros((0, 2), dtype=np.int64)
    sel = bonds[bonds[:, 2] == adhesion_type]
    pairs = [(frame.row_of[a], frame.row_of[b]) for a, b, _ in sel
             if a in frame.row_of and b in frame.row_of]
    return np.array(pairs, dtype=np.int64).reshape(-1, 2)


def vertex_bond_counts(frame, pairs):
    counts = np.zeros(len(frame.ids), dtype=np.int64)
    np.add.at(counts, pairs.ravel(), 1)
    return counts


def contact_numbers(frame, sigma, pairs=None):
    """Per cell (in frame.cells order) the number of distinct other cells it touches: a vertex
    pair of the two cells closer than the mean of their diameters (periodic), or an adhesive
    bond between them (pairs of row indices), as compute dpoly/tissue counts z."""
    from scipy.spatial import cKDTree
    wrapped = np.mod(frame.pos - frame.lo, frame.length)
    wrapped = np.minimum(wrapped, np.nextafter(frame.length, 0))
    tree = cKDTree(wrapped, boxsize=frame.length)
    found = tree.query_pairs(float(sigma.max()), output_type="ndarray")
    neighbours = {m: set() for m in frame.cells}
    if len(found):
        i, j = found[:, 0], found[:, 1]
        d = np.hypot(*frame.minimum_image(wrapped[i] - wrapped[j]).T)
        keep = (d < 0.5 * (sigma[i] + sigma[j])) & (frame.mol[i] != frame.mol[j])
        found = found[keep]
    for group in (found, pairs if pairs is not None else np.zeros((0, 2), dtype=np.int64)):
        for a, b in group:
            ma, mb = int(frame.mol[a]), int(frame.mol[b])
            if ma != mb:
                neighbours[ma].add(mb)
                neighbours[mb].add(ma)
    return np.array([len(neighbours[m]) for m in frame.cells])
