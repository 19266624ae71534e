#!/usr/bin/env python3
"""Reads what diagnose.in wrote in a run folder and prints the diagnosis of one minimization.

    python3 analyse.py [--log diagnose.log] [--top 10] [--windows 8] [DIR]

1. the force norms along the minimization: the 2-norm of the atoms' forces (fnorm), the largest
   component (fmax) and the box's force 2 V (P - P0), in windows of iterations, with the decay
   rate of log10 fnorm per 10^4 iterations in each window (a slow mode decays at a steady small
   rate, a floor does not decay, an oscillation goes up and down);
2. the slowest mode: the change of the positions between the last two snapshots of slow.dump
   (late in the minimization every faster mode has decayed), per cell, and how much of it each
   cell's rigid motion (translation and rotation) carries;
3. where the residual force sits: the atoms with the largest force, their cell and the part of
   their force from each term (forces.<term>.dump: the force without a term, subtracted from the
   force with all; the area term is what is left), and the squared force per cell.
Standard library only (and tests/regression.py's reader of thermo tables).
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests"))
import regression    # noqa: E402  (its reader of LAMMPS's thermo tables)

TERMS = ("segment", "adhesion", "bending", "contact")


def thermo_rows(log):
    """The thermo rows of the first minimization in the log: dicts by column name."""
    for columns, rows in regression.thermo_blocks(log):
        if columns[:2] == ["Step", "PotEng"]:
            return [dict(zip(columns, row)) for row in rows]
    return []


def read_dump(path):
    atoms = {}
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    names = lines[start].split()[2:]
    for line in lines[start + 1:]:
        if line.startswith("ITEM:"):
            break
        row = dict(zip(names, line.split()))
        atoms[int(row["id"])] = (int(row["mol"]), float(row["x"]), float(row["y"]),
                                 float(row["fx"]), float(row["fy"]))
    return atoms


def snapshots(path):
    """slow.dump as a list of (step, {id: (mol, x, y)})."""
    shots, lines = [], open(path).read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            count = int(lines[k + 3])
            names = lines[k + 8].split()[2:]
            atoms = {}
            for line in lines[k + 9:k + 9 + count]:
                row = dict(zip(names, line.split()))
                atoms[int(row["id"])] = (int(row["mol"]), float(row["xu"]), float(row["yu"]))
            shots.append((step, atoms))
            k += 9 + count
        else:
            k += 1
    return shots


def slow_mode(path):
    shots = snapshots(path)
    if len(shots) < 2:
        print(f"{path}: fewer than 2 snapshots")
        return
    # the last two snapshots a full dump interval apart (the final one may come sooner)
    gaps = [shots[k + 1][0] - shots[k][0] for k in range(len(shots) - 1)]
    interval = max(set(gaps), key=gaps.count)
    k = max(k for k, g in enumerate(gaps) if g == interval)
    (s1, a), (s2, b) = shots[k], shots[k + 1]
    common = [i for i in b if i in a]
    d = {i: (b[i][1] - a[i][1], b[i][2] - a[i][2]) for i in common}
    whole = sum(v[0] ** 2 + v[1] ** 2 for v in d.values())
    if whole == 0.0:
        print(f"\nslowest mode: no vertex moved between steps {s1} and {s2}")
        return
    # the whole tissue's translation costs nothing and is no mode of the force: taken out
    mx = sum(v[0] for v in d.values()) / len(d)
    my = sum(v[1] for v in d.values()) / len(d)
    d = {i: (v[0] - mx, v[1] - my) for i, v in d.items()}
    total = sum(dx * dx + dy * dy for dx, dy in d.values())
    print(f"\nslowest mode: positions at step {s2} minus step {s1}: the whole tissue moved "
          f"({mx:.3g}, {my:.3g}), {len(d) * (mx * mx + my * my) / whole:.3f} of |dx|^2; the rest: "
          f"|dx| = {math.sqrt(total):.3g}, largest on one vertex "
          f"{max(math.hypot(*v) for v in d.values()):.3g}")
    if total == 0.0:
        return
    cells = {}
    for i in common:
        cells.setdefault(a[i][0], []).append(i)
    rows = []
    for c, ids in cells.items():
        n = len(ids)
        cx = sum(a[i][1] for i in ids) / n
        cy = sum(a[i][2] for i in ids) / n
        tx = sum(d[i][0] for i in ids) / n
        ty = sum(d[i][1] for i in ids) / n
        # rotation about the centroid: least squares angle of the displacements minus translation
        num = sum((a[i][1] - cx) * (d[i][1] - ty) - (a[i][2] - cy) * (d[i][0] - tx) for i in ids)
        den = sum((a[i][1] - cx) ** 2 + (a[i][2] - cy) ** 2 for i in ids)
        w = num / den if den else 0.0
        cell2 = sum(d[i][0] ** 2 + d[i][1] ** 2 for i in ids)
        rigid2 = n * (tx * tx + ty * ty) + w * w * den
        rows.append((cell2, c, n, math.hypot(tx, ty) , w, rigid2))
    rows.sort(reverse=True)
    rigid = sum(r[5] for r in rows)
    print(f"share of |dx|^2 in the cells' rigid translations and rotations: {rigid / total:.3f}")
    print(f"{'cell':>4} {'vertices':>8} {'share':>6} {'translation':>11} {'rotation':>10} "
          f"{'rigid share of cell':>19}")
    for cell2, c, n, t, w, rigid2 in rows[:6]:
        print(f"{c:>4} {n:>8} {cell2 / total:>6.3f} {t:>11.3g} {w:>10.3g} {rigid2 / cell2:>19.3f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", nargs="?", default=".")
    ap.add_argument("--log", default="diagnose.log")
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--windows", type=int, default=8)
    args = ap.parse_args()
    os.chdir(args.dir)

    rows = thermo_rows(args.log)
    if len(rows) < 3:
        sys.exit(f"{args.log}: fewer than 3 thermo rows in the first minimization")
    first = rows[0]["Step"]
    print(f"minimization: {len(rows)} thermo rows, iterations 0 to {rows[-1]['Step'] - first:.0f}")
    print(f"{'iterations':>21} {'fnorm first':>12} {'fnorm min':>11} {'fnorm max':>11} "
          f"{'fnorm last':>11} {'log10/1e4 it':>12} {'|fbox| max':>11} {'vol max-min':>11} "
          f"{'phi_patch':>9}")
    size = max(2, len(rows) // args.windows)
    for k in range(0, len(rows) - 1, size):
        w = rows[k:k + size + 1]
        f = [r["Fnorm"] for r in w]
        span = w[-1]["Step"] - w[0]["Step"]
        rate = (math.log10(f[-1]) - math.log10(f[0])) / span * 1e4 if span and min(f) > 0 else 0
        print(f"{w[0]['Step'] - first:>10.0f}-{w[-1]['Step'] - first:<10.0f} {f[0]:>12.4g} "
              f"{min(f):>11.4g} {max(f):>11.4g} {f[-1]:>11.4g} {rate:>12.3g} "
              f"{max(abs(r['v_fbox']) for r in w):>11.3g} "
              f"{max(r['Volume'] for r in w) - min(r['Volume'] for r in w):>11.3g} "
              f"{w[-1].get('c_tissue[2]', float('nan')):>9.5f}")

    if os.path.exists("slow.dump"):
        slow_mode("slow.dump")
    if not os.path.exists("forces.all.dump"):
        print("no forces.all.dump: the minimization did not finish")
        return
    full = read_dump("forces.all.dump")
    parts = {}
    for term in TERMS:
        other = read_dump(f"forces.no_{term}.dump")
        parts[term] = {i: (full[i][3] - other[i][3], full[i][4] - other[i][4]) for i in full}
    parts["area"] = {i: (full[i][3] - sum(parts[t][i][0] for t in TERMS),
                         full[i][4] - sum(parts[t][i][1] for t in TERMS)) for i in full}
    names = TERMS + ("area",)
    total2 = sum(a[3] ** 2 + a[4] ** 2 for a in full.values())
    print(f"\nfinal state: {len(full)} vertices, force 2-norm {math.sqrt(total2):.4g}")
    print(f"largest forces (|f|, cell, and each term's |f| on that vertex):")
    print(f"{'id':>6} {'cell':>4} {'|f|':>10} " + " ".join(f"{n:>10}" for n in names))
    ranked = sorted(full, key=lambda i: -(full[i][3] ** 2 + full[i][4] ** 2))
    for i in ranked[:args.top]:
        fi = math.hypot(full[i][3], full[i][4])
        print(f"{i:>6} {full[i][0]:>4} {fi:>10.3g} "
              + " ".join(f"{math.hypot(*parts[n][i]):>10.3g}" for n in names))
    cells = {}
    for i, a in full.items():
        cells[a[0]] = cells.get(a[0], 0.0) + a[3] ** 2 + a[4] ** 2
    share = sorted(cells.items(), key=lambda c: -c[1])
    print("share of |f|^2 per cell (largest 5): "
          + ", ".join(f"cell {c} {v / total2:.2f}" for c, v in share[:5]))


if __name__ == "__main__":
    main()
