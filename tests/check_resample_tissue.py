#!/usr/bin/env python3
"""Check tools/resample_tissue.py on examples/mesophyll/tissue_N16.data (32 vertices per cell).

    check_resample_tissue.py [--lmp BUILD/lmp]

Without LAMMPS (the resampled rings, --rings-only):
* n = 32 gives back the input's vertices (to 1e-4 of the segment length: its segments are equal
  to their strain, ~1e-6, which adds up along a ring) and its l0, d_kl, d_kb, sigma, a0 (to 1e-5 relative);
* at n = 16, 24, 48, 64 every segment has the input's EA = d_kl / l0 and every vertex its
  B = d_kb lbar (to 1e-5; so d_kl ~ 32/n, d_kb ~ n/32), sigma and a0 are the input's, and each
  ring's preferred perimeter sum(l0) is the input's less the polygon's corner cutting (< 3%; sharp corners at n = 24);
With --lmp, the whole tool at n = 32 (bonds at touching pairs, relax at P0): the same number
of adhesive bonds (to 1%), phi_patch and <calA> within 2e-3 of the input's, every vertex within
2% of a segment of the input's position after the box scaling of the relax.
Exits 1 with the failed checks listed. Standard library only.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import resample_tissue  # noqa: E402

SOURCE = os.path.join(ROOT, "examples", "mesophyll", "tissue_N16.data")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def close(a, b, rtol):
    return abs(a - b) <= rtol * max(abs(a), abs(b))


def rings_of(path):
    return resample_tissue.read_tissue(path)[1]


def tissue_line(path, lmp, scratch):
    """phi_patch, <calA>, bonds of a data file, from compute dpoly/tissue (in.make_tissue's)."""
    log = os.path.join(scratch, "log.check")
    probe = os.path.join(scratch, "in.check")
    factors = "Stiffness" in resample_tissue.read_sections(path)[1]
    with open(probe, "w") as f:
        f.write("units lj\ndimension 2\natom_style molecular\nboundary p p p\n"
                "fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes\n" +
                ("fix Stiffness all property/atom d_kl d_kb ghost yes\n" if factors else "") +
                f"read_data {path} fix Vertices NULL Vertices" +
                (" fix Stiffness NULL Stiffness\n" if factors else "\n") +
                "bond_style hybrid dpoly/segment mesophyll/adhesion\n"
                "bond_coeff 1 dpoly/segment 1.0\nbond_coeff 2 mesophyll/adhesion 1.0\n"
                "angle_style dpoly/bending\nangle_coeff * 0.4\npair_style dpoly/contact\n"
                "pair_coeff * * 1.0\nspecial_bonds lj 1.0 1.0 1.0\ncomm_modify cutoff 2.0\n"
                "fix cells all dpoly/cells eps_a 1.0\ncompute tissue all dpoly/tissue\n"
                "run 0 post no\n"
                'print "TISSUE $(c_tissue[2]) $(c_tissue[3]) $(c_tissue[5])"\n')
    subprocess.run([lmp, "-in", probe, "-log", log, "-screen", "none"], check=True)
    with open(log) as f:
        words = [line.split() for line in f if line.startswith("TISSUE")][0]
    return float(words[1]), float(words[2]), int(float(words[3]))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", help="LAMMPS binary: also check the whole tool at n = 32")
    args = p.parse_args()
    box, original = resample_tissue.read_tissue(SOURCE)
    segment = original[0][0]["l0"]
    with tempfile.TemporaryDirectory() as scratch:
        for n in (16, 24, 32, 48, 64):
            path = os.path.join(scratch, f"rings{n}.data")
            resample_tissue.main([SOURCE, str(n), path, "--rings-only"])
            for old, new in zip(original, rings_of(path)):
                shift = (new[0]["x"] + box[0] - old[0]["x"], new[0]["y"] + box[2] - old[0]["y"])
                shift = tuple(round(d / (box[1] - box[0])) * (box[1] - box[0]) for d in shift)
                if n == 32:
                    for a, b in zip(old, new):
                        d = math.hypot(b["x"] + box[0] - shift[0] - a["x"],
                                       b["y"] + box[2] - shift[1] - a["y"])
                        check(d < 1e-4 * segment, f"n 32: vertex {a['tag']} moved by {d:.2e}")
                        for key in ("l0", "kl", "kb", "sigma", "a0"):
                            check(close(a[key], b[key], 1e-5),
                                  f"n 32: vertex {a['tag']} {key} {a[key]} -> {b[key]}")
                # EA = eps_l d_kl / l0 and B = eps_b d_kb lbar of the input (uniform in it)
                ea, modulus = old[0]["kl"] / old[0]["l0"], old[0]["kb"] * old[0]["l0"]
                for k, v in enumerate(new):
                    lbar = 0.5 * (new[k - 1]["l0"] + v["l0"])
                    check(close(v["kl"] / v["l0"], ea, 1e-5) and
                          close(v["kb"] * lbar, modulus, 1e-5),
                          f"n {n}: EA {v['kl'] / v['l0']:.8g} (input {ea:.8g}) or B "
                          f"{v['kb'] * lbar:.8g} (input {modulus:.8g}) changed")
                    check(close(v["sigma"], segment, 1e-9) and v["a0"] == old[0]["a0"],
                          f"n {n}: sigma or a0 of a new vertex changed")
                perimeter = [sum(v["l0"] for v in ring) for ring in (old, new)]
                check(0 <= perimeter[0] - perimeter[1] < 0.03 * perimeter[0],
                      f"n {n}: cell {old[0]['cell']} sum(l0) {perimeter[0]} -> {perimeter[1]}")
        if args.lmp:
            out = os.path.join(scratch, "tissue32.data")
            resample_tissue.main([SOURCE, "32", out, "--lmp", os.path.abspath(args.lmp)])
            before = tissue_line(SOURCE, os.path.abspath(args.lmp), scratch)
            after = tissue_line(out, os.path.abspath(args.lmp), scratch)
            check(abs(before[0] - after[0]) < 2e-3, f"phi_patch {before[0]} -> {after[0]}")
            check(abs(before[1] - after[1]) < 2e-3, f"<calA> {before[1]} -> {after[1]}")
            check(abs(before[2] - after[2]) <= 0.01 * before[2], f"bonds {before[2]} -> "
                  f"{after[2]}")
            new_box, relaxed = resample_tissue.read_tissue(out)
            scale = (new_box[1] - new_box[0]) / (box[1] - box[0])
            worst = 0.0
            for old, new in zip(original, relaxed):
                cx = sum(v["x"] for v in old) / len(old)
                cy = sum(v["y"] for v in old) / len(old)
                nx = sum(v["x"] for v in new) / len(new)
                ny = sum(v["y"] for v in new) / len(new)
                # relative to the cell's centre, whose position the box scaling moves
                for a, b in zip(old, new):
                    worst = max(worst, math.hypot(b["x"] - nx - (a["x"] - cx),
                                                  b["y"] - ny - (a["y"] - cy)))
            check(worst < 0.02 * segment, f"n 32: a vertex moved by {worst / segment:.3f} "
                  f"segments relative to its cell's centre (box scale {scale:.5f})")
            print(f"n 32 through in.make_tissue: phi_patch {before[0]:.4f} -> {after[0]:.4f}, "
                  f"<calA> {before[1]:.4f} -> {after[1]:.4f}, bonds {before[2]} -> {after[2]}, "
                  f"largest vertex move relative to its cell {worst / segment:.4f} segments")
    for f in failures[:20]:
        print("FAILED:", f)
    print(f"{len(failures)} failed checks" if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
