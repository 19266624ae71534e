#!/usr/bin/env python3
"""Measure tissue images as the paper measures micrographs (binarize, segment, p^2/(4 pi a) per cell).

    image_metrics.py cells.N64.dump [--growth growth.N64.txt] [--bonds bonds.N64.dump]
                     [--frame K] [--pixel 0.01] [--outline disks|smooth|polygon] [--close R]
                     [--save-labels F.tif]
                     [--plot F.png] [--csv F.csv]
    image_metrics.py --image micrograph.png [--pixel-size 0.5] [--periodic] [--binary]
                     [--touch-gap PIXELS] [--plot F.png] [--csv F.csv]
    image_metrics.py --bias              # the pixel-perimeter bias on discs and hexagons

(a) A simulated frame (one frame of the run's dump; default the last) is rasterized into a label
    image at the chosen pixel size: each cell its molecule ID, air 0; a cell is its polygon and,
    with --outline disks (default), the disks of its vertices (diameter d_sigma; see --sigma when
    the dump has no d_sigma column); --outline smooth closes each cell (dilation and erosion by
    --close, default the median vertex radius, taking air pixels only), which fills most of
    the scallops between the disks that a micrograph's smooth walls do not have, and makes calA
    nearly independent of the pixel size; the periodic box is one image, cells that cross its edges
    wrap around. Pixels that two cells claim go to the cell whose polygon holds them, else to the
    nearest vertex disk (distance over radius).
(b) Any label image is measured with scikit-image: per cell its area, perimeter (estimator
    --estimator, default crofton4; --bias shows how biased each is), calA = p^2/(4 pi a) and
    contact number (distinct labels it touches, 4-neighbour, after growing the labels by
    --touch-gap pixels); porosity (air pixels / all); the pore-size distribution as local
    thickness (diameter of the largest disk inside the air that covers the pixel, from a
    Euclidean distance transform). A micrograph is a PNG or TIFF label image (integer labels, or
    RGB with one colour per cell, air 0 / black) or, with --binary, a grey image that is
    thresholded (Otsu) and segmented into connected components. Cells touching the image edge
    are left out of the per-cell means unless the image is --periodic.

The table shows the simulation's own values (polygon area and perimeter, calA, z from overlaps
and adhesive bonds, 1 - phi) next to the image's. Needs python3-numpy, python3-scipy,
python3-skimage, python3-matplotlib (Debian).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesophyll_frames as mf  # noqa: E402

mf.require(["numpy", "scipy", "skimage"])
import numpy as np  # noqa: E402
from scipy import ndimage  # noqa: E402
from skimage import draw, measure  # noqa: E402

ESTIMATORS = ("crofton4", "crofton2", "regionprops", "contour", "pixel_edges")
ESTIMATOR_TEXT = {
    "crofton4": "Crofton formula, 4 directions (skimage.measure.perimeter_crofton)",
    "crofton2": "Crofton formula, 2 directions (skimage.measure.perimeter_crofton)",
    "regionprops": "contour through boundary pixel centres, 4-connected "
                   "(skimage.measure.perimeter)",
    "contour": "marching-squares contour at level 0.5 (skimage.measure.find_contours)",
    "pixel_edges": "count of exposed pixel edges (the naive estimate)",
}


# --------------------------------------------------------------------------------------------
# (a) rasterizing a simulated frame

def raster_grid(lo, length, pixel):
    """Pixel counts and sizes that tile the box exactly (each close to `pixel`)."""
    n = np.maximum(1, np.round(np.asarray(length) / pixel)).astype(int)
    return n, np.asarray(length) / n


def rasterize(polygons, sigmas, labels, lo, length, pixel, outline="disks"):
    """Label image (rows = y from lo[1] up, columns = x) of the cells in a periodic box.

    polygons: list of (n, 2) vertex arrays (contiguous rings, unwrapped); sigmas: matching
    arrays of vertex diameters (ignored for outline 'polygon'); labels: the label of each cell
    (> 0). A pixel belongs to a cell when its centre is inside the cell's polygon or (outline
    'disks') inside one of its vertex disks; periodic images are drawn so that cells crossing
    the box edges wrap around."""
    lo = np.asarray(lo, dtype=float)
    length = np.asarray(length, dtype=float)
    n, px = raster_grid(lo, length, pixel)
    shape = (n[1], n[0])
    image = np.zeros(shape, dtype=np.int32)
    claims = np.zeros(shape, dtype=np.int16)
    for poly, lab in zip(polygons, labels):
        c = (poly[:, 0] - lo[0]) / px[0] - 0.5       # pixel coordinates of the vertices
        r = (poly[:, 1] - lo[1]) / px[1] - 0.5
        mine = np.zeros(shape, dtype=bool)
        for sx in (-1, 0, 1):
            for sy in (-1, 0, 1):
                cc, rr = c + sx * n[0], r + sy * n[1]
                if cc.max() < -1 or cc.min() > n[0] or rr.max() < -1 or rr.min() > n[1]:
                    continue
                pr, pc = draw.polygon(rr, cc, shape=shape)
                mine[pr, pc] = True
        image[mine] = lab
        claims += mine
    contested = claims > 1
    if outline == "polygon" and not contested.any():
        return image
    # vertex disks (and contested pixels): the vertex with the smallest distance / radius
    from scipy.spatial import cKDTree
    pos = np.vstack(polygons)
    owner = np.concatenate([np.full(len(p), lab) for p, lab in zip(polygons, labels)])
    radius = 0.5 * np.concatenate(sigmas) if outline == "disks" else None
    wrapped = np.minimum(np.mod(pos - lo, length), np.nextafter(length, 0))
    tree = cKDTree(wrapped, boxsize=length)
    todo = contested | (image == 0) if outline == "disks" else contested
    rows, cols = np.nonzero(todo)
    centres = np.column_stack([(cols + 0.5) * px[0], (rows + 0.5) * px[1]])
    k = min(8, len(pos))
    if outline == "disks":
        dist, idx = tree.query(centres, k=k, distance_upper_bound=float(radius.max()))
    else:
        dist, idx = tree.query(centres, k=k)
    dist = np.atleast_2d(dist.reshape(len(centres), k))
    idx = np.atleast_2d(idx.reshape(len(centres), k))
    valid = idx < len(pos)
    safe = np.where(valid, idx, 0)
    if outline == "disks":
        score = np.where(valid, dist / radius[safe], np.inf)
        cover = score < 1.0
        # a contested pixel stays with one of the polygons that hold it
        score = np.where(cover | contested[rows, cols][:, None], score, np.inf)
    else:
        score = np.where(valid, dist, np.inf)
    best = np.argmin(score, axis=1)
    got = np.isfinite(score[np.arange(len(best)), best])
    new = owner[safe[np.arange(len(best)), best]]
    image[rows[got], cols[got]] = new[got]
    return image


def close_cells(labels, radius):
    """Each cell's region closed (dilation then erosion) by a disk of `radius` pixels, the
    pixels it gains taken from the air only: fills the scallops between vertex disks, as a
    microscope sees a smooth cell wall. The image is periodic (tiled 3 x 3 to close the cells
    that cross its edges whole)."""
    R = int(np.ceil(radius))
    if radius <= 0:
        return labels.copy()
    ny, nx = labels.shape
    tile = np.tile(labels, (3, 3))
    pieces = measure.label(tile, background=0, connectivity=2)
    out = labels.copy()
    for reg in measure.regionprops(pieces):
        cy, cx = reg.centroid
        if not (ny <= cy < 2 * ny and nx <= cx < 2 * nx):
            continue
        r0, c0, r1, c1 = reg.bbox
        mask = np.pad(reg.image, R + 1)
        # Euclidean dilation then erosion by the radius, from distance transforms
        grown = ndimage.distance_transform_edt(~mask) <= radius
        closed = ndimage.distance_transform_edt(grown) > radius
        rr, cc = np.nonzero(closed & ~mask)
        rr = (rr + r0 - R - 1) % ny
        cc = (cc + c0 - R - 1) % nx
        lab = tile[reg.coords[0, 0], reg.coords[0, 1]]
        air = out[rr, cc] == 0
        out[rr[air], cc[air]] = lab
    return out


def frame_cells(frame, sigma_default=None):
    """Polygons, vertex diameters, labels (molecule IDs) and the sigma's source of a frame."""
    sigma, source = frame.sigma(sigma_default)
    return (frame.polygons(), [sigma[ring] for ring in frame.rings], list(frame.cells),
            sigma, source)


# --------------------------------------------------------------------------------------------
# (b) measuring a label image

def perimeter_of(mask, estimator):
    """Perimeter in pixels of a boolean mask (padded so it does not touch the array edge)."""
    m = np.pad(mask, 2)
    if estimator == "crofton4":
        return float(measure.perimeter_crofton(m, directions=4))
    if estimator == "crofton2":
        return float(measure.perimeter_crofton(m, directions=2))
    if estimator == "regionprops":
        return float(measure.perimeter(m, neighbourhood=4))
    if estimator == "contour":
        return float(sum(np.sum(np.hypot(*np.diff(c, axis=0).T))
                         for c in measure.find_contours(m.astype(float), 0.5)))
    if estimator == "pixel_edges":
        m = m.astype(np.int8)
        return float(np.abs(np.diff(m, axis=0)).sum() + np.abs(np.diff(m, axis=1)).sum())
    raise ValueError(f"unknown perimeter estimator '{estimator}' (one of {', '.join(ESTIMATORS)})")


def cell_regions(labels, periodic):
    """{label: boolean mask of the whole cell, cropped} and whether it touches the image edge.

    For a periodic image the label image is tiled 3 x 3 and, of the connected pieces of each
    label, those whose centroid lies in the middle tile are taken: a cell that wraps around the
    edges comes out whole."""
    out = {}
    if periodic:
        ny, nx = labels.shape
        tile = np.tile(labels, (3, 3))
        pieces = measure.label(tile, background=0, connectivity=2)
        for reg in measure.regionprops(pieces, intensity_image=tile):
            cy, cx = reg.centroid
            if not (ny <= cy < 2 * ny and nx <= cx < 2 * nx):
                continue
            lab = int(round(reg.intensity_max if hasattr(reg, "intensity_max")
                            else reg.max_intensity))
            r0, c0, r1, c1 = reg.bbox
            mask = reg.image
            if lab in out:                       # a cell in several pieces: join them
                (pr0, pc0), old = out[lab][1], out[lab][0]
                R0, C0 = min(pr0, r0), min(pc0, c0)
                R1 = max(pr0 + old.shape[0], r1)
                C1 = max(pc0 + old.shape[1], c1)
                joined = np.zeros((R1 - R0, C1 - C0), dtype=bool)
                joined[pr0 - R0:pr0 - R0 + old.shape[0], pc0 - C0:pc0 - C0 + old.shape[1]] |= old
                joined[r0 - R0:r1 - R0, c0 - C0:c1 - C0] |= mask
                out[lab] = (joined, (R0, C0), False)
            else:
                out[lab] = (mask, (r0, c0), False)
        return {lab: (m, edge) for lab, (m, _, edge) in out.items()}
    for reg in measure.regionprops(labels):
        r0, c0, r1, c1 = reg.bbox
        edge = r0 == 0 or c0 == 0 or r1 == labels.shape[0] or c1 == labels.shape[1]
        out[int(reg.label)] = (reg.image, edge)
    return out


def touching(labels, periodic, gap=0):
    """{label: set of labels it touches}: 4-neighbour pixel pairs of two different cells, after
    growing every label by `gap` pixels into the air (a micrograph's walls between cells)."""
    lab = labels
    if gap > 0:
        from skimage.segmentation import expand_labels
        if periodic:
            ny, nx = labels.shape
            big = expand_labels(np.tile(labels, (3, 3)), distance=gap)
            lab = big[ny:2 * ny, nx:2 * nx]
        else:
            lab = expand_labels(labels, distance=gap)
    nb = {int(v): set() for v in np.unique(lab) if v != 0}
    for axis in (0, 1):
        a = lab
        b = np.roll(lab, -1, axis=axis)
        if not periodic:
            a = a.take(range(lab.shape[axis] - 1), axis=axis)
            b = b.take(range(lab.shape[axis] - 1), axis=axis)
        sel = (a != b) & (a > 0) & (b > 0)
        for u, v in set(zip(a[sel].tolist(), b[sel].tolist())):
            nb[u].add(v)
            nb[v].add(u)
    return nb


def local_thickness(pore, periodic=False, tolerance=0.03):
    """Local thickness of the pores (True pixels), in pixels: at each pore pixel the diameter of
    the largest disk inside the pores that covers it (0 outside the pores).

    The Euclidean distance transform dt gives at each pore pixel c the distance r of its centre
    to the nearest cell pixel's centre; the pore's edge lies half a pixel before that pixel, so
    the disk about c that stays in the pore has diameter 2r - 1; the pixels whose centres are
    closer than r + 1/2 to c (the disk plus half a pixel, the pixels' own extent) count as
    covered by it, and a rim pixel that no disk reached takes the largest value of its eight
    neighbours. Centres are taken from the
    distance ridge (skimage's medial axis and the local maxima of dt), largest first; a centre
    whose disk lies inside disks already drawn, to `tolerance` times its radius (at least half a
    pixel), is skipped. A periodic image is padded by wrapping."""
    from skimage.morphology import medial_axis
    pore = np.asarray(pore, dtype=bool)
    if not pore.any():
        return np.zeros(pore.shape)
    work, pad = pore, 0
    if periodic:
        half = max(pore.shape) // 2 + 1
        dt = ndimage.distance_transform_edt(np.pad(pore, half, mode="wrap"))
        pad = min(half, int(np.ceil(dt.max())) + 2)
        dt = dt[half - pad:dt.shape[0] - half + pad, half - pad:dt.shape[1] - half + pad]
        work = np.pad(pore, pad, mode="wrap")
    else:
        dt = ndimage.distance_transform_edt(work)
    ridge = medial_axis(work) | (work & (dt >= ndimage.maximum_filter(dt, size=3)))
    rows, cols = np.nonzero(ridge)
    radius = dt[rows, cols]
    big = int(np.ceil(radius.max())) + 1
    shape = (work.shape[0] + 2 * big, work.shape[1] + 2 * big)
    thick = np.zeros(shape)
    slack = np.full(shape, -np.inf)      # max over drawn disks of (radius - distance)
    dist = {}
    for k in np.argsort(-radius, kind="stable"):
        r = radius[k]
        i, j = rows[k] + big, cols[k] + big
        if slack[i, j] >= r - max(0.5, tolerance * r):
            continue
        R = int(np.ceil(r + 0.5))
        if R not in dist:
            y, x = np.mgrid[-R:R + 1, -R:R + 1]
            dist[R] = np.hypot(x, y)
        d = dist[R]
        win = np.s_[i - R:i + R + 1, j - R:j + R + 1]
        t = thick[win]
        t[(d < r + 0.5) & (t == 0)] = 2.0 * r - 1.0
        np.maximum(slack[win], r - d, out=slack[win])
    thick = thick[big:big + work.shape[0], big:big + work.shape[1]]
    # a pore pixel that no drawn disk reached (the discrete disks miss some pixels of the
    # pore's rim) takes the largest value next to it; each pixel is also a disk of its own
    missed = work & (thick == 0)
    thick[missed] = ndimage.grey_dilation(thick, size=3)[missed]
    thick = np.maximum(thick, np.where(work, 2.0 * dt - 1.0, 0.0))
    if pad:
        thick = thick[pad:-pad, pad:-pad]
    return np.where(pore, thick, 0.0)


def measure_labels(labels, pixel=1.0, periodic=False, estimator="crofton4", touch_gap=0,
                   pores=True):
    """Per-cell and whole-image measurements of a label image (air 0); lengths in units of
    `pixel` (the side of one pixel). pores=False leaves out the local thickness."""
    regions = cell_regions(labels, periodic)
    nb = touching(labels, periodic, touch_gap)
    cells = []
    for lab in sorted(regions):
        mask, edge = regions[lab]
        area = float(mask.sum()) * pixel ** 2
        perim = perimeter_of(mask, estimator) * pixel
        cells.append({"label": lab, "area": area, "perimeter": perim,
                      "calA": perim ** 2 / (4 * np.pi * area), "z": len(nb.get(lab, ())),
                      "edge": bool(edge)})
    pore = labels == 0
    thick = local_thickness(pore, periodic) * pixel if pores else np.zeros(pore.shape)
    values = thick[pore]
    return {"cells": cells, "porosity": float(pore.mean()), "thickness": thick,
            "pore_thickness": values, "pixel": pixel, "estimator": estimator,
            "periodic": periodic}


# --------------------------------------------------------------------------------------------
# the bias of pixel perimeters

def disc_mask(radius, offset=(0.0, 0.0)):
    n = int(np.ceil(radius)) + 3
    y, x = np.mgrid[-n:n + 1, -n:n + 1].astype(float)
    return (x - offset[0]) ** 2 + (y - offset[1]) ** 2 < radius ** 2


def hexagon_mask(circumradius, angle=0.0, offset=(0.0, 0.0)):
    n = int(np.ceil(circumradius)) + 3
    t = angle + np.arange(6) * np.pi / 3
    r = n + offset[1] + circumradius * np.sin(t)
    c = n + offset[0] + circumradius * np.cos(t)
    mask = np.zeros((2 * n + 1, 2 * n + 1), dtype=bool)
    pr, pc = draw.polygon(r, c, shape=mask.shape)
    mask[pr, pc] = True
    return mask


def perimeter_bias(sizes=(5, 10, 20, 40), estimators=ESTIMATORS, samples=12, seed=1):
    """Mean relative error (measured/exact - 1) of perimeter, area and calA of discs (radius in
    pixels) and regular hexagons (circumradius in pixels), over random sub-pixel offsets and,
    for hexagons, random rotations. Returns rows (shape, size, estimator, dp, da, dcalA)."""
    rng = np.random.default_rng(seed)
    rows = []
    for shape in ("disc", "hexagon"):
        for size in sizes:
            if shape == "disc":
                p_exact, a_exact = 2 * np.pi * size, np.pi * size ** 2
            else:
                p_exact, a_exact = 6.0 * size, 1.5 * np.sqrt(3) * size ** 2
            masks = []
            for _ in range(samples):
                off = rng.uniform(-0.5, 0.5, 2)
                masks.append(disc_mask(size, off) if shape == "disc"
                             else hexagon_mask(size, rng.uniform(0, np.pi / 3), off))
            for est in estimators:
                dp, da, dc = [], [], []
                for m in masks:
                    p, a = perimeter_of(m, est), float(m.sum())
                    dp.append(p / p_exact - 1)
                    da.append(a / a_exact - 1)
                    dc.append((p ** 2 / a) / (p_exact ** 2 / a_exact) - 1)
                rows.append((shape, size, est, float(np.mean(dp)), float(np.mean(da)),
                             float(np.mean(dc))))
    return rows


def print_bias(rows):
    print("Pixel-perimeter bias: mean of measured/exact - 1 over 12 sub-pixel placements "
          "(hexagons also rotated)")
    print(f"{'shape':8s} {'size px':>7s}  {'estimator':12s} {'perimeter':>10s} {'area':>8s} "
          f"{'calA':>8s}")
    for shape, size, est, dp, da, dc in rows:
        print(f"{shape:8s} {size:7g}  {est:12s} {100 * dp:+9.2f}% {100 * da:+7.2f}% "
              f"{100 * dc:+7.2f}%")
    print("size: disc radius or hexagon circumradius in pixels. Estimators:")
    for est in ESTIMATORS:
        print(f"  {est:12s} {ESTIMATOR_TEXT[est]}")


# --------------------------------------------------------------------------------------------
# reading images

def read_label_image(path, binary=False):
    """A label image from PNG or TIFF: integer labels (air 0); RGB(A) with one colour per cell
    (black = air); or, with binary, a grey image thresholded by Otsu's method (cells bright)
    whose connected components are the cells."""
    from skimage import io
    img = io.imread(path)
    if img.ndim == 3 and img.shape[-1] in (3, 4):
        rgb = img[..., :3].astype(np.int64)
        if binary:
            img = rgb.mean(axis=-1)
        else:
            key = (rgb[..., 0] << 32) | (rgb[..., 1] << 16) | rgb[..., 2]
            _, inv = np.unique(key, return_inverse=True)
            labels = inv.reshape(key.shape).astype(np.int32)
            # the sorted colours: black (key 0), if there, is the first and becomes air 0
            return labels if (key == 0).any() else labels + 1
    if img.ndim != 2:
        raise ValueError(f"{path}: an image of shape {img.shape} is not a 2D label image")
    if binary:
        from skimage.filters import threshold_otsu
        fg = img > threshold_otsu(img)
        return measure.label(fg, background=0, connectivity=1).astype(np.int32)
    return img.astype(np.int32)


def save_label_image(path, labels):
    """16-bit (or 32-bit TIFF) label image, row 0 at the top (y flipped)."""
    from skimage import io
    flipped = labels[::-1]
    if labels.max() < 65536:
        io.imsave(path, flipped.astype(np.uint16), check_contrast=False)
    else:
        io.imsave(path, flipped.astype(np.uint32), check_contrast=False)


# --------------------------------------------------------------------------------------------
# the table and the plot

def simulation_values(frame, sigma, bonds=None, adhesion_type=2):
    polys = frame.polygons()
    area = np.array([mf.polygon_area(p) for p in polys])
    perim = np.array([mf.polygon_perimeter(p) for p in polys])
    pairs = mf.adhesive_pairs(frame, bonds, adhesion_type) if bonds is not None else None
    z = mf.contact_numbers(frame, sigma, pairs)
    return {"label": list(frame.cells), "area": area, "perimeter": perim,
            "calA": perim ** 2 / (4 * np.pi * area), "z": z,
            "phi": float(area.sum() / np.prod(frame.length)), "bonds": pairs is not None}


def summary(m):
    cells = [c for c in m["cells"] if m["periodic"] or not c["edge"]]
    get = lambda k: np.array([c[k] for c in cells], dtype=float)  # noqa: E731
    t = m["pore_thickness"]
    return {"cells": len(cells), "edge": len(m["cells"]) - len(cells),
            "porosity": m["porosity"], "area": get("area").mean() if cells else np.nan,
            "perimeter": get("perimeter").mean() if cells else np.nan,
            "calA": get("calA").mean() if cells else np.nan,
            "calA_median": np.median(get("calA")) if cells else np.nan,
            "z": get("z").mean() if cells else np.nan,
            "pore_mean": t.mean() if t.size else 0.0,
            "pore_median": np.median(t) if t.size else 0.0,
            "pore_p90": np.percentile(t, 90) if t.size else 0.0,
            "pore_max": t.max() if t.size else 0.0}


def print_table(img, sim=None, growth_row=None, notes=()):
    s = summary(img)
    rows = [("cells measured", s["cells"], None)]
    if s["edge"]:
        rows.append(("cells on the image edge (left out)", s["edge"], None))
    simv = {}
    if sim is not None:
        simv = {"area": np.mean(sim["area"]), "perimeter": np.mean(sim["perimeter"]),
                "calA": np.mean(sim["calA"]), "calA_median": np.median(sim["calA"]),
                "z": np.mean(sim["z"]), "porosity": 1.0 - sim["phi"]}
    rows += [("porosity (1 - phi; simulation: polygons)", s["porosity"], simv.get("porosity"))]
    if growth_row is not None and "phi_patch" in growth_row:
        rows.append(("porosity 1 - phi_patch (growth table)", None, 1.0 - growth_row["phi_patch"]))
    rows += [("mean cell area", s["area"], simv.get("area")),
             ("mean perimeter", s["perimeter"], simv.get("perimeter")),
             ("mean calA = p^2/(4 pi a)", s["calA"], simv.get("calA")),
             ("median calA", s["calA_median"], simv.get("calA_median")),
             ("mean contact number z", s["z"], simv.get("z"))]
    if growth_row is not None:
        for key, text in (("calA", "mean calA (growth table)"), ("z", "mean z (growth table)")):
            if key in growth_row:
                rows.append((text, None, growth_row[key]))
    rows += [("pore local thickness: mean", s["pore_mean"], None),
             ("pore local thickness: median", s["pore_median"], None),
             ("pore local thickness: 90th percentile", s["pore_p90"], None),
             ("pore local thickness: largest", s["pore_max"], None)]
    fmt = lambda v: "" if v is None else (f"{v:d}" if isinstance(v, int) else f"{v:.5g}")  # noqa
    w = max(len(r[0]) for r in rows)
    head = f"{'quantity':{w}s}  {'simulation':>12s}  {'image':>12s}  {'image/sim':>9s}"
    print(head)
    print("-" * len(head))
    for name, iv, sv in rows:
        ratio = f"{iv / sv:9.4f}" if (iv is not None and sv is not None and sv != 0
                                      and not isinstance(iv, int)) else ""
        print(f"{name:{w}s}  {fmt(sv):>12s}  {fmt(iv):>12s}  {ratio:>9s}")
    print(f"perimeter estimator: {ESTIMATOR_TEXT[img['estimator']]}")
    for n in notes:
        print(n)


def write_csv(path, img, sim=None):
    simrow = {}
    if sim is not None:
        simrow = {lab: k for k, lab in enumerate(sim["label"])}
    with open(path, "w") as f:
        f.write("label,area,perimeter,calA,z,edge,sim_area,sim_perimeter,sim_calA,sim_z\n")
        for c in img["cells"]:
            k = simrow.get(c["label"])
            extra = ("" if k is None else f"{sim['area'][k]:.6g},{sim['perimeter'][k]:.6g},"
                     f"{sim['calA'][k]:.6g},{int(sim['z'][k])}")
            if k is None:
                extra = ",,,"
            f.write(f"{c['label']},{c['area']:.6g},{c['perimeter']:.6g},{c['calA']:.6g},"
                    f"{c['z']},{int(c['edge'])},{extra}\n")


def plot(path, labels, img, sim=None, extent=None, title=""):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(9, 8))
    rng = np.random.default_rng(3)
    colours = rng.uniform(0.25, 1.0, (int(labels.max()) + 1, 3))
    colours[0] = 0.0
    ax[0, 0].imshow(colours[labels], origin="lower", extent=extent, interpolation="nearest")
    ax[0, 0].set_title("label image (air black)")
    th = np.ma.masked_where(labels > 0, img["thickness"])
    im = ax[0, 1].imshow(th, origin="lower", extent=extent, cmap="magma",
                         interpolation="nearest")
    ax[0, 1].set_facecolor("0.85")
    fig.colorbar(im, ax=ax[0, 1], shrink=0.8, label="local thickness")
    ax[0, 1].set_title("pores: local thickness")
    cells = [c for c in img["cells"] if img["periodic"] or not c["edge"]]
    ca = np.array([c["calA"] for c in cells])
    if sim is not None:
        idx = {lab: k for k, lab in enumerate(sim["label"])}
        pairs = [(sim["calA"][idx[c["label"]]], c["calA"]) for c in cells if c["label"] in idx]
        if pairs:
            s, i = np.array(pairs).T
            ax[1, 0].plot(s, i, "o", ms=4)
            lim = [min(s.min(), i.min()) * 0.97, max(s.max(), i.max()) * 1.03]
            ax[1, 0].plot(lim, lim, "k--", lw=0.8)
            ax[1, 0].set_xlabel(r"$\mathcal{A}$, simulation (polygon)")
            ax[1, 0].set_ylabel(r"$\mathcal{A}$, image")
            ax[1, 0].set_title("shape parameter per cell")
    else:
        ax[1, 0].hist(ca, bins=20)
        ax[1, 0].set_xlabel(r"$\mathcal{A} = p^2/(4\pi a)$")
        ax[1, 0].set_ylabel("cells")
    t = img["pore_thickness"]
    if t.size:
        ax[1, 1].hist(t, bins=40, weights=np.full(t.size, img["pixel"] ** 2))
    ax[1, 1].set_xlabel("pore local thickness")
    ax[1, 1].set_ylabel("pore area")
    ax[1, 1].set_title(f"porosity {img['porosity']:.3f}")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


# --------------------------------------------------------------------------------------------

def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="\n".join(__doc__.splitlines()[2:]))
    p.add_argument("dump", nargs="?", help="per-vertex dump of a run (cells.N*.dump)")
    p.add_argument("--image", help="measure this label image (PNG or TIFF) instead")
    p.add_argument("--bias", action="store_true", help="print the pixel-perimeter bias table")
    p.add_argument("--frame", type=int, default=-1, help="dump frame (0 = first, -1 = last)")
    p.add_argument("--growth", help="growth table of the run, for its phi_patch, calA, z")
    p.add_argument("--bonds", help="local dump of the bonds (for z with adhesive bonds)")
    p.add_argument("--adhesion-type", type=int, default=2, help="bond type of adhesion (2)")
    p.add_argument("--pixel", type=float, default=None,
                   help="pixel size in simulation units (default: box / 800)")
    p.add_argument("--outline", choices=("disks", "smooth", "polygon"), default="disks",
                   help="a cell is its polygon plus its vertex disks (default), the same closed "
                        "by a disk of radius --close (smooth: most of the scallops between the "
                        "vertex disks filled), or its polygon")
    p.add_argument("--close", type=float, default=None,
                   help="closing radius of --outline smooth (default: the median vertex "
                        "radius, d_sigma / 2)")
    p.add_argument("--sigma", type=float, default=None,
                   help="vertex diameter where the dump has no d_sigma column (default: each "
                        "vertex's mean segment length)")
    p.add_argument("--pixel-size", type=float, default=1.0,
                   help="--image: length of one pixel (e.g. um), default 1")
    p.add_argument("--periodic", action="store_true", help="--image: the image is periodic")
    p.add_argument("--binary", action="store_true",
                   help="--image: threshold a grey image (Otsu) and segment it")
    p.add_argument("--touch-gap", type=float, default=0,
                   help="grow labels by this many pixels before counting contacts (default 0)")
    p.add_argument("--estimator", choices=ESTIMATORS, default="crofton4",
                   help="perimeter estimator (default crofton4)")
    p.add_argument("--save-labels", help="write the label image (16-bit PNG or TIFF)")
    p.add_argument("--plot", help="write a figure (PNG)")
    p.add_argument("--csv", help="write the per-cell values (CSV)")
    a = p.parse_args(argv)

    if a.bias:
        print_bias(perimeter_bias())
        return 0
    if a.image:
        labels = read_label_image(a.image, a.binary)
        img = measure_labels(labels, a.pixel_size, a.periodic, a.estimator, a.touch_gap)
        print(f"{a.image}: {labels.shape[1]} x {labels.shape[0]} pixels, "
              f"{len(img['cells'])} labels")
        print_table(img)
        if a.csv:
            write_csv(a.csv, img)
        if a.plot:
            plot(a.plot, labels[::-1], dict(img, thickness=img["thickness"][::-1]),
                 title=os.path.basename(a.image))
        return 0
    if not a.dump:
        p.error("name a dump, --image FILE or --bias")

    frames = list(mf.read_frames(a.dump))
    if not frames:
        p.error(f"{a.dump}: no complete frame")
    k = a.frame if a.frame >= 0 else len(frames) + a.frame
    frame = frames[k]
    bonds = None
    if a.bonds:
        for ts, b in mf.read_bond_frames(a.bonds):
            if ts == frame.timestep:
                bonds = b
        if bonds is None:
            print(f"note: {a.bonds} has no frame at step {frame.timestep}; z without bonds")
    polys, sig, labs, sigma, source = frame_cells(frame, a.sigma)
    pixel = a.pixel or float(frame.length.min()) / 800
    labels = rasterize(polys, sig, labs, frame.lo, frame.length, pixel,
                       "polygon" if a.outline == "polygon" else "disks")
    _, px = raster_grid(frame.lo, frame.length, pixel)
    close = a.close if a.close is not None else 0.5 * float(np.median(sigma))
    if a.outline == "smooth":
        labels = close_cells(labels, close / float(px[0]))
    img = measure_labels(labels, float(px[0]), True, a.estimator, a.touch_gap)
    sim = simulation_values(frame, sigma, bonds, a.adhesion_type)
    growth_row = None
    if a.growth:
        g = mf.read_growth(a.growth)
        if k < len(g["step"]):
            growth_row = {name: float(col[k]) for name, col in g.items()}
    print(f"{a.dump}: frame {k} (timestep {frame.timestep}), {len(labs)} cells, box "
          f"{frame.length[0]:.4g} x {frame.length[1]:.4g}, pixel {px[0]:.4g} "
          f"({labels.shape[1]} x {labels.shape[0]}), outline {a.outline}")
    notes = [f"vertex diameters: {source}" if a.outline != "polygon" else
             "cells rasterized as their polygons (no vertex disks)",
             "simulation z: other cells with an overlapping vertex pair"
             + (" or an adhesive bond" if sim["bonds"] else " (no bond dump: bonds not counted)"),
             "image z: distinct labels touching (4-neighbour pixels)"]
    if a.outline == "smooth":
        notes.append("outline smooth: polygon and disks, each cell closed by a disk of radius "
                     f"{close:.4g}" + (" (--close)" if a.close is not None else
                                       " (the median vertex radius)"))
    if a.outline != "polygon":
        notes.append("the image cells include their vertex disks, so their areas and perimeters "
                     "are larger than the polygons'")
    print_table(img, sim, growth_row, notes)
    if a.save_labels:
        save_label_image(a.save_labels, labels)
        print(f"wrote {a.save_labels}")
    if a.csv:
        write_csv(a.csv, img, sim)
        print(f"wrote {a.csv}")
    if a.plot:
        extent = [frame.lo[0], frame.lo[0] + frame.length[0], frame.lo[1],
                  frame.lo[1] + frame.length[1]]
        plot(a.plot, labels, img, sim, extent,
             f"{os.path.basename(a.dump)} frame {k}: image measurements")
        print(f"wrote {a.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
