"""Runs of both codes from the same state for the comparisons with the published code
(low_bending.py and low_beta.py for Fig 5, high_lambda.py and growth_per_step.py for Fig 4,
high_pressure.py for Fig 6):
tissue_N16.data with a figure's parameter file and its base set (theta0_min -3 pi/20 in both) at
the pressure of that figure's sweeps."""
import argparse
import concurrent.futures
import csv
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TISSUE = os.path.join(ROOT, "examples", "tissue", "tissue_N16.data")
# each figure's parameter file and the pressure its sweeps run at
FIGURES = {"fig5": ("fig5.mesophyll", "1e-5"),    # fig5_coarse.sweep and fig5_late.sweep
           "fig4": ("fig4.mesophyll", "1e-6"),    # fig4.sweep (the caption's pressure)
           "fig6": ("fig6.mesophyll", "1e-1")}    # fig6.sweep's highest (high_pressure.py)
THETA0_MIN_ARG = "0.3"    # the driver multiplies it by -pi/2: theta0_min = -3 pi/20
# the package's two ways to run: with the driver's cycle, and as the sweeps run it (its defaults)
PACKAGE_MODES = {"package_published_rules": ["-var", "rules", "published", "-var",
                                             "break_start", "2", "-var", "steer", "mass"],
                 "package_sweep": []}


def arguments(doc, name):
    """The options every comparison takes: the driver, lmp, the work folder, the CSV."""
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


def published(binary, lmp, work, folder, seed, run_options, resume=False, figure="fig5"):
    """Run the driver (run.py) into work/folder with the figure's theta0_min and P0 and the given
    run.py options; return the rows of its CSV (run.py writes it once the run is measured)."""
    out = os.path.join(work, folder + ".csv")
    command = [sys.executable, os.path.join(HERE, "run.py"), binary,
               os.path.join(work, "tissue_N16.input"), seed, out, "--work",
               os.path.join(work, folder), "--lmp", lmp, "--data", TISSUE,
               "--set", f"t0_min={THETA0_MIN_ARG}", "--set",
               f"P0={FIGURES[figure][1]}"] + run_options
    run_once(command, out + ".command", lambda: os.path.exists(out), resume,
             stdout=subprocess.DEVNULL)
    return list(csv.DictReader(open(out)))


def package(lmp, work, folder, mode, variables, resume=False, figure="fig5", tissue=TISSUE):
    """Run in.mesophyll in work/folder from tissue (16 cells) with the figure's base set at its
    P0, ftol 1e-11, no restart files, the mode's variables and the given ones ({name: value});
    return the folder."""
    parameters, p0 = FIGURES[figure]
    folder = os.path.join(work, folder)
    os.makedirs(folder, exist_ok=True)
    command = [lmp, "-in", os.path.join(ROOT, "examples", "mesophyll", "in.mesophyll"),
               "-var", "N", "16", "-var", "tissue", tissue, "-var", "parameters",
               os.path.join(ROOT, "potentials", parameters), "-var", "set", "base", "-var", "P0",
               p0, "-var", "ftol", "1e-11"]
    for name, value in variables.items():
        command += ["-var", name, value]
    command += ["-var", "restart_every", "0", "-log", "log.lammps", "-screen", "none"] + \
        PACKAGE_MODES[mode]
    log = os.path.join(folder, "log.lammps")
    run_once(command, os.path.join(folder, "command.txt"),
             lambda: os.path.exists(log) and "Total wall time:" in open(log).read(), resume,
             cwd=folder)
    return folder


# fix dpoly/check's count of overlapping cell outlines with the first pair it names (two cells,
# or a cell and its own periodic image), and in.mesophyll's line after minimum 2
PAIRS = re.compile(r"(\d+) pairs of cells interpenetrate "
                   r"\(first: (?:cells (\d+) and (\d+)|cell (\d+) and its periodic image)\)")
PROGRESS = re.compile(r"^growth step 2/2: .* phi_patch (\S+) <calA> (\S+) <z> (\S+)")


def pairs_in(line):
    """(count, 'a-b') of fix dpoly/check's line ('a-image' for a cell and its periodic image),
    (0, '') where it names none."""
    m = PAIRS.search(line or "")
    if not m:
        return 0, ""
    first = f"{m.group(2)}-{m.group(3)}" if m.group(2) else f"{m.group(4)}-image"
    return int(m.group(1)), first


def published_first_step(binary, lmp, work, folder, driver_settings, figure="fig5"):
    """The driver's frame 1 (run.py --steps 1: the relaxed input grown once and minimized at P0;
    no bond breaks before it, so the seed does not matter), measured by in.measure: [phi_patch,
    calA, z, interpenetrating pairs, first pair]. driver_settings: run.py's --set NAME=VALUE."""
    options = ["--steps", "1"]
    for setting in driver_settings:
        options += ["--set", setting]
    rows = published(binary, lmp, work, folder, "20261122", options, figure=figure)
    frame = next(r for r in rows if r["growth_steps"] == "1")
    # in.measure's fix dpoly/check lines, one per frame: the last is frame 1's
    checks = [line for line in open(os.path.join(work, folder, "log.measure"))
              if line.startswith("fix dpoly/check:")]
    count, first = pairs_in(checks[-1])
    if count != int(frame["interpenetrating_pairs"]):
        sys.exit(f"{work}/{folder}: the check line and the CSV disagree on the pairs")
    return [frame["phi_patch"], frame["calA"], frame["z"], count, first]


def package_first_step(lmp, work, folder, mode, variables, figure="fig5", tissue=TISSUE):
    """in.mesophyll's minimum 2, the first after a growth step (-var steps 2), in the mode with
    the given variables: [phi_patch, calA, z, interpenetrating pairs, first pair]."""
    folder = package(lmp, work, folder, mode, dict(variables, steps="2"), figure=figure,
                     tissue=tissue)
    log = open(os.path.join(folder, "log.lammps")).read().splitlines()
    state = next(PROGRESS.match(line).groups() for line in log if PROGRESS.match(line))
    check = next(line for line in log if line.startswith("fix dpoly/check: minimum 2 "))
    return list(state) + list(pairs_in(check))


def compare_first_steps(doc, name, label, values, driver_settings, package_variables,
                        figure="fig5"):
    """The main() of a first-step comparison (low_bending.py, high_lambda.py, growth_per_step.py):
    for each value of the parameter label, the driver's frame 1 with driver_settings(value)
    (run.py --set items) and the package's minimum 2 in each mode with package_variables(value,
    mode) (in.mesophyll variables); writes the CSV --out, prints the table and returns the
    parsed options."""
    a = arguments(doc, name).parse_args()
    lmp, binary = os.path.abspath(a.lmp), os.path.abspath(a.binary)
    driver_input(a.work)
    rows = []
    for value in values:
        rows.append([value, "published"] + published_first_step(
            binary, lmp, a.work, f"published_{value}", driver_settings(value), figure))
        for mode in PACKAGE_MODES:
            rows.append([value, mode] + package_first_step(
                lmp, a.work, f"{mode}_{value}", mode, package_variables(value, mode), figure))
        print(f"{label} {value}: done", flush=True)
    write_csv(a.out, [label, "code", "phi_patch", "calA", "z", "interpenetrating_pairs",
                      "first_pair"], rows)
    width = max(len(c) for c in PACKAGE_MODES)
    first = max([len(label)] + [len(v) for v in values])
    print(f"{label:{first}} {'code':{width}} phi_patch calA   z     pairs (first)")
    for r in rows:
        print(f"{r[0]:{first}} {r[1]:{width}} {float(r[2]):.4f}    {float(r[3]):.4f} "
              f"{float(r[4]):.3f} {r[5]} ({r[6] or '-'})")
    print(f"wrote {a.out}")
    return a


def run_all(jobs, one, tasks):
    """[one(task) for task in tasks], jobs at a time. A run that fails, or Ctrl-C, cancels the
    runs not yet started (a free worker may have picked up the next one already); the ones under
    way finish, then the error is raised."""
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        futures = [pool.submit(one, task) for task in tasks]
        try:
            return [future.result() for future in futures]
        except BaseException:
            pool.shutdown(wait=True, cancel_futures=True)
            raise


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        w.writerows(rows)
