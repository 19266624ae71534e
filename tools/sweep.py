#!/usr/bin/env python3
"""Parameter sweeps of the development protocol as one LAMMPS job on partitions.

    tools/sweep.py plan SWEEP_FILE DIR         write the run list of a sweep into DIR
    cd DIR && mpirun -np P lmp -partition Px1 -in ROOT/examples/sweep/in.sweep
    tools/sweep.py summary DIR [--reference FILE] [--split POROSITY]   one row per run

plan reads a sweep file (format: doc/Howto_sweep.rst) and writes DIR/plan.lmp (the number of
runs and the commands in.sweep calls), DIR/runs.csv (one row per run: its grid point, seed and
initial tissue) and, per run, DIR/runs/<id>/run.lmp (the variables of the protocol,
examples/mesophyll/in.mesophyll, for that run, after deleting those a previous run of the same
partition left) and run.json. in.sweep hands the runs out to the partitions with a uloop
variable; before each run it calls `sweep.py state` and after it `sweep.py finish` in the run's
folder:

    state    writes state.lmp: skip a finished run, resume from the newest restart file below
             the last growth step, or start afresh; a run whose previous attempt stopped with a
             LAMMPS error is marked finished with status error and skipped (else a resumed sweep
             would stop at it again); stamps the start time
    finish   stamps the end time and writes the marker file `finished` (a run is finished only
             once that file exists: a killed run never has it)

summary reads every run's growth table, log and marker and writes DIR/summary.csv and
DIR/points.csv (ensemble mean and standard deviation per grid point over the runs with status
ok, with --accept unconverged those too) and prints the table. Per run: status (ok;
unconverged: minima that did not converge or missed P0; failed: minima with tangled or inverted
rings, non-finite values or a packing fraction out of range, which are no result; error: LAMMPS
stopped; unfinished), growth steps, delta_A early and late (RMS difference of the mean shape
parameter from reference points (porosity, calA), each matched with the growth step of nearest
porosity phi_max - phi_patch, phi_max = 0.975), delta_phi_plus, z and phi_patch at the step
nearest phi_patch = 0.5, failed checks, attempts, wall and loop seconds. Standard library only.
"""
import argparse
import csv
import functools
import itertools
import json
import math
import os
import re
import shlex
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesophyll_run  # noqa: E402  (the log readers)
from lammps_data import DataFile  # noqa: E402

PHI_MAX = 0.975                  # the simulations' largest packing fraction (paper, Methods)
DEFAULT_REFERENCE = os.path.join(ROOT, "examples", "sweep", "reference_paper_text.txt")
# the variables in.sweep itself keeps between runs: a protocol must not define them
SWEEP_VARIABLES = {"runs", "run", "sweep_state", "sweep_finish", "protocol", "skip",
                   "resuming", "resume_from", "sweep_note"}
# fix dpoly/check problems after which a minimum is not a state of the model at all; the other
# two kinds (not converged, P off P0), as fix dpoly/check words them, make a run "unconverged"
CONVERGENCE_PROBLEMS = ("the minimizer stopped without converging", "|P - P0|/P0 =")


# --- the sweep file ------------------------------------------------------------------------------

class SweepFile:
    """A sweep file: keyword lines, '#' comments; relative paths are relative to the file."""

    KEYWORDS = {"name", "protocol", "parameters", "set", "vary", "point", "seeds", "tissue",
                "fixed", "growth", "part_of"}

    def __init__(self, path):
        self.path = path
        here = os.path.dirname(os.path.abspath(path))
        self.name = os.path.splitext(os.path.basename(path))[0]
        self.protocol = os.path.join(ROOT, "examples", "mesophyll", "in.mesophyll")
        self.parameters = os.path.join(ROOT, "potentials", "arabidopsis.mesophyll")
        self.set = "default"
        self.axes, self.points, self.seeds, self.tissues, self.fixed = [], [], [], [], {}
        self.growth = None
        self.part_of = None    # the sweep file of which this one plans a part
        with open(path) as f:
            for number, line in enumerate(f, 1):
                words = line.split("#")[0].split()
                if not words:
                    continue
                key, values = words[0], words[1:]
                where = f"{path}:{number}"
                if key not in self.KEYWORDS:
                    sys.exit(f"{where}: unknown keyword '{key}' (known: "
                             f"{' '.join(sorted(self.KEYWORDS))})")
                if not values:
                    sys.exit(f"{where}: '{key}' needs a value")
                if key == "name":
                    self.name = values[0]
                elif key in ("protocol", "parameters", "part_of"):
                    setattr(self, key, os.path.normpath(os.path.join(here, values[0])))
                elif key == "set":
                    self.set = values[0]
                elif key == "vary":
                    if len(values) < 2:
                        sys.exit(f"{where}: 'vary NAME VALUE...' needs a name and a value")
                    self.axes.append((values[0], values[1:]))
                elif key == "point":
                    point = []
                    for pair in values:
                        if "=" not in pair:
                            sys.exit(f"{where}: point takes NAME=VALUE pairs, not '{pair}'")
                        point.append(tuple(pair.split("=", 1)))
                    self.points.append(point)
                elif key == "seeds":
                    for seed in values:
                        if not seed.isdigit() or int(seed) < 1:
                            sys.exit(f"{where}: a seed must be a positive integer, not '{seed}'")
                    self.seeds += values
                elif key == "tissue":
                    self.tissues += [os.path.normpath(os.path.join(here, v)) for v in values]
                elif key == "fixed":
                    if len(values) % 2:
                        sys.exit(f"{where}: 'fixed' takes NAME VALUE pairs")
                    self.fixed.update(zip(values[::2], values[1::2]))
                elif key == "growth":
                    try:
                        self.growth = (float(values[0]),
                                       int(values[1]) if len(values) > 1 else None)
                    except ValueError:
                        sys.exit(f"{where}: 'growth TOTAL [MAX_STEPS]' takes a number and an "
                                 f"integer, not '{' '.join(values)}'")
                    if not self.growth[0] > 0 or (self.growth[1] or 1) < 1:
                        sys.exit(f"{where}: the total growth and the step cap must be > 0, not "
                                 f"'{' '.join(values)}'")
        files = [("protocol", self.protocol), ("parameters", self.parameters)]
        if self.part_of:
            files.append(("whole sweep's (part_of)", self.part_of))
        for what, path_ in files:
            if not os.path.isfile(path_):
                sys.exit(f"{self.path}: the {what} file {path_} does not exist")
        if not self.tissues:
            self.tissues = [os.path.join(os.path.dirname(self.protocol), "tissue_N64.data")]
        for tissue in self.tissues:
            if not os.path.isfile(tissue):
                sys.exit(f"{self.path}: the tissue {tissue} does not exist")
        if not self.seeds:
            sys.exit(f"{self.path}: no seeds (a line 'seeds 1 2 3')")

    def grid(self):
        """The grid points: the product of the vary axes, then the extra points, each a list of
        (name, value); one empty point without either."""
        names = [name for name, _ in self.axes]
        grid = [list(zip(names, values)) for values in
                itertools.product(*[values for _, values in self.axes])] if self.axes else []
        for point in self.points:
            if point not in grid:
                grid.append(point)
        return grid or [[]]


def protocol_variables(protocol):
    """Every variable the protocol file itself defines (not those of files it includes: a
    protocol that includes files must define the variables a sweep sets in its own lines)."""
    names, text = set(), open(protocol).read()
    for match in re.finditer(r"^\s*variable\s+(\w+)", text, re.MULTILINE):
        names.add(match.group(1))
    return names


def protocol_defaults(protocol):
    """{name: value} of the protocol's index variables: what a run that leaves one unset takes
    (a sweep file that does not mention tmaxadapt runs with in.mesophyll's 'no')."""
    text = open(protocol).read()
    return dict(re.findall(r"^\s*variable\s+(\w+)\s+index\s+(\S+)", text, re.MULTILINE))


def parameter_sets(path):
    """{set: {name: value}} of a parameter file (doc/mesophyll_parameters.rst)."""
    sets = {}
    with open(path) as f:
        if next(f, None) is None:    # the metadata line
            sys.exit(f"{path}: an empty parameter file")
        for line in f:
            words = line.split("#")[0].split()
            if words:
                sets.setdefault(words[0], {}).update(zip(words[1::2], words[2::2]))
    return sets


@functools.lru_cache(maxsize=None)
def cells_in(tissue):
    """The number of cells (molecule IDs) of a data file, read once per file: a grid plans
    hundreds of runs from the same few tissues, and a part plans its whole's runs again."""
    atoms = DataFile(tissue).sections.get("Atoms", [])
    cells = {words[1] for words in atoms}
    if not cells:
        sys.exit(f"{tissue}: no Atoms in the data file")
    return len(cells)


def planned(folder):
    """(name, sweep file, protocol) of a planned folder, read from its plan.lmp: the first line
    gives the sweep's name (whatever the folder is called) and its file relative to the package's
    folder; the protocol line gives the file every run includes, relative to a run's folder
    (runs/<run>, all at one depth)."""
    plan_file = os.path.join(folder, "plan.lmp")
    if not os.path.isfile(plan_file):
        sys.exit(f"{folder} has no plan.lmp: not a folder of tools/sweep.py plan")
    with open(plan_file) as f:
        found = re.match(r"# sweep (\S+) from (.+): \d+ runs ", f.readline())
        protocol = next((words[3] for words in map(str.split, f)
                         if words[:3] == ["variable", "protocol", "string"]), None)
    if found is None:
        sys.exit(f"{folder}/plan.lmp names no sweep: not a folder of tools/sweep.py plan")
    if protocol is None:
        sys.exit(f"{folder}/plan.lmp names no protocol: not a folder of tools/sweep.py plan")
    return (found.group(1), os.path.normpath(os.path.join(ROOT, found.group(2))),
            os.path.normpath(os.path.join(folder, "runs", "run", protocol)))


def path_from(folder, path):
    """path as the run folder sees it: relative when both lie in one tree (the package's, or a
    sweep folder's next to its files), so that the two move together; else absolute."""
    folder, path = os.path.abspath(folder), os.path.abspath(path)
    return path if os.path.commonpath([folder, path]) == os.sep else os.path.relpath(path, folder)


def point_label(point):
    return " ".join(f"{name}={value}" for name, value in point) or "base"


def step_cap(growth, delta_a):
    """The growth-step cap a sweep's 'growth A [MAX]' gives a run at delta_a: enough steps to
    grow every cell's a0 by A, at most MAX."""
    steps = math.ceil(growth[0] / delta_a - 1e-9)
    return min(steps, growth[1] or steps)


def planned_runs(sweep_file):
    """What a sweep file plans, without writing anything: (the SweepFile, the names a run may
    set, the runs in order). Each run is {id, point, point_values, tissue, seed, values}, values
    holding its variables but the paths of its tissue and parameter file. Exits naming the
    problem on a bad sweep file."""
    sweep = SweepFile(sweep_file)
    sets = parameter_sets(sweep.parameters)
    if sweep.set not in sets:
        sys.exit(f"{sweep.path}: the set '{sweep.set}' is not in {sweep.parameters} "
                 f"(it has: {' '.join(sets)})")
    parameter_names = set().union(*sets.values())
    variables = protocol_variables(sweep.protocol)
    clash = variables & SWEEP_VARIABLES
    if clash:
        sys.exit(f"{sweep.protocol} defines {', '.join(sorted(clash))}, which in.sweep keeps "
                 f"between runs")
    known = variables | parameter_names
    grid = sweep.grid()
    for name in [n for point in grid for n, _ in point] + list(sweep.fixed):
        if name not in known:
            sys.exit(f"{sweep.path}: '{name}' is neither a variable of {sweep.protocol} nor a "
                     f"parameter of {sweep.parameters}")
        if name in ("N", "tissue", "seed", "parameters", "resume"):
            sys.exit(f"{sweep.path}: '{name}' is set by the sweep itself (seeds, tissue, "
                     f"parameters lines), not by vary, point or fixed")
    for name, value in [(n, v) for point in grid for n, v in point] + list(sweep.fixed.items()):
        if name == "set" and value not in sets:
            sys.exit(f"{sweep.path}: the set '{value}' is not in {sweep.parameters} "
                     f"(it has: {' '.join(sets)})")
        if name == "steps" and not (value.isdigit() and int(value) > 0):
            sys.exit(f"{sweep.path}: steps must be a whole number above 0, not '{value}'")
    if "steps" in sweep.fixed and sweep.growth:
        sys.exit(f"{sweep.path}: give either 'growth' or 'fixed steps', not both")

    runs = []
    for point in grid:
        for tissue in sweep.tissues:
            for seed in sweep.seeds:
                values = dict(sweep.fixed)
                values.update(point)
                values.update(seed=seed, N=str(cells_in(tissue)))
                if sweep.growth:
                    delta_a = float(values.get("delta_a", sets[values.get("set", sweep.set)]
                                               .get("delta_a", "nan")))
                    if not delta_a > 0:
                        sys.exit(f"{sweep.path}: 'growth' needs delta_a > 0, not {delta_a}")
                    values["steps"] = str(step_cap(sweep.growth, delta_a))
                values.setdefault("set", sweep.set)
                runs.append({"point": point_label(point), "point_values": dict(point),
                             "tissue": tissue, "seed": seed, "values": values})
    width = len(str(len(runs)))
    for k, run in enumerate(runs, 1):
        run["id"] = f"{k:0{width}d}"
    if sweep.part_of:
        check_part(sweep, runs)
    return sweep, known, runs


def run_key(sweep, run):
    """What makes two planned runs the same run, whichever sweep file plans them (values as
    written: a part must write 0.01 where its whole does, not 1e-2)."""
    return (sweep.protocol, sweep.parameters, run["tissue"],
            tuple(sorted(run["values"].items())))


def check_part(part, runs):
    """A part of a sweep (part_of) plans only runs that the whole plans too, so that parts run
    in different sessions or on different machines add up to the whole; exits naming the first
    run that the whole does not have."""
    if os.path.abspath(part.part_of) == os.path.abspath(part.path):
        sys.exit(f"{part.path}: a sweep cannot be a part of itself (part_of)")
    if SweepFile(part.part_of).part_of:    # before planning it: a cycle would not end
        sys.exit(f"{part.path}: its whole {part.part_of} is a part of another sweep itself")
    whole, _, whole_runs = planned_runs(part.part_of)
    keys = {run_key(whole, run) for run in whole_runs}
    for run in runs:
        if run_key(part, run) not in keys:
            sys.exit(f"{part.path}: run {run['id']} ({run['point']}, seed {run['seed']}, tissue "
                     f"{os.path.basename(run['tissue'])}) is not a run of the whole sweep "
                     f"{part.part_of} (part_of): a part plans only the whole's runs")


def plan(args):
    sweep, known, runs = planned_runs(args.sweep_file)
    planned = {run["id"] for run in runs}
    runs_dir = os.path.join(args.dir, "runs")
    stale = sorted(d for d in (os.listdir(runs_dir) if os.path.isdir(runs_dir) else [])
                   if d not in planned and os.path.exists(os.path.join(runs_dir, d, "run.json")))
    if stale:
        sys.exit(f"{runs_dir} holds runs {', '.join(stale)} that this plan does not have (an "
                 f"earlier, other plan); plan a changed sweep into a new folder")
    os.makedirs(runs_dir, exist_ok=True)
    tool = os.path.abspath(__file__)
    for run in runs:
        folder = os.path.join(args.dir, "runs", run["id"])
        os.makedirs(folder, exist_ok=True)
        values = dict(run["values"], tissue=path_from(folder, run["tissue"]),
                      parameters=path_from(folder, sweep.parameters))
        record = {"sweep": sweep.name, "id": run["id"], "point": run["point"],
                  "point_values": run["point_values"], "seed": run["seed"],
                  "tissue": path_from(ROOT, run["tissue"]), "N": int(values["N"]),
                  "steps": int(values.get("steps", 0)) or None, "variables": values}
        record_path = os.path.join(folder, "run.json")
        if os.path.exists(record_path):
            old = json.load(open(record_path))
            if old != record:
                sys.exit(f"{folder} holds run {old['id']} of another plan ({old['point']}, "
                         f"seed {old['seed']}); plan a changed sweep into a new folder")
        with open(record_path, "w") as f:
            json.dump(record, f, indent=1, sort_keys=True)
        with open(os.path.join(folder, "run.lmp"), "w") as f:
            f.write(f"# run {run['id']} of sweep {sweep.name}: {run['point']}, seed {run['seed']}"
                    f", tissue {record['tissue']} (written by tools/sweep.py plan)\n")
            f.write("# the variables a previous run of this partition defined go first\n")
            for name in sorted(known | {"resume"}):
                f.write(f"variable {name} delete\n")
            for name, value in sorted(values.items()):
                f.write(f"variable {name} index {value}\n")
    with open(os.path.join(args.dir, "runs.csv"), "w", newline="") as f:
        axes = sorted({n for run in runs for n in run["point_values"]})
        out = csv.writer(f)
        out.writerow(["run", "point"] + axes + ["seed", "tissue", "N", "steps"])
        for run in runs:
            out.writerow([run["id"], run["point"]] + [run["point_values"].get(a, "")
                                                      for a in axes]
                         + [run["seed"], path_from(ROOT, run["tissue"]),
                            run["values"]["N"], run["values"].get("steps", "")])
    python = shlex.quote(sys.executable or "python3")
    with open(os.path.join(args.dir, "plan.lmp"), "w") as f:
        f.write(f"# sweep {sweep.name} from {os.path.relpath(sweep.path, ROOT)}: {len(runs)} runs "
                f"(written by tools/sweep.py plan)\n")
        f.write(f"variable runs equal {len(runs)}\n")
        # relative to a run's folder, the working directory when in.sweep includes it
        first = os.path.abspath(os.path.join(args.dir, "runs", runs[0]["id"]))
        f.write(f"variable protocol string {path_from(first, sweep.protocol)}\n")
        f.write(f'variable sweep_state string "{python} {tool} state"\n')
        f.write(f'variable sweep_finish string "{python} {tool} finish"\n')
    print(f"{len(runs)} runs of sweep {sweep.name} ({len(sweep.grid())} points x "
          f"{len(sweep.tissues)} tissues x {len(sweep.seeds)} seeds) in {args.dir}")


# --- before and after each run (in its folder) ----------------------------------------------------

ATTEMPT = "sweep: attempt "    # in.sweep prints it into the run's log at every start


def last_attempt_error(log_path):
    """The ERROR line of the last attempt logged, or None."""
    if not os.path.exists(log_path):
        return None
    text = open(log_path, errors="replace").read()
    last = text.rsplit(ATTEMPT, 1)[-1]    # the whole log before the first attempt
    for line in last.splitlines():
        if line.startswith("ERROR"):
            return line.strip()
    return None


def restart_files(cells):
    found = []
    for name in os.listdir("."):
        m = re.fullmatch(rf"restart\.N{cells}\.(\d+)", name)
        if m:
            found.append((int(m.group(1)), name))
    return sorted(found)


def state(args):
    record = json.load(open("run.json"))
    skip, resume, note = 0, None, ""
    if os.path.exists("finished"):
        skip, note = 1, "finished before: skipped"
    else:
        error = last_attempt_error("log.lammps")
        if error:
            with open("finished", "w") as f:
                f.write(f"error {error}\n")
            skip, note = 1, f"its last attempt stopped with {error}: marked as error, skipped"
        else:
            steps = record["steps"]
            usable = [(k, name) for k, name in restart_files(record["N"])
                      if steps is None or k < steps]
            if usable:
                resume = usable[-1][1]
                note = f"resumes from {resume}"
            else:
                note = "starts"
            with open("times.txt", "a") as f:
                f.write(f"start {time.time():.3f}\n")
    # LAMMPS would expand a $, and a quote of either kind in the note (an error message such as
    # fire/nph's "the largest force's cell") would end or unbalance the string; LAMMPS counts
    # triple quotes on the comment line too
    printable = note.replace('"', "`").replace("'", "`").replace("$", "")
    with open("state.lmp", "w") as f:
        f.write(f"# run {record['id']}: {printable} (written by tools/sweep.py state)\n")
        f.write(f"variable skip equal {skip}\n")
        f.write(f"variable resuming equal {int(resume is not None)}\n")
        f.write(f"variable resume_from string {resume or 'none'}\n")
        f.write(f'variable sweep_note string "{printable}"\n')


def finish(args):
    with open("times.txt", "a") as f:
        f.write(f"end {time.time():.3f}\n")
    with open("finished.tmp", "w") as f:
        f.write("finished\n")
    os.replace("finished.tmp", "finished")


# --- summary -------------------------------------------------------------------------------------

def read_reference(path, split):
    """[(porosity, calA, stage)] of a reference file: porosity calA [early|late] per line."""
    if not os.path.isfile(path):
        sys.exit(f"the reference file {path} does not exist")
    points = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split("#")[0].split()
            if not words:
                continue
            try:
                porosity, calA = float(words[0]), float(words[1])
            except (ValueError, IndexError):
                sys.exit(f"{path}:{number}: expected 'porosity calA [early|late]', got "
                         f"'{line.strip()}'")
            stage = words[2] if len(words) > 2 else ("early" if porosity < split else "late")
            if stage not in ("early", "late"):
                sys.exit(f"{path}:{number}: the stage must be early or late, not '{stage}'")
            points.append((porosity, calA, stage))
    if not points:
        sys.exit(f"{path}: no reference points")
    return points


def delta_A(growth, reference, stage):
    """(RMS of mean calA minus the reference's, each point matched with the growth step of
    nearest porosity; the largest porosity distance between a point and its step), or
    (None, None) without points of that stage. The distance shows a run that never came near a
    point's porosity (a compacting run): its delta_A then compares other stages of growth."""
    porosity = [PHI_MAX - phi for phi in growth["phi_patch"]]
    squares, gap = [], 0.0
    for p_ref, calA_ref, s in reference:
        if s != stage:
            continue
        k = min(range(len(porosity)), key=lambda i: abs(porosity[i] - p_ref))
        squares.append((growth["calA"][k] - calA_ref) ** 2)
        gap = max(gap, abs(porosity[k] - p_ref))
    if not squares:
        return None, None
    return math.sqrt(sum(squares) / len(squares)), gap


def nearest_half(growth):
    k = min(range(len(growth["phi_patch"])), key=lambda i: abs(growth["phi_patch"][i] - 0.5))
    return growth["z"][k], growth["phi_patch"][k]


def read_times(path):
    """(wall seconds of the finishing attempt, attempts) from times.txt."""
    if not os.path.exists(path):
        return None, 0
    # a line cut short by a kill is passed over
    stamps = [words for words in (line.split() for line in open(path)) if len(words) == 2]
    starts = [float(t) for kind, t in stamps if kind == "start"]
    if stamps and stamps[-1][0] == "end" and starts:
        return float(stamps[-1][1]) - starts[-1], len(starts)
    return None, len(starts)


def summarize_run(folder, reference):
    record = json.load(open(os.path.join(folder, "run.json")))
    row = {"run": record["id"], "point": record["point"], "seed": record["seed"],
           "tissue": record["tissue"], "N": record["N"], "steps_planned": record["steps"]}
    row.update({f"value:{k}": v for k, v in record["point_values"].items()})
    log = os.path.join(folder, "log.lammps")
    text = open(log, errors="replace").read() if os.path.exists(log) else ""
    checks = mesophyll_run.check_lines(text)
    failures = [c for c in checks if c.failed]
    invalid = [c for c in failures
               if any(part and not part.startswith(CONVERGENCE_PROBLEMS)
                      for part in c.problems.split("; "))]
    table = os.path.join(folder, f"growth.N{record['N']}.txt")
    growth = mesophyll_run.growth_table(table) if os.path.exists(table) else {}
    marker = os.path.join(folder, "finished")
    finished = open(marker).read().strip() if os.path.exists(marker) else None
    steps = len(growth.get("step", []))
    finite = all(math.isfinite(x) for column in growth.values() for x in column)
    error = last_attempt_error(log) if finished is None else None
    if error:    # a LAMMPS error stopped the job; the summary came before the next start
        finished = f"error {error}"    # marked it
    if finished is None:
        status = "unfinished"
    elif finished.startswith("error"):
        status = "error"
    elif invalid or not finite or steps == 0:
        status = "failed"
    elif failures:
        status = "unconverged"
    else:
        status = "ok"
    wall, attempts = read_times(os.path.join(folder, "times.txt"))
    row.update(status=status, steps=steps, failed_checks=len(failures),
               first_failure=(finished if status == "error" else
                              f"minimum {failures[0].minimum}: {failures[0].problems}"
                              if failures else ""),
               attempts=attempts, wall_s=wall,
               loop_s=sum(loop.seconds for loop in mesophyll_run.loop_times(text)))
    if steps and finite:
        z, phi = nearest_half(growth)
        (dA_early, gap_early), (dA_late, gap_late) = (delta_A(growth, reference, stage)
                                                      for stage in ("early", "late"))
        row.update(delta_A_early=dA_early, delta_A_late=dA_late,
                   porosity_gap_early=gap_early, porosity_gap_late=gap_late,
                   delta_phi_plus=growth["dphi_plus"][-1], z_half=z, phi_half=phi,
                   phi_final=growth["phi_patch"][-1], calA_final=growth["calA"][-1])
    return row


COLUMNS = ["run", "point", "seed", "tissue", "N", "status", "steps", "steps_planned",
           "delta_A_early", "delta_A_late", "porosity_gap_early", "porosity_gap_late",
           "delta_phi_plus", "z_half", "phi_half", "phi_final",
           "calA_final", "failed_checks", "attempts", "wall_s", "loop_s", "first_failure"]
STATS = ["delta_A_early", "delta_A_late", "delta_phi_plus", "z_half", "phi_half", "phi_final"]


def mean_std(values):
    values = [v for v in values if v is not None]
    if not values:
        return None, None
    mean = sum(values) / len(values)
    std = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1)) \
        if len(values) > 1 else None
    return mean, std


def summary(args):
    reference = read_reference(args.reference, args.split)
    if not os.path.isdir(os.path.join(args.dir, "runs")):
        sys.exit(f"{args.dir} has no runs/ folder: plan a sweep into it first (sweep.py plan)")
    folders = sorted(os.path.join(args.dir, "runs", d)
                     for d in os.listdir(os.path.join(args.dir, "runs")))
    rows = [summarize_run(folder, reference) for folder in folders
            if os.path.exists(os.path.join(folder, "run.json"))]
    axes = sorted({k for row in rows for k in row if k.startswith("value:")})
    fmt = lambda v: "" if v is None else (f"{v:.6g}" if isinstance(v, float) else v)  # noqa
    with open(os.path.join(args.dir, "summary.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(COLUMNS[:2] + [a[6:] for a in axes] + COLUMNS[2:])
        for row in rows:
            out.writerow([fmt(row.get(c)) for c in COLUMNS[:2] + axes + COLUMNS[2:]])
    points = {}
    for row in rows:
        points.setdefault(row["point"], []).append(row)
    with open(os.path.join(args.dir, "points.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["point"] + [a[6:] for a in axes] + ["runs", "ok", "unconverged", "failed",
                                                          "error", "unfinished"]
                     + [f"{s}_{m}" for s in STATS for m in ("mean", "std")])
        for label, group in points.items():
            ok = [r for r in group if r["status"] in args.accept]
            counts = [sum(r["status"] == s for r in group)
                      for s in ("ok", "unconverged", "failed", "error", "unfinished")]
            stats = [fmt(x) for s in STATS for x in mean_std([r.get(s) for r in ok])]
            out.writerow([label] + [group[0].get(a, "") for a in axes] + [len(group)] + counts
                         + stats)
    print(f"{'run':>5} {'point':24} {'seed':>9} {'status':11} {'steps':>5} {'dA_early':>8} "
          f"{'dA_late':>8} {'dphi+':>7} {'z(.5)':>5} {'at phi':>6} {'failed':>6} {'wall_s':>8}")
    for r in rows:
        num = lambda key, spec: format(r[key], spec) if r.get(key) is not None else "-"  # noqa
        print(f"{r['run']:>5} {r['point'][:24]:24} {r['seed']:>9} {r['status']:11} "
              f"{r['steps']:>5} {num('delta_A_early', '8.4f')} {num('delta_A_late', '8.4f')} "
              f"{num('delta_phi_plus', '7.4f')} {num('z_half', '5.2f')} {num('phi_half', '6.3f')} "
              f"{r['failed_checks']:>6} {num('wall_s', '8.1f')}")
    counts = {s: sum(r["status"] == s for r in rows) for s in
              ("ok", "unconverged", "failed", "error", "unfinished")}
    print(f"{len(rows)} runs: " + ", ".join(f"{n} {s}" for s, n in counts.items() if n)
          + f"; reference {os.path.abspath(args.reference)}; wrote summary.csv and points.csv "
            f"in {args.dir}")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)
    q = sub.add_parser("plan", help="write the run list of a sweep file into a folder")
    q.add_argument("sweep_file")
    q.add_argument("dir")
    sub.add_parser("state", help="(in.sweep, in a run's folder) skip, resume or start")
    sub.add_parser("finish", help="(in.sweep, in a run's folder) mark the run finished")
    q = sub.add_parser("summary", help="summarize every run of a sweep folder")
    q.add_argument("dir")
    q.add_argument("--reference", default=DEFAULT_REFERENCE,
                   help="(porosity, calA[, early|late]) points; default: the paper's text")
    q.add_argument("--split", type=float, default=0.25,
                   help="porosity that separates early from late points without a stage column")
    q.add_argument("--accept", action="append", default=["ok"], choices=["unconverged"],
                   help="also average runs of this status in points.csv (default: ok only)")
    args = p.parse_args()
    {"plan": plan, "state": state, "finish": finish, "summary": summary}[args.command](args)


if __name__ == "__main__":
    main()
