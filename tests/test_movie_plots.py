#!/usr/bin/env python3
"""tools/make_movie.py and tools/plot_mesophyll.py on a synthetic three-step run whose box grows:
the MP4 and GIF have one frame per growth step, the curves fill in, the tissue frame's box stays
put while the lab frame's grows, periodic images and vertex disks are drawn, the pressure panel
is |P/P0 - 1| on a log axis. Exit 77 (skip) only if a Debian package (matplotlib, ffmpeg) is
missing."""
import contextlib
import io
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viz_helpers as vh  # noqa: E402

vh.require(["numpy", "matplotlib", "PIL"])
if not shutil.which("ffmpeg") or not shutil.which("ffprobe"):
    print("test_movie_plots.py: no ffmpeg/ffprobe (Debian: apt-get install ffmpeg)",
          file=sys.stderr)
    sys.exit(vh.SKIP)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection, PolyCollection  # noqa: E402

import make_movie  # noqa: E402
import mesophyll_frames as mf  # noqa: E402
import plot_mesophyll as pm  # noqa: E402

P0 = 1e-3


def synthetic_run(folder, steps=3):
    """Four 12-gons in a box that grows by 20% a step (cells scaled with it), one across the
    x edge and one across the corner; growth table with P = P0 (1 + 1e-10 k), one exact."""
    frames, rows = [], []
    for k in range(steps):
        L = 6.0 * 1.2 ** k
        lo = np.array([-L / 2, -L / 2])
        cells = []
        for cx, cy in ((0.0, 0.0), (0.5, 0.05), (0.45, 0.45), (-0.25, 0.2)):
            ring = vh.regular_ring(12, 0.15 * L, (cx * L, cy * L))
            cells.append((ring, {"d_sigma": 0.03 * L}))
        frames.append((1000 * (k + 1), lo, lo + L, cells))
        phi = 4 * 0.5 * 12 * (0.15 * L) ** 2 * np.sin(2 * np.pi / 12) / L ** 2
        P = P0 if k == 1 else P0 * (1 + 1e-10 * (k + 1))
        rows.append(f"{k + 1} {P!r} {phi:.6f} {phi + 0.1:.6f} 1.05 1 0 0 100")
    dump, growth = os.path.join(folder, "cells.dump"), os.path.join(folder, "growth.txt")
    vh.write_dump(dump, frames)
    with open(growth, "w") as f:
        f.write("# step P phi phi_patch calA z bonds dphi_plus iterations\n" + "\n".join(rows)
                + "\n")
    return dump, growth


def frames_of(path):
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                          "-show_entries", "stream=nb_read_frames,width,height,codec_name",
                          "-of", "default=noprint_wrappers=1", path],
                         check=True, capture_output=True, text=True).stdout
    return dict(line.split("=", 1) for line in out.split())


class Movie(unittest.TestCase):
    def test_movie(self):
        with tempfile.TemporaryDirectory() as tmp:
            dump, growth = synthetic_run(tmp)
            out = os.path.join(tmp, "movie")
            err = io.StringIO()
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
                rc = make_movie.main([growth, dump, "--out", out, "--dpi", "40", "--fps", "2",
                                      "--keep-frames", os.path.join(tmp, "frames")])
            self.assertEqual(rc, 0)
            self.assertIn("rendering frame 3/3 (growth step 3)", err.getvalue())
            mp4, gif = frames_of(out + ".mp4"), frames_of(out + ".gif")
            self.assertEqual((mp4["codec_name"], mp4["nb_read_frames"]), ("h264", "3"))
            self.assertEqual((gif["codec_name"], gif["nb_read_frames"]), ("gif", "3"))
            self.assertEqual(int(mp4["width"]) % 2, 0)
            from PIL import Image
            shots = [np.asarray(Image.open(os.path.join(tmp, "frames", f"frame_{k:04d}.png"))
                                .convert("L"), dtype=float) for k in range(3)]
            h, w = shots[0].shape
            right = slice(int(0.72 * w), int(0.9 * w))
            # the curves fill in: the right panels change from frame to frame
            self.assertGreater(np.abs(shots[2][:, right] - shots[0][:, right]).mean(), 0.5)

    def test_tissue_and_lab_frames(self):
        with tempfile.TemporaryDirectory() as tmp:
            dump, _ = synthetic_run(tmp)
            frames = list(mf.read_frames(dump))
        self.assertEqual(make_movie.lab_limits(frames, margin=0),
                         (-4.32, 4.32, -4.32, 4.32))
        norm = matplotlib.colors.Normalize(1, 2)
        for frame in frames:
            sig, source = pm.frame_sigmas(frame)
            self.assertEqual(source, "d_sigma")
            fig, (a, b) = plt.subplots(1, 2)
            pm.draw_tissue(a, frame.lo, frame.length, frame.polygons(), norm, "viridis",
                           sigmas=sig, scaled=True)
            pm.draw_tissue(b, frame.lo, frame.length, frame.polygons(), norm, "viridis",
                           sigmas=sig, limits=make_movie.lab_limits(frames))
            # tissue frame: box units, the same limits at every step
            self.assertEqual(a.get_xlim(), (0.0, 1.0))
            polys = [c for c in a.collections if isinstance(c, PolyCollection)
                     and not isinstance(c, EllipseCollection)][0]
            # 1 + 2 + 4 + 1 images: inside, across x, across the corner, inside
            self.assertEqual(len(polys.get_paths()), 8)
            xy = np.vstack([p.vertices for p in polys.get_paths()])
            self.assertTrue((xy > -0.3).all() and (xy < 1.3).all())
            disks = [c for c in a.collections if isinstance(c, EllipseCollection)][0]
            self.assertEqual(len(disks.get_offsets()), 8 * 12)
            # lab frame: the box patch has this step's size
            box = [p for p in b.patches][0]
            self.assertAlmostEqual(box.get_width(), frame.length[0])
            self.assertEqual(b.get_xlim() + b.get_ylim(), make_movie.lab_limits(frames))
            plt.close(fig)


class Plots(unittest.TestCase):
    def test_pressure_panel(self):
        dev = pm.pressure_deviation([P0, P0 * (1 + 3e-11), P0 * (1 - 2e-9)], P0)
        np.testing.assert_allclose(dev, [pm.P_FLOOR, 3e-11, 2e-9], rtol=1e-3)
        fig, ax = plt.subplots()
        pm.draw_pressure(ax, [1, 2, 3], [P0, P0 * 1.1, P0 * 0.99], P0)
        self.assertEqual(ax.get_yscale(), "log")
        np.testing.assert_allclose(ax.lines[0].get_ydata(), [pm.P_FLOOR, 0.1, 0.01])
        plt.close(fig)

    def test_command_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            dump, growth = synthetic_run(tmp)
            out = os.path.join(tmp, "plots")
            tool = os.path.join(vh.TOOLS, "plot_mesophyll.py")
            for args in ([], ["--no-disks"]):
                run = subprocess.run([sys.executable, tool, growth, dump, "--out", out,
                                      "--phi", "0.5", "0.3"] + args,
                                     capture_output=True, text=True)
                self.assertEqual(run.returncode, 0, run.stderr)
                for name in ("shape", "packing", "snapshots"):
                    self.assertGreater(os.path.getsize(f"{out}_{name}.png"), 1000)
            self.assertNotIn("vertex disks", run.stdout)


if __name__ == "__main__":
    unittest.main(verbosity=2)
