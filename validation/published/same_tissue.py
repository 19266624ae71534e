"""Runs of both codes from the same state for the Fig 5 comparisons (low_bending.py,
low_beta.py): tissue_N16.data with Fig 5's parameter file, its base set (theta0_min -3 pi/20)
at P0 = 1e-5, the pressure of fig5_coarse.sweep and fig5_late.sweep."""
import argparse
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TISSUE = os.path.join(ROOT, "examples", "tissue", "tissue_N16.data")
PARAMETERS = os.path.join(ROOT, "potentials", "fig5.mesophyll")
P0 = "1e-5"
THETA0_MIN_ARG = "0.3"    # the driver multiplies it by -pi/2: theta0_min = -3 pi/20
# the package's two ways to run: with the driver's cycle, and as the sweeps run it (its defaults)
PACKAGE_MODES = {"package_published_rules": ["-var", "rules", "published", "-var",
                                             "break_start", "2", "-var", "steer", "mass"],
                 "package_sweep": []}


def arguments(doc, name):
    """The options both comparisons take: the driver, lmp, the work folder, the CSV."""
    p = argparse.ArgumentParser(description=" ".join(doc.split("\n\n")[0].split()))
    p.add_argument("binary", help="the driver build.sh made")
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--work", default=os.path.join("/tmp", name))
    p.add_argument("--out", default=os.path.join(HERE, name + ".csv"))
    return p


def driver_input(work):
    """Write the tissue as the driver's input file (make_input.py) into work; return its path."""
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "tissue_N16.input")
    subprocess.run([sys.executable, os.path.join(HERE, "make_input.py"), TISSUE, path],
                   check=True, stdout=subprocess.DEVNULL)
    return path


def run_once(command, record, complete, resume, **kw):
    """Run command, and write it into record once it has succeeded. With resume, skip it where
    record holds the same command and complete() says its outputs are whole: a comparison
    stopped and started again reruns only what it had not finished. Reuse trusts the record:
    after a change to the binaries or the input files, start without resume."""
    line = " ".join(command) + "\n"
    if resume and os.path.exists(record) and open(record).read() == line and complete():
        return
    if os.path.exists(record):
        os.remove(record)
    subprocess.run(command, check=True, **kw)
    with open(record, "w") as f:
        f.write(line)


def published(binary, lmp, work, folder, seed, run_options, resume=False):
    """Run the driver (run.py) into work/folder with Fig 5's theta0_min and P0 and the given
    run.py options; return the rows of its CSV (run.py writes it once the run is measured)."""
    out = os.path.join(work, folder + ".csv")
    command = [sys.executable, os.path.join(HERE, "run.py"), binary,
               os.path.join(work, "tissue_N16.input"), seed, out, "--work",
               os.path.join(work, folder), "--lmp", lmp, "--data", TISSUE,
               "--set", f"t0_min={THETA0_MIN_ARG}", "--set", f"P0={P0}"] + run_options
    run_once(command, out + ".command", lambda: os.path.exists(out), resume,
             stdout=subprocess.DEVNULL)
    return list(csv.DictReader(open(out)))


def package(lmp, work, folder, mode, variables, resume=False):
    """Run in.mesophyll in work/folder with Fig 5's base set at P0, ftol 1e-11, no restart
    files, the mode's variables and the given ones ({name: value}); return the folder."""
    folder = os.path.join(work, folder)
    os.makedirs(folder, exist_ok=True)
    command = [lmp, "-in", os.path.join(ROOT, "examples", "mesophyll", "in.mesophyll"),
               "-var", "N", "16", "-var", "tissue", TISSUE, "-var", "parameters", PARAMETERS,
               "-var", "set", "base", "-var", "P0", P0, "-var", "ftol", "1e-11"]
    for name, value in variables.items():
        command += ["-var", name, value]
    command += ["-var", "restart_every", "0", "-log", "log.lammps", "-screen", "none"] + \
        PACKAGE_MODES[mode]
    log = os.path.join(folder, "log.lammps")
    run_once(command, os.path.join(folder, "command.txt"),
             lambda: os.path.exists(log) and "Total wall time:" in open(log).read(), resume,
             cwd=folder)
    return folder


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        w.writerows(rows)
