#!/usr/bin/env python3
"""Reads what diagnose.in wrote in a run folder and prints the diagnosis of one minimization.

    python3 analyse.py [--log diagnose.log] [--top 10] [--windows 8] [DIR]

1. the force norms along the minimization: the 2-norm of the atoms' forces (fnorm), the largest
   component (fmax) and the box's force 2 V (P - P0), in windows of iterations, with the decay
   rate of log10 fnorm per 10^4 iterations in each window (a slow mode decays at a steady small
   rate, a floor does not decay, an oscillation goes up and down);
2. where the residual force sits: the atoms with the largest force, their cell and the part of
   their force from each term (forces.<term>.dump: the force without a term, subtracted from the
   force with all; the area term is what is left), and the squared force per cell.
Standard library only.
"""
import argparse
import math
import os
import re
import sys

TERMS = ("segment", "adhesion", "bending", "contact")


def thermo_rows(log):
    """The thermo rows of the first minimization in the log: dicts by column name."""
    rows, header = [], None
    for line in open(log, errors="replace"):
        words = line.split()
        if words[:2] == ["Step", "PotEng"]:
            if header is not None:
                break
            header = words
            continue
        if header and words and re.fullmatch(r"\d+", words[0]) and len(words) == len(header):
            try:
                rows.append(dict(zip(header, map(float, words))))
            except ValueError:
                pass
        elif header and rows and line.startswith("Loop time"):
            break
    return rows


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
