#!/usr/bin/env python3
"""The development movie of a MESOPHYLL run: MP4 (ffmpeg) and GIF, one frame per growth step.

    make_movie.py growth.N64.txt cells.N64.dump [--out mesophyll_N64] [--fps 4] [--dpi 100]
                  [--P0 1e-3] [--sigma S] [--no-disks] [--frames K ...] [--no-mp4] [--no-gif]

Each frame shows, side by side: the tissue frame (box coordinates (x - lo)/L: the periodic box
stays put, periodic images fill it), the lab frame (the box as it grows, at the scale of the
last one), and phi (patch and polygons) and |P/P0 - 1| against growth step, filled in up to the
frame's step. Cells are coloured by calA = p^2/(4 pi a) on one scale for the whole movie and
drawn with their vertex disks (d_sigma; without it --sigma or each vertex's mean segment
length). The frames are rendered to PNGs in a temporary folder (a progress line on stderr) and
put together by ffmpeg: <out>.mp4 (H.264, yuv420p) and <out>.gif (ffmpeg's palette filters; with
no ffmpeg, Pillow writes the GIF and the MP4 is left out). Needs python3-matplotlib and ffmpeg.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesophyll_frames as mf  # noqa: E402

mf.require(["numpy", "matplotlib"])
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import plot_mesophyll as pm  # noqa: E402


def lab_limits(frames, margin=0.02):
    """Fixed axis limits of the lab frame: the union of all boxes, plus a margin."""
    lo = np.min([f.lo for f in frames], axis=0)
    hi = np.max([f.lo + f.length for f in frames], axis=0)
    pad = margin * (hi - lo)
    return (lo[0] - pad[0], hi[0] + pad[0], lo[1] - pad[1], hi[1] + pad[1])


def render_frames(frames, growth, folder, P0=1e-3, sigma=None, disks=True, dpi=100,
                  progress=True):
    """Draw one PNG per frame in folder (frame_0000.png, ...); returns their paths."""
    n = len(frames)
    steps = growth["step"][:n] if growth is not None else np.arange(1, n + 1)
    calA = [np.array([mf.shape_parameter(p) for p in f.polygons()]) for f in frames]
    norm = matplotlib.colors.Normalize(vmin=1.0,
                                       vmax=max(2.0, float(np.max(np.concatenate(calA)))))
    limits = lab_limits(frames)
    paths = []
    started = time.time()
    source = None
    for k, frame in enumerate(frames):
        fig = plt.figure(figsize=(13.0, 5.0))
        grid = fig.add_gridspec(2, 3, width_ratios=[1, 1, 0.9], left=0.02, right=0.93,
                                wspace=0.2, hspace=0.3)
        tissue = fig.add_subplot(grid[:, 0])
        lab = fig.add_subplot(grid[:, 1])
        phi_ax = fig.add_subplot(grid[0, 2])
        p_ax = fig.add_subplot(grid[1, 2], sharex=phi_ax)
        sig = None
        if disks:
            sig, source = pm.frame_sigmas(frame, sigma)
        polys = frame.polygons()
        cells = pm.draw_tissue(tissue, frame.lo, frame.length, polys, norm, "viridis",
                               sigmas=sig, colours=calA[k], scaled=True)
        tissue.set_title("tissue frame (box fixed)")
        pm.draw_tissue(lab, frame.lo, frame.length, polys, norm, "viridis", sigmas=sig,
                       colours=calA[k], limits=limits)
        lab.set_title(f"lab frame: box {frame.length[0]:.3g} x {frame.length[1]:.3g}")
        if growth is not None:
            upto = slice(0, k + 1)
            phi_ax.plot(steps[upto], growth["phi_patch"][:n][upto], "o-", ms=3,
                        label=r"$\phi$ patch")
            phi_ax.plot(steps[upto], growth["phi"][:n][upto], "s-", ms=3,
                        label=r"$\phi$ polygons")
            lo_phi = min(growth["phi"][:n].min(), growth["phi_patch"][:n].min())
            hi_phi = max(growth["phi"][:n].max(), growth["phi_patch"][:n].max())
            phi_ax.set_ylim(lo_phi - 0.03, hi_phi + 0.03)
            phi_ax.set_xlim(steps[0] - 0.5, steps[-1] + 0.5)
            phi_ax.legend(fontsize=8, loc="upper right")
            pm.draw_pressure(p_ax, steps[upto], growth["P"][:n][upto], P0, marker="o", ms=3)
            dev = pm.pressure_deviation(growth["P"][:n], P0)
            p_ax.set_ylim(pm.P_FLOOR / 2, max(10 * dev.max(), 1e-9))
        phi_ax.set_ylabel(r"$\phi$")
        p_ax.set_xlabel("growth step")
        p_ax.set_title(f"$P_0$ = {P0:g}", fontsize=8)
        cax = fig.add_axes([0.945, 0.15, 0.012, 0.7])
        fig.colorbar(cells, cax=cax, label=r"$\mathcal{A} = p^2/(4\pi a)$")
        title = f"growth step {int(steps[k])}"
        if growth is not None:
            title += (f":  $\\phi_{{patch}}$ = {growth['phi_patch'][k]:.3f},  "
                      f"$\\langle\\mathcal{{A}}\\rangle$ = {calA[k].mean():.3f}")
        fig.suptitle(title)
        path = os.path.join(folder, f"frame_{k:04d}.png")
        fig.savefig(path, dpi=dpi)
        plt.close(fig)
        paths.append(path)
        if progress:
            spent = time.time() - started
            left = spent / (k + 1) * (n - k - 1)
            print(f"\rrendering frame {k + 1}/{n} (growth step {int(steps[k])}), "
                  f"{spent:.0f} s, about {left:.0f} s left   ", end="", file=sys.stderr,
                  flush=True)
    if progress:
        print(file=sys.stderr)
    return paths, source


def even_size_filter():
    return "scale=trunc(iw/2)*2:trunc(ih/2)*2"


def write_mp4(folder, path, fps, ffmpeg):
    cmd = [ffmpeg, "-y", "-loglevel", "error", "-framerate", str(fps), "-i",
           os.path.join(folder, "frame_%04d.png"), "-vf", even_size_filter(),
           "-c:v", "libx264", "-pix_fmt", "yuv420p", "-movflags", "+faststart", path]
    subprocess.run(cmd, check=True)


def write_gif(folder, path, fps, ffmpeg, paths):
    if ffmpeg:
        graph = ("split[a][b];[a]palettegen=stats_mode=diff[p];"
                 "[b][p]paletteuse=dither=bayer:bayer_scale=4")
        cmd = [ffmpeg, "-y", "-loglevel", "error", "-framerate", str(fps), "-i",
               os.path.join(folder, "frame_%04d.png"), "-vf", graph, "-loop", "0", path]
        subprocess.run(cmd, check=True)
        return
    from PIL import Image
    images = [Image.open(p).convert("P", palette=Image.ADAPTIVE) for p in paths]
    images[0].save(path, save_all=True, append_images=images[1:], loop=0,
                   duration=int(1000 / fps))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="\n".join(__doc__.splitlines()[2:]))
    p.add_argument("growth", help="growth table of the run (growth.N*.txt)")
    p.add_argument("dump", help="per-vertex dump of the run (cells.N*.dump)")
    p.add_argument("--out", default="mesophyll_movie", help="prefix of <out>.mp4 and <out>.gif")
    p.add_argument("--fps", type=float, default=4, help="frames (growth steps) per second")
    p.add_argument("--dpi", type=int, default=100, help="resolution of the frames")
    p.add_argument("--P0", type=float, default=1.0e-3, help="target pressure (default 1e-3)")
    p.add_argument("--sigma", type=float, default=None,
                   help="vertex diameter where the dump has no d_sigma column")
    p.add_argument("--no-disks", action="store_true", help="draw the polygons only")
    p.add_argument("--frames", type=int, nargs="+", help="only these frames (0 = first)")
    p.add_argument("--no-mp4", action="store_true")
    p.add_argument("--no-gif", action="store_true")
    p.add_argument("--keep-frames", help="also copy the PNG frames into this folder")
    a = p.parse_args(argv)

    frames = list(mf.read_frames(a.dump))
    if not frames:
        p.error(f"{a.dump}: no complete frame")
    growth = mf.read_growth(a.growth)
    n = min(len(frames), len(growth["step"]))
    if len(frames) != len(growth["step"]):
        print(f"note: {len(frames)} dump frames, {len(growth['step'])} growth rows: "
              f"using the first {n}", file=sys.stderr)
    frames = frames[:n]
    growth = {k: v[:n] for k, v in growth.items()}
    if a.frames:
        frames = [frames[k] for k in a.frames]
        growth = {key: v[a.frames] for key, v in growth.items()}
    ffmpeg = shutil.which("ffmpeg")
    if not ffmpeg and not a.no_mp4:
        print("note: no ffmpeg (Debian: apt-get install ffmpeg): no MP4; the GIF from Pillow",
              file=sys.stderr)
    with tempfile.TemporaryDirectory() as folder:
        paths, source = render_frames(frames, growth, folder, a.P0, a.sigma, not a.no_disks,
                                      a.dpi)
        written = []
        if ffmpeg and not a.no_mp4:
            write_mp4(folder, a.out + ".mp4", a.fps, ffmpeg)
            written.append(a.out + ".mp4")
        if not a.no_gif:
            write_gif(folder, a.out + ".gif", a.fps, ffmpeg, paths)
            written.append(a.out + ".gif")
        if a.keep_frames:
            os.makedirs(a.keep_frames, exist_ok=True)
            for path in paths:
                shutil.copy(path, a.keep_frames)
            written.append(os.path.join(a.keep_frames, "frame_*.png"))
    if source:
        print(f"vertex disks: {source}")
    print(f"{len(paths)} frames: wrote " + ", ".join(written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
