#!/usr/bin/env python3
"""The paper's sensitivity study from sweep folders: figures, CSVs and a section of
doc/validation.md with a verdict on each direction the paper states.

    tools/sweep_report.py [--fig4 DIR|CSV ...] [--fig5 DIR|CSV ...] [--fig6 DIR|CSV ...]
                          [--out validation/sweeps] [--doc doc/validation.md]
                          [--accept unconverged] [--sweeps examples/sweep]

Each DIR is a sweep folder of examples/sweep/fig4*.sweep, fig5*.sweep or fig6*.sweep, run (or
partly run) with examples/sweep/in.sweep. A figure may have several sweeps (e.g. fig6_coarse
and fig6_N32, the same pressures at 16 and 32 cells): each gets the figure's directions, and
the first Fig 6 sweep is the one a Fig 4 or 5 sweep borrows its base point from. The parts of
a sweep run in parts (part_of) are judged together as their whole grid; a part that plans every
point of its whole (fig6.sweep and fig6_voronoi.sweep, one tissue each, of fig6_two_tissues.sweep)
is judged on its own as well. For each:
`tools/sweep.py summary DIR`, its summary.csv and points.csv copied to OUT/<sweep>_summary.csv
and _points.csv, its withdrawn runs (run, reason, loop seconds) to OUT/<sweep>_withdrawn.csv,
the figures of tools/sweep_plot.py into OUT (Fig 4 and 5: heatmaps with the caption's
highlighted points ringed and ensemble calA curves of those points; Fig 6: delta_A and
delta_phi_plus against P0 and the calA curves), and what the sweep cost (runs, loop seconds,
wall time). Then the section between SECTION_BEGIN and SECTION_END of --doc is replaced
(appended the first time): per direction of the paper, the ensemble means, their standard
errors, and the verdict by the rule of compare() below. Nothing in the section is typed by
hand; a sweep left out or not run yields "not run". Needs python3-scipy (Student's t), and
python3-numpy and python3-matplotlib for the figures.

A CSV in place of a DIR is such an archive, OUT/<sweep>_summary.csv, read back where the sweep
folder is gone (sweep folders hold gigabytes of dumps and stay on the machine that ran them):
its rows, _withdrawn.csv and figures are used as the earlier report wrote them, after checking
that they are, run for run, the runs --sweeps/<sweep>.sweep plans today (ids, points, seeds,
tissues, step caps); an archive of another plan is refused.
"""
import argparse
import csv
import filecmp
import json
import math
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import sweep  # noqa: E402  (the parameter-file reader)
import mesophyll_frames  # noqa: E402

mesophyll_frames.require(["scipy"])
from scipy.stats import norm, t as student  # noqa: E402

SWEEP = os.path.join(ROOT, "tools", "sweep.py")
PLOT = os.path.join(ROOT, "tools", "sweep_plot.py")
SWEEP_FILES = os.path.join(ROOT, "examples", "sweep")    # where an archive's sweep file lies
KINDS = ("fig4", "fig5", "fig6")
SECTION_BEGIN = "<!-- sweeps: tools/sweep_report.py -->"
SECTION_END = "<!-- /sweeps -->"
PUBLISHED_BEGIN = "<!-- published: tools/validate.py --published -->"
# a run withdrawn after it finished: its outputs moved to runs/<id>/withdrawn/, with the reason
# in this file there; it reads unfinished, and a resumed sweep runs it again
WITHDRAWN_REASON = os.path.join("withdrawn", "REASON.txt")
# a difference counts as resolved when it is as unlikely by chance as a normal one beyond this
# many standard errors of the difference (two-sided: LEVEL, 4.55 %); with few runs the difference
# over its standard error follows Student's t (Welch), whose wider tails need more (needed())
RESOLVED = 2.0
LEVEL = math.erfc(RESOLVED / math.sqrt(2))
# z near phi_patch = 0.5 compares two points only where both came this close to 0.5
NEAR_HALF = 0.05
# the captions' highlighted points: Fig 4 (lambda, delta_a), Fig 5 (beta, eps_b)
HIGHLIGHTED = {"fig4": ("lambda", "delta_a", [(1.5, 0.1), (2, 0.002), (5, 0.01), (5, 0.5)]),
               "fig5": ("beta", "eps_b", [(70, 0.1), (30, 0.01), (300, 0.03), (200, 0.6)])}
# the figures' base point (the default of the parameters each figure varies)
BASE = {"fig4": {"lambda": 5, "delta_a": 0.5}, "fig5": {"beta": 100, "eps_b": 0.4},
        "fig6": {"P0": 1e-3}}
# The three figures' base sets differ in P0 only: a Fig 4 or 5 sweep run at a pressure of the
# Fig 6 sweep may leave its base point out and borrow those runs (borrow_base checks it).
# The runs must share the stopping rule too: phi_stop here; the growth-step cap "steps" may
# differ only where no borrowed run reached the smaller cap (borrow_base checks it).
BORROW_RUN_VARIABLES = ("P0", "ftol", "ftol_scale", "fnorm", "phi_stop", "maxiter", "refine", "set",
                        "tmaxadapt")


# --- ensembles and the comparison rule ----------------------------------------------------------

def tissue_name(row):
    """The file name of a run's initial tissue ('' where the row has none)."""
    return os.path.basename(row.get("tissue", ""))


class Ensemble:
    """The runs of one grid point: how many of each status, and the statistics of a quantity
    over the accepted ones (mean, sample standard deviation, standard error of the mean)."""

    def __init__(self, rows, accept):
        self.rows, self.accept = rows, accept
        self.accepted = [r for r in rows if r["status"] in accept]
        self.counts = {}
        for r in rows:
            self.counts[r["status"]] = self.counts.get(r["status"], 0) + 1

    def values(self, quantity):
        out = []
        for r in self.accepted:
            try:
                v = float(r[quantity])
            except (KeyError, ValueError):
                continue
            if math.isfinite(v):
                out.append(v)
        return out

    def stats(self, quantity):
        """(mean, sd, standard error, n); None for what n does not define."""
        v = self.values(quantity)
        n = len(v)
        if n == 0:
            return None, None, None, 0
        mean = sum(v) / n
        if n == 1:
            return mean, None, None, 1
        sd = math.sqrt(sum((x - mean) ** 2 for x in v) / (n - 1))
        return mean, sd, sd / math.sqrt(n), n

    def tissues(self):
        """The initial tissues (file names) of the accepted runs, sorted: two points whose means
        come from different tissues differ by the tissues as well as by the parameters."""
        return sorted({tissue_name(r) for r in self.accepted})

    def on(self, tissues):
        """The runs of this point from the given tissues alone."""
        return Ensemble([r for r in self.rows if tissue_name(r) in tissues], self.accept)

    def status_text(self):
        order = ("ok", "unconverged", "failed", "error", "unfinished")
        return ", ".join(f"{self.counts[s]} {s}" for s in order if self.counts.get(s))


def welch_df(sa, na, sb, nb):
    """Welch's degrees of freedom of the difference of two means with standard errors sa and sb
    from na and nb runs (infinite where neither spreads)."""
    va, vb = sa * sa, sb * sb
    if va + vb == 0:
        return math.inf
    return (va + vb) ** 2 / (va * va / (na - 1) + vb * vb / (nb - 1))


def difference_law(df):
    """The law of a difference over its standard error: Student's t at df degrees of freedom,
    the normal where df is infinite."""
    return norm if math.isinf(df) else student(df)


def tail(score, df, sides):
    """The tail beyond score: the chance of a difference this large (one side: in the stated
    direction) with no difference at all."""
    law = difference_law(df)
    return 2 * law.sf(abs(score)) if sides == 2 else law.sf(score)


def resolving_chance(sides):
    """The chance at which one comparison resolves: LEVEL two-sided, half of it on one side (the
    same bound on a difference in the stated direction)."""
    return LEVEL if sides == 2 else LEVEL / 2


def needed(df, chance=LEVEL, sides=2):
    """The size, in standard errors, that a difference with df degrees of freedom must exceed
    to arise by chance no more often than `chance` (RESOLVED where df is infinite)."""
    return float(difference_law(df).isf(chance / 2 if sides == 2 else chance))


def compare(a, b, quantity, sign):
    """Is quantity larger (sign +1) or smaller (sign -1) at ensemble a than at b? 'holds' when
    the difference of the means, in the stated direction, exceeds needed(df) standard errors
    of the difference (the two standard errors added in quadrature; df Welch's): with no
    difference there, as rare as RESOLVED standard errors of a normal difference; 'opposite'
    when it does so against it; 'not resolved' in between; 'equal' when every run of both has
    the same value (no spread: these runs cannot show a difference either way); 'too few runs'
    below two accepted runs either side.
    Returns (verdict, mean_a, se_a, n_a, mean_b, se_b, n_b, difference / its standard error,
    degrees of freedom)."""
    ma, _, sa, na = a.stats(quantity)
    mb, _, sb, nb = b.stats(quantity)
    if na < 2 or nb < 2:
        return "too few runs", ma, sa, na, mb, sb, nb, None, None
    se = math.hypot(sa, sb)
    diff = sign * (ma - mb)
    df = welch_df(sa, na, sb, nb)
    if se == 0 and diff == 0:    # every run of both gives one value: no spread to resolve
        return "equal", ma, sa, na, mb, sb, nb, 0.0, df
    score = diff / se if se > 0 else (math.inf if diff > 0 else -math.inf)
    bound = needed(df)
    verdict = "holds" if score > bound else "opposite" if score < -bound else "not resolved"
    return verdict, ma, sa, na, mb, sb, nb, score, df


def number(text):
    """float(text), or None where the summary's cell is empty or missing."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def same_value(text, value):
    parsed = number(text)
    return parsed is not None and math.isclose(parsed, float(value), rel_tol=1e-9)


def ensemble_at(rows, values, accept):
    """The Ensemble of the runs whose grid values are `values` ({axis: number}); None when
    the sweep has no such point."""
    chosen = [r for r in rows if all(same_value(r.get(k), v) for k, v in values.items())]
    return Ensemble(chosen, accept) if chosen else None


# --- one sweep folder ----------------------------------------------------------------------------

def run_tool(command):
    result = subprocess.run([sys.executable] + command, capture_output=True, text=True)
    missing = os.environ.get("MESOPHYLL_MISSING_EXIT")    # the tests' skip code (77)
    if missing and result.returncode == int(missing):
        print(result.stderr, end="", file=sys.stderr)
        sys.exit(result.returncode)    # a Debian package is missing: say so, skip
    if result.returncode:
        sys.exit(f"sweep_report: {' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


def sweep_cost(rows):
    """(loop seconds of all attempts, wall seconds of the finishing attempts, runs finished
    with a wall time) of a sweep's summary rows. The wall seconds add the partitions' busy
    time, so pauses of the sweep do not count."""
    loop = sum(float(r["loop_s"] or 0) for r in rows)
    walls = [float(r["wall_s"]) for r in rows if r["wall_s"] not in ("", None)]
    return loop, sum(walls), len(walls)


def withdrawn_runs(folder):
    """[(run id, reason, loop seconds)] of the runs of a sweep folder that were withdrawn:
    their cost still counts."""
    found = []
    runs = os.path.join(folder, "runs")
    for run in sorted(os.listdir(runs)):
        path = os.path.join(runs, run, WITHDRAWN_REASON)
        if os.path.exists(path):
            log = os.path.join(os.path.dirname(path), "log.lammps")
            text = open(log, errors="replace").read() if os.path.exists(log) else ""
            found.append((run, " ".join(open(path).read().split()),
                          sum(t.seconds for t in sweep.mesophyll_run.loop_times(text))))
    return found


WITHDRAWN_COLUMNS = ["run", "reason", "loop_s"]


def shown(path):
    """path as typed from the package's folder where it lies inside, else absolute."""
    path = os.path.abspath(path)
    return os.path.relpath(path, ROOT) if path.startswith(ROOT + os.sep) else path


def listed(words):
    """'a', 'a and b', 'a, b and c'."""
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def archive_name(path):
    """The sweep's name when path is an archived summary <name>_summary.csv, else None."""
    base = os.path.basename(path)
    return base[:-len("_summary.csv")] if base.endswith("_summary.csv") else None


def heatmap_axes(kind, rows):
    """sweep_plot.py heatmaps' axes of the figure and its highlighted points, those on the grid
    of rows only (a part of a sweep holds some rows)."""
    x, y, marks = HIGHLIGHTED[kind]
    on_grid = [m for m in marks
               if any(same_value(r[x], m[0]) and same_value(r[y], m[1]) for r in rows)]
    return ["--x", x, "--y", y] + [a for m in on_grid for a in ("--mark", f"{m[0]},{m[1]}")]


class Sweep:
    """A summarized sweep and the figures drawn from it: from its folder, or from the CSVs a
    report archived from that folder (OUT/<name>_summary.csv, _points.csv, _withdrawn.csv and
    the figures beside them), checked against the runs its sweep file plans."""

    def __init__(self, kind, source, out, accept, sweep_files):
        self.kind, self.out, self.accept = kind, out, accept
        self.figures = []
        if os.path.isfile(source):
            self.load_archive(source, sweep_files)
        else:
            self.load_folder(source)
        self.loop_s, self.wall_s, self.timed = sweep_cost(self.rows)
        self.withdrawn = {}
        for run, reason, _ in self.withdrawn_list:
            self.withdrawn.setdefault(reason, []).append(run)
        self.withdrawn_loop_s = sum(loop for _, _, loop in self.withdrawn_list)
        self.loop_s += self.withdrawn_loop_s
        self.archive()

    def load_folder(self, folder):
        self.folder, self.archived = folder, False
        extra = [a for k in self.accept if k != "ok" for a in ("--accept", k)]
        run_tool([SWEEP, "summary", folder] + extra)
        self.rows = list(csv.DictReader(open(os.path.join(folder, "summary.csv"))))
        self.name, self.sweep_path, self.protocol = sweep.planned(folder)
        self.sweep_file = shown(self.sweep_path)
        self.part_of = sweep.SweepFile(self.sweep_path).part_of
        self.withdrawn_list = withdrawn_runs(folder)
        self.draw(extra)

    def load_archive(self, path, sweep_files):
        self.name, self.archived = archive_name(path), True
        self.folder = os.path.dirname(os.path.abspath(path))
        self.rows = list(csv.DictReader(open(path)))
        sweep_file = os.path.join(sweep_files, f"{self.name}.sweep")
        if not os.path.isfile(sweep_file):
            sys.exit(f"sweep_report: {path} is the archive of sweep {self.name}, but its sweep "
                     f"file {sweep_file} does not exist")
        definition, _, planned = sweep.planned_runs(sweep_file)
        self.sweep_path, self.sweep_file = sweep_file, shown(sweep_file)
        self.protocol, self.part_of = definition.protocol, definition.part_of
        self.records = {}
        for run in planned:
            self.records[run["id"]] = {"variables": dict(
                run["values"], tissue=run["tissue"], parameters=definition.parameters)}
        self.check_archive(path, sweep_file, planned)
        withdrawn = os.path.join(self.folder, f"{self.name}_withdrawn.csv")
        self.withdrawn_list = ([(r["run"], r["reason"], float(r["loop_s"]))
                                for r in csv.DictReader(open(withdrawn))]
                               if os.path.exists(withdrawn) else [])
        # the figures the report drew from the folder when it archived it
        for what in ("heatmaps", "against", "curves"):
            png = os.path.join(self.folder, f"{self.name}_{what}.png")
            if os.path.exists(png):
                self.figures.append(png)

    def check_archive(self, path, sweep_file, planned):
        """The archived rows must be the runs the sweep file plans today, one for one: the same
        ids, points, seeds, tissues, cells and step caps; else the archive is of another plan."""
        def planned_row(run):
            return (run["id"], run["point"], run["seed"], sweep.path_from(ROOT, run["tissue"]),
                    run["values"]["N"], run["values"].get("steps", ""))
        def archived_row(row):
            return tuple(row.get(c) for c in ("run", "point", "seed", "tissue", "N",
                                              "steps_planned"))
        want = [planned_row(run) for run in planned]
        have = [archived_row(row) for row in self.rows]
        if want != have:
            first = next((f"run {w[0]}: planned {w[1:]}, archived {h[1:]}"
                          for w, h in zip(want, have) if w != h),
                         f"{len(want)} runs planned, {len(have)} archived")
            sys.exit(f"sweep_report: {path} is not the sweep {sweep_file} plans today ({first});"
                     f" give the sweep folder, or the sweep file the archive was made with")

    def archive(self):
        """Keep the summary as CSVs in OUT, where a later report can read it back (an archive
        read where it lies is kept already)."""
        if self.archived and os.path.abspath(self.folder) == os.path.abspath(self.out):
            return
        for table in ("summary", "points"):
            source = os.path.join(self.folder, f"{self.name}_{table}.csv" if self.archived
                                  else f"{table}.csv")
            shutil.copy(source, os.path.join(self.out, f"{self.name}_{table}.csv"))
        if self.archived:
            for png in self.figures:
                shutil.copy(png, self.out)
            self.figures = [os.path.join(self.out, os.path.basename(p)) for p in self.figures]
        withdrawn = os.path.join(self.out, f"{self.name}_withdrawn.csv")
        if self.withdrawn_list:
            with open(withdrawn, "w", newline="") as f:
                out = csv.writer(f)
                out.writerow(WITHDRAWN_COLUMNS)
                out.writerows([run, reason, f"{loop:.6g}"]
                              for run, reason, loop in self.withdrawn_list)
        elif os.path.exists(withdrawn):
            os.remove(withdrawn)

    def plot(self, what, args, extra):
        png = os.path.join(self.out, f"{self.name}_{what}.png")
        run_tool([PLOT, what, self.folder, "-o", png] + args + extra)
        self.figures.append(png)

    def draw(self, extra):
        if not any(r["status"] in self.accept for r in self.rows):
            return    # nothing to draw: the section says so
        if self.kind in HIGHLIGHTED:
            if set(HIGHLIGHTED[self.kind][:2]) <= set(self.rows[0]):
                self.plot("heatmaps", heatmap_axes(self.kind, self.rows), extra)
            # the curves of every point with an accepted run (the reduced grids hold the
            # highlighted points and few others)
            chosen = [p for p in dict.fromkeys(r["point"] for r in self.rows)
                      if any(r["point"] == p and r["status"] in self.accept for r in self.rows)]
            self.plot("curves", [a for p in chosen for a in ("--point", p)], extra)
        else:
            self.plot("against", ["--x", "P0"], extra)
            self.plot("curves", [], extra)

    def at(self, **values):
        found = ensemble_at(self.rows, values, self.accept)
        if found is None and self.borrowed and values == BASE[self.kind]:
            return self.borrowed[1]
        return found

    def points(self):
        """[(label, Ensemble)] in the order of the plan, a borrowed base point first."""
        labels = list(dict.fromkeys(r["point"] for r in self.rows))
        own = [(p, Ensemble([r for r in self.rows if r["point"] == p], self.accept))
               for p in labels]
        return ([self.borrowed] if self.borrowed else []) + own

    borrowed = None    # (label, Ensemble) of a base point taken from the Fig 6 sweep

    def settings(self, record):
        """A run's variables as it ran: those its record sets, its protocol's defaults for the
        rest."""
        return dict(sweep.protocol_defaults(self.protocol), **record["variables"])

    def stopping_rule(self):
        """'below phi_patch 0.45 or after 12 growth steps': the sweep's phi_stop (its first
        run's, or its protocol's default) and step caps (per point where they differ)."""
        settings = self.settings(self.run_record(self.rows[0]))
        caps = sorted({int(r["steps_planned"]) for r in self.rows if r.get("steps_planned")})
        steps = ("-" if not caps else f"{caps[0]}" if len(caps) == 1
                 else f"{caps[0]}-{caps[-1]} (by point)")
        return (f"below phi_patch {settings.get('phi_stop', '-')} or after {steps} growth "
                f"steps")

    def run_record(self, row):
        """The run's record: its variables as the run saw them (a folder's run.json, or the
        plan of an archive's sweep file)."""
        if self.archived:
            return self.records[row["run"]]
        return json.load(open(os.path.join(self.folder, "runs", row["run"], "run.json")))

    def parameter_file(self, record):
        """The run's parameter file (a folder's run.json gives it relative to the run)."""
        return os.path.join(self.folder, "runs", record["id"], record["variables"]["parameters"]) \
            if not self.archived else record["variables"]["parameters"]

    def borrow_base(self, fig6):
        """Take the base point from the Fig 6 sweep where this sweep lacks it and runs at one of
        its pressures: allowed only when the base parameter sets agree apart from P0, and the
        runs agree in every variable of BORROW_RUN_VARIABLES and in seeds and tissues.
        Returns a sentence saying what was borrowed, or why not (None: nothing to borrow)."""
        if ensemble_at(self.rows, BASE[self.kind], self.accept) is not None or fig6 is None:
            return None
        mine, theirs = self.run_record(self.rows[0]), fig6.run_record(fig6.rows[0])
        sets = [sweep.parameter_sets(s.parameter_file(r))[r["variables"]["set"]]
                for s, r in ((self, mine), (fig6, theirs))]
        # the run's pressure: its own variable, else its parameter set's (a sweep that leaves P0
        # to the set, as fig5_part1.sweep)
        p0 = float(mine["variables"].get("P0", sets[0].get("P0", "nan")))
        for s in sets:
            s.pop("P0", None)
        if sets[0] != sets[1]:
            return (f"{self.name} has no base point, and the base set of its parameter file "
                    f"differs from {fig6.name}'s beyond P0: none borrowed.")
        rows = [r for r in fig6.rows if same_value(r.get("P0"), p0)]
        if not rows:
            return f"{self.name} has no base point, and {fig6.name} has no P0 = {p0:g}."
        lender = fig6.run_record(rows[0])
        # P0 agrees by the choice of rows (its text may differ: 1e-7, 1.0e-7)
        settings = [dict(self.settings(mine), P0=p0), dict(fig6.settings(lender), P0=p0)]
        differ = [name for name in BORROW_RUN_VARIABLES
                  if settings[0].get(name) != settings[1].get(name)]
        seeds_tissues = lambda rs: sorted((r["seed"], r["tissue"]) for r in rs)  # noqa: E731
        if differ or seeds_tissues(rows) != seeds_tissues(
                [r for r in self.rows if r["point"] == self.rows[0]["point"]]):
            return (f"{self.name} has no base point; {fig6.name}'s P0 = {p0:g} runs differ in "
                    f"{', '.join(differ) or 'seeds or tissues'}: none borrowed.")
        caps = (mine["variables"].get("steps"), lender["variables"].get("steps"))
        phi_stop = mine["variables"].get("phi_stop")
        cap_note = step_cap_note(rows, caps, phi_stop)
        if cap_note is None:
            return (f"{self.name} has no base point; {fig6.name}'s P0 = {p0:g} runs have a "
                    f"growth-step cap of {caps[1]} against {caps[0]} here, and not all of them "
                    f"stopped at phi_patch {phi_stop} before the smaller cap: none borrowed.")
        label = f"base ({fig6.name}, P0={p0:g})"
        self.borrowed = (label, Ensemble(rows, self.accept))
        return (f"{self.name}'s base point {BASE[self.kind]} is {fig6.name}'s P0 = {p0:g} point: "
                f"the same parameter set apart from P0, and runs with the same pressure, force "
                f"tolerance, phi_stop {phi_stop}, seeds and tissues; {cap_note}. It is not a "
                f"tile of the heatmap.")


class Whole:
    """A sweep run in parts (sweep files with part_of): its runs in the order of its own plan,
    each with the row of the part that ran it, or unfinished where no part given has; and the
    figure of the whole grid (Fig 4 and 5: heatmaps; Fig 6: against P0). The verdicts are the
    whole's (a part's runs are the whole's, so points of two parts compare as points of one
    sweep); the parts keep their own tables and figures, and borrow no base point. A part that
    plans every point of the whole (the whole grid from one of its tissues) is an ensemble of
    its own as well: it keeps its verdicts (complete), and the whole, whose points then pool
    the runs of several parts (pooled), gets a table of its own. The figure is drawn where the
    whole has an accepted run, and replaces one drawn earlier from other numbers (draw())."""

    def __init__(self, kind, path, parts, out, accept):
        self.kind, self.parts, self.figures, self.accept = kind, parts, [], accept
        definition, _, planned = sweep.planned_runs(path)
        self.name, self.sweep_file = definition.name, shown(path)
        ran, planned_by = {}, []
        for part in parts:
            part_definition, _, part_runs = sweep.planned_runs(part.sweep_path)
            key = {run["id"]: sweep.run_key(part_definition, run) for run in part_runs}
            planned_by.append(set(key.values()))
            for row in part.rows:
                ran[key[row["run"]]] = row
        whole_points = {}
        for run in planned:
            whole_points.setdefault(run["point"], set()).add(sweep.run_key(definition, run))
        self.complete = [part for part, keys in zip(parts, planned_by)
                         if all(keys & runs for runs in whole_points.values())]
        self.pooled = any(sum(bool(keys & runs) for keys in planned_by) > 1
                          for runs in whole_points.values())
        self.rows = []
        for run in planned:
            row = dict(ran.get(sweep.run_key(definition, run)) or
                       {"status": "unfinished", "steps": "0"})
            row.update(run["point_values"], run=run["id"], point=run["point"], seed=run["seed"],
                       tissue=sweep.path_from(ROOT, run["tissue"]), N=run["values"]["N"],
                       steps_planned=run["values"].get("steps", ""))
            self.rows.append(row)
        self.figure = "heatmaps" if self.kind in HIGHLIGHTED else "against"
        png = os.path.join(out, f"{self.name}_{self.figure}.png")
        if any(r["status"] in accept for r in self.rows):
            self.draw(png, accept)
            self.figures.append(png)

    def at(self, **values):
        return ensemble_at(self.rows, values, self.accept)

    def points(self):
        """[(label, Ensemble)] in the order of the whole's plan, unfinished points included."""
        labels = list(dict.fromkeys(r["point"] for r in self.rows))
        return [(p, Ensemble([r for r in self.rows if r["point"] == p], self.accept))
                for p in labels]

    def draw(self, png, accept):
        """Draw the figure in a scratch folder; put it at png unless the one there was drawn from
        the same numbers (the CSVs beside them agree: per tile or point the mean, spread and
        accepted, all and failed runs), so that a report of the same runs writes nothing."""
        columns = list(dict.fromkeys(k for row in self.rows for k in row))
        with tempfile.TemporaryDirectory(prefix="sweep_whole_") as scratch:
            folder = os.path.join(scratch, self.name)    # the figure's title names the folder
            os.makedirs(folder)
            with open(os.path.join(folder, "summary.csv"), "w", newline="") as f:
                out = csv.DictWriter(f, columns, restval="")
                out.writeheader()
                out.writerows(self.rows)
            axes = (heatmap_axes(self.kind, self.rows) if self.figure == "heatmaps"
                    else ["--x", "P0"])
            drawn = os.path.join(scratch, os.path.basename(png))
            run_tool([PLOT, self.figure, folder, "-o", drawn] + axes
                     + [a for k in sorted(accept) if k != "ok" for a in ("--accept", k)])
            table, new_table = (os.path.splitext(p)[0] + ".csv" for p in (png, drawn))
            if os.path.exists(png) and os.path.exists(table) and \
                    filecmp.cmp(table, new_table, shallow=False):
                return
            shutil.copy(drawn, png)
            shutil.copy(new_table, table)

    def lines(self, rel):
        counts = Ensemble(self.rows, {"ok"}).status_text()
        done = sum(r["status"] != "unfinished" for r in self.rows)
        names = listed([part.name for part in self.parts])
        one = len(self.complete) == 1
        own = (f" {listed([part.name for part in self.complete])} "
               f"{'plans' if one else 'plan'} every point of the whole (the whole "
               f"grid from fewer seeds or tissues), so {'it has' if one else 'they have'} "
               f"directions of {'its' if one else 'their'} own above as well." if self.complete
               else "")
        pooled = (" Its points pool the runs of several parts (means over all their seeds "
                  "and tissues):" if self.pooled else "")
        figure = ("The heatmaps of the whole grid:" if self.figure == "heatmaps" else
                  "delta_A and delta_phi_plus against P0 over the whole grid:")
        return ([f"**{self.name}** ({self.kind}, the whole grid of `{self.sweep_file}`, run in "
                 f"parts): {done} of {len(self.rows)} runs done, from its part"
                 f"{'s' if len(self.parts) > 1 else ''} {names} ({counts}). Each part plans "
                 f"only runs of the whole, the same in every variable (`tools/sweep.py plan` "
                 f"checks it), so the verdicts above compare points across parts as the "
                 f"whole's; each part's table, cost and figures (below) are its own.{own}"
                 + (pooled if self.pooled else f" {figure}"), ""]
                + (points_table(self) + ["", figure, ""] if self.pooled else [])
                + [f"![{os.path.basename(p)}]({rel(p)})" for p in self.figures]
                + (["No figure: no part of it has an accepted run."]
                   if not self.figures else []) + [""])


def wholes_of(sweeps, out, accept):
    """The sweeps that the given ones are parts of, each a Whole of the parts given."""
    parts = {}
    for one in sweeps:
        if one.part_of:
            parts.setdefault((one.kind, one.part_of), []).append(one)
    return [Whole(kind, path, group, out, accept) for (kind, path), group in parts.items()]


def step_cap_note(rows, caps, phi_stop):
    """The borrowed runs are the runs this sweep would have made when both sweeps cap growth at
    the same number of steps, or when every borrowed run stopped at phi_stop before the
    smaller cap. Returns a clause saying which, or None when neither."""
    if caps[0] == caps[1]:
        return f"both cap growth at {caps[0]} steps"
    smaller = min(int(c) for c in caps if c is not None) if None not in caps else None
    stopped = smaller is not None and phi_stop is not None and all(
        r["status"] != "unfinished" and r["phi_final"] not in ("", None)
        and float(r["phi_final"]) < float(phi_stop) and int(r["steps"]) - 1 < smaller
        for r in rows)
    if not stopped:
        return None
    return (f"the growth-step caps differ ({caps[0]} here, {caps[1]} there), but every "
            f"borrowed run stopped at phi_patch {phi_stop} after at most "
            f"{max(int(r['steps']) - 1 for r in rows)} growth steps, before either cap")


# --- the section ---------------------------------------------------------------------------------

def fmt(x, spec=".3g"):
    return "-" if x is None else format(x, spec)


def mean_se(m, s, n):
    return "-" if m is None else f"{m:{'.4g'}} +- {fmt(s, '.2g')} (n = {n})"


def claim_line(title, sweep, a_values, b_values, quantity, sign, note=""):
    """One direction as a markdown bullet: the two ensembles, the difference in standard
    errors, the verdict."""
    if sweep is None:
        return f"- *{title}*: not run (no sweep folder given)."
    a, b = sweep.at(**a_values), sweep.at(**b_values)
    name = lambda v: ", ".join(f"{k} = {x:g}" for k, x in v.items())  # noqa: E731
    if a is None or b is None:
        missing = name(a_values) if a is None else name(b_values)
        return f"- *{title}*: not run ({sweep.name} has no point {missing})."
    verdict, ma, sa, na, mb, sb, nb, score, df = compare(a, b, quantity, sign)
    far = [p for p in (a, b) if p.stats("phi_half")[0] is not None
           and abs(p.stats("phi_half")[0] - 0.5) > NEAR_HALF]
    if quantity == "z_half" and far and verdict != "too few runs":
        verdict = "not near 0.5"
    text = {"holds": "**holds**", "opposite": "**does not hold: the opposite is resolved**",
            "not resolved": f"**cannot be told at this resolution** (resolving needs "
                            f"{fmt(df and needed(df), '.2f')} standard errors with these runs)",
            "equal": f"**cannot be told**: every run of both gives {quantity} = "
                     f"{fmt(ma, 'g')}, so these runs cannot show a difference"
                     + (" (the runs stop once phi_patch falls below phi_stop, and none "
                        "compacted before that: this protocol cannot show compaction here)"
                        if quantity == "delta_phi_plus" else ""),
            "not near 0.5": f"**cannot be told**: the runs of a point ended before phi_patch "
                            f"came within {NEAR_HALF:g} of 0.5, so z is compared at different "
                            f"stages",
            "too few runs": "**cannot be told: fewer than two accepted runs**"}[verdict]
    mixed = tissue_note(a, b, quantity, sign, name(a_values), name(b_values))
    return (f"- *{title}* ({quantity}; {sweep.name}): {mean_se(ma, sa, na)} at {name(a_values)} "
            f"[{a.status_text()}] against {mean_se(mb, sb, nb)} at {name(b_values)} "
            f"[{b.status_text()}]; difference {fmt(score, '+.1f')} standard errors: {text}. "
            f"Where the runs ended: {name(a_values)}: {reach_note(a)}; {name(b_values)}: "
            f"{reach_note(b)}."
            + (f" {mixed}" if mixed else "") + (f" {note}" if note else ""))


def compare_on_shared(a, b, quantity, sign):
    """compare() on the tissues whose accepted runs both points have, those alone: (the shared
    tissues, the verdict, the score, its df); the verdict None where they share no tissue."""
    theirs = set(b.tissues())
    shared = [t for t in a.tissues() if t in theirs]
    if not shared:
        return shared, None, None, None
    verdict, *_, score, df = compare(a.on(shared), b.on(shared), quantity, sign)
    return shared, verdict, score, df


def tissue_note(a, b, quantity, sign, a_name, b_name):
    """Where the accepted runs of two points come from different tissues (a sweep run in parts
    from several tissues, some not yet run; or every run of one tissue failing at a point), their
    difference carries the tissues' as well: a sentence saying so, and the difference on the
    tissues they share alone; '' where the tissues agree."""
    ta, tb = a.tissues(), b.tissues()
    if ta == tb or len(a.accepted) < 2 or len(b.accepted) < 2:    # same, or nothing compared
        return ""
    shared, verdict, score, _ = compare_on_shared(a, b, quantity, sign)
    head = (f"Tissues differ: the accepted runs at {a_name} are from {listed(ta)}, at {b_name} "
            f"from {listed(tb)}, so the difference carries the tissues' with the seeds'")
    if not shared:
        return head + "; they share no tissue to compare on."
    said = {"holds": "resolved in the stated direction", "opposite": "resolved against it",
            "not resolved": "not resolved", "equal": "no spread to resolve",
            "too few runs": "fewer than two accepted runs"}[verdict]
    size = f"{score:+.1f} standard errors, " if score is not None else ""
    return head + f"; on {listed(shared)} alone: {size}{said}."


def holm(chances, level):
    """Which of a family's comparisons (their chances by tail()) stay resolved once corrected
    for their number (Holm's step-down): the family as a whole is as unlikely to resolve a
    difference by chance as one comparison alone at `level`. Returns the indices that stay."""
    order = sorted(range(len(chances)), key=lambda k: chances[k])
    stay = []
    for rank, k in enumerate(order):
        if chances[k] > level / (len(chances) - rank):
            break
        stay.append(k)
    return stay


def corrected_note(family, sides):
    """What a family of comparisons ((score in standard errors, df) each) shows after the
    correction: (the indices of those that stay resolved, a sentence saying so, or how far the
    strongest fell short); ([], '') where none resolves even alone."""
    tested = len(family)
    alone = resolving_chance(sides)
    chances = [tail(score, df, sides) for score, df in family]
    resolved = sum(c <= alone for c in chances)
    if not resolved:
        return [], ""
    stay = holm(chances, alone)
    score, df = family[min(range(tested), key=lambda k: chances[k])]
    asked = needed(df, alone / tested, sides)
    family_text = f"{tested} comparison{'s' if tested != 1 else ''}"
    raw = (f"{resolved} of {tested} resolve{'s' if resolved == 1 else ''} alone "
           f"({chance(tested, sides)})")
    if stay:
        return stay, (f"{len(stay)} of {tested} stay{'s' if len(stay) == 1 else ''} resolved "
                      f"once corrected for the {family_text} (Holm); {raw}")
    return stay, (f"{raw}, but none stays resolved once corrected for the {family_text} (Holm): "
                  f"the strongest, {abs(score):.1f} standard errors in size, is below the "
                  f"{asked:.2f} the correction asks of it")


def chance(tests, sides):
    """How many of `tests` comparisons would resolve by chance alone, with no difference there:
    the verdict rule resolves each at the chance LEVEL (two-sided, 4.55 %; one-sided half of
    it) and does not correct for their number."""
    return (f"with no difference at all, {tests} comparison{'s' if tests != 1 else ''} would "
            f"resolve {tests * resolving_chance(sides):.2g} by chance")


def reach_note(e):
    """Where the accepted runs of a point ended: mean growth steps and final phi_patch, and
    phi_patch at the step nearest 0.5 (where z_half is taken)."""
    if not e.accepted:
        return "no accepted run"
    steps, phi_final, phi_half = (e.stats(q)[0] for q in ("steps", "phi_final", "phi_half"))
    return (f"{steps:.1f} minima recorded (the first before growth), phi_patch "
            f"{phi_final:.3f} (nearest 0.5: {phi_half:.3f})")


def unchanged_lines(sweep, reference):
    """'P0 up to 1e-3 hardly matters': each lower pressure of the sweep (in the order of its
    plan) against the reference one, for each quantity of the figure. No resolved difference
    is not a shown equality: the verdict says so, and how large a difference would have been
    resolved (needed() standard errors, per line)."""
    if sweep is None:
        return ["- *P0 up to 1e-3 hardly matters*: not run (no Fig 6 sweep folder given)."]
    b = sweep.at(**reference)
    pressures = dict.fromkeys(number(r.get("P0")) for r in sweep.rows)    # in plan order
    lower = [{"P0": p} for p in pressures if p is not None and p < reference["P0"]]
    lines, counts, scores = [], {}, []
    for values in lower:
        a = sweep.at(**values)
        if a is None or b is None:
            continue
        for quantity in ("delta_A_early", "delta_A_late", "delta_phi_plus", "z_half"):
            verdict, ma, sa, na, mb, sb, nb, score, df = compare(a, b, quantity, +1)
            counts[verdict] = counts.get(verdict, 0) + 1
            if verdict in ("holds", "opposite", "not resolved"):
                scores.append((score, df))
            where = (f"  - {quantity}: {mean_se(ma, sa, na)} at P0 = {values['P0']:g} against "
                     f"{mean_se(mb, sb, nb)} at {reference['P0']:g}: ")
            if verdict == "too few runs":
                lines.append(where + "not compared (fewer than two accepted runs)")
            elif verdict == "equal":
                lines.append(where + f"every run of both gives {fmt(ma, 'g')}: no difference "
                                     f"to resolve, none shown either")
            else:
                lines.append(where + f"difference {fmt(score, '+.1f')} standard errors (SE of "
                                     f"the difference {fmt(math.hypot(sa, sb), '.2g')}; "
                                     f"resolving needs {needed(df):.2f})")
    resolved = counts.get("holds", 0) + counts.get("opposite", 0)
    tested = resolved + counts.get("not resolved", 0)
    stay, note = corrected_note(scores, 2)
    if not tested:
        return ["- *P0 up to 1e-3 hardly matters*: cannot be told (no two pressures at or "
                "below 1e-3 with two accepted runs each and spread in a quantity)."]
    left = [f"{counts[v]} {what}" for v, what in (("equal", "without spread"),
                                                 ("too few runs", "with too few runs"))
            if counts.get(v)]
    if stay:
        verdict = f"**does not hold**: {note}"
    elif resolved:
        verdict = f"**no difference resolved** once corrected: {note}"
    else:
        verdict = (f"**no difference resolved** in {tested} comparison"
                   f"{'s' if tested != 1 else ''} (consistent with the claim, not shown: a "
                   f"difference smaller than the standard errors resolving needs, given per "
                   f"line, could be there)")
    return [f"- *P0 up to 1e-3 hardly matters* ({sweep.name}): {verdict}"
            + (f"; not compared: {', '.join(left)}" if left else "") + ":"] + lines


def optimal_lines(sweeps):
    """'the default is near-optimal in delta_A': per sweep, the base point's delta_A against
    every other point. No point resolved lower is not a shown optimum: the line says so, and
    how many points could be compared at all."""
    lines = []
    for one in sorted(sweeps, key=lambda s: KINDS.index(s.kind)):
        kind = one.kind
        base = one.at(**BASE[kind])
        if base is None:
            lines.append(f"  - {one.name}: no base point ({BASE[kind]}).")
            continue
        for quantity in ("delta_A_early", "delta_A_late"):
            better, ranks, compared, scores, labels = [], [], [], [], []
            mb = base.stats(quantity)[0]
            everywhere = one.points()
            for label, e in everywhere:
                m = e.stats(quantity)[0]
                if m is None or mb is None:
                    continue
                ranks.append(m)
                verdict, *_, score, df = compare(e, base, quantity, -1)
                if e.rows != base.rows and verdict != "too few runs":
                    compared.append((label, e))
                if verdict in ("holds", "opposite", "not resolved") and e.rows != base.rows:
                    scores.append((score, df))    # the family: comparisons with spread
                    labels.append(f"{label} ({m:.3g})")
                if verdict == "holds":
                    better.append(f"{label} ({m:.3g})")
            if mb is None:
                lines.append(f"  - {one.name}, {quantity}: the base point has no accepted run.")
                continue
            if len(ranks) < 2:
                lines.append(f"  - {one.name}, {quantity}: cannot be told (no point beside "
                             f"the base with an accepted run).")
                continue
            rank = 1 + sum(m < mb for m in ranks)
            m, _, se, n = base.stats(quantity)
            stay, note = corrected_note(scores, 1)
            among = (f"among the {len(compared)} of {len(everywhere) - 1} other points with "
                     f"two or more accepted runs")
            lines.append(f"  - {one.name}, {quantity}: base {mean_se(m, se, n)}, "
                         f"rank {rank} of the {len(ranks)} points with an accepted run "
                         f"({len(everywhere)} points in the sweep); "
                         + (f"**no point resolved lower** {among} (consistent, not shown)"
                            if not better else
                            f"**does not hold**: resolved lower at "
                            f"{', '.join(labels[k] for k in sorted(stay))}; {note}"
                            if stay else
                            f"**no point resolved lower** once corrected, {among}: resolved "
                            f"lower alone: {', '.join(better)}; {note}")
                         + matched_note(compared, base, quantity))
    if not lines:
        return ["- *the default is near-optimal in delta_A*: not run."]
    return ["- *the default is near-optimal in delta_A* (the base point of each sweep against "
            "its other points; lower is closer to the reference points):"] + lines


def matched_note(compared, base, quantity):
    """'the default is near-optimal', where some compared points have accepted runs from other
    tissues than the base: how many, and the family again with each point compared with the
    base on the tissues they share alone (Holm over that family); '' where every point's
    tissues are the base's."""
    base_tissues = base.tissues()
    mixed = sum(e.tissues() != base_tissues for _, e in compared)
    if not mixed:
        return ""
    scores, labels = [], []
    for label, e in compared:
        _, verdict, score, df = compare_on_shared(e, base, quantity, -1)
        if verdict in ("holds", "opposite", "not resolved"):
            scores.append((score, df))
            labels.append(label)
    stay, _ = corrected_note(scores, 1)
    has, carry = (("has", "its difference carries") if mixed == 1 else
                  ("have", "their differences carry"))
    return (f"; tissues differ: {mixed} of the {len(compared)} compared points {has} "
            f"accepted runs from other tissues than the base's ({listed(base_tissues)}), so "
            f"{carry} the tissues' with the seeds'; compared with the base on "
            f"the tissues each shares with it alone ({len(scores)} comparison"
            f"{'' if len(scores) == 1 else 's'}), "
            + (f"{len(stay)} stay{'s' if len(stay) == 1 else ''} resolved lower once corrected "
               f"(Holm): {', '.join(labels[k] for k in sorted(stay))}" if stay else
               "none stays resolved lower once corrected (Holm)"))


def points_table(sweep):
    lines = ["| point | runs | delta_A early | delta_A late | delta_phi_plus | z near 0.5 "
             "(at phi_patch) | phi_patch end |", "| --- | --- | --- | --- | --- | --- | --- |"]
    for label, e in sweep.points():
        def cell(quantity):
            m, _, se, n = e.stats(quantity)
            return mean_se(m, se, n)
        z, phi = e.stats("z_half"), e.stats("phi_half")
        lines.append(f"| {label} | {e.status_text()} | {cell('delta_A_early')} | "
                     f"{cell('delta_A_late')} | {cell('delta_phi_plus')} | "
                     f"{fmt(z[0], '.3g')} ({fmt(phi[0], '.3f')}) | "
                     f"{fmt(e.stats('phi_final')[0], '.3f')} |")
    return lines


def section(sweeps, doc_dir, command, notes, wholes=()):
    rel = lambda p: os.path.relpath(p, doc_dir)  # noqa: E731
    archived = [s.name for s in sweeps if s.archived]
    files = listed([f"`{s.sweep_file}`" for s in sweeps])
    many = len(archived) > 1
    whose = "those reports'" if many else "that report's"
    source = "" if not archived else (
        f" {listed(archived)} {'are' if many else 'is'} read back from the "
        f"{'summaries' if many else 'summary'} earlier reports archived from "
        f"{'their sweep folders' if many else 'its sweep folder'} (`<name>_summary.csv` "
        f"beside the figures), checked run for run against the runs "
        f"{'their sweep files plan' if many else 'its sweep file plans'} today: rows, cost, "
        f"withdrawn runs and figures are {whose}.")
    lines = [SECTION_BEGIN, "## The sensitivity study as ensembles (Figs 4-6 of the paper)", "",
             f"Made by `{command}` from the sweep folders of {files} (the paper's full grids "
             "are `fig4.sweep`, `fig5.sweep` and `fig6.sweep`, and `fig6_two_tissues.sweep` "
             "the last from two tissues; the other sweep files are reduced grids or parts of "
             f"them, each saying how and why).{source} Every run has vertex "
             "insertion (the example's default). "
             "Runs stop once phi_patch falls below their sweep's phi_stop or at their step "
             "cap (both given per sweep below). Status as "
             "`tools/sweep.py summary`: only *ok* runs enter the means; an *unconverged* run "
             "(a minimum that stopped early or missed P0), a *failed* one (rings that cross "
             "themselves or are inverted, cells that interpenetrate, non-finite values) and an "
             "*error* (LAMMPS stopped it) are counted, never averaged. Means are over the seeds "
             "and initial tissues of each point (below); "
             "+- is the standard error of the mean (sample SD / sqrt(n)). delta_A is against "
             "the three points of the paper's text (`examples/sweep/reference_paper_text.txt`), "
             "not the paper's nine measured points. This section supersedes the two-seed "
             "section \"Sensitivity\" above for the paper's directions.", "",
             f"Verdict rule: a difference is **resolved** where, with no difference there, "
             f"one this large would arise by chance no more often than a normal one beyond "
             f"{RESOLVED:g} standard errors ({100 * LEVEL:.2f} %, two-sided). The difference of "
             f"the two ensemble means over its standard error follows Student's t with Welch's "
             f"degrees of freedom, whose tails are wider with few runs: resolving needs "
             f"{needed(4):.2f} standard errors with 3 runs a side, {needed(8):.2f} with 5, "
             f"{needed(18):.2f} with 10 (equal spreads), {RESOLVED:g} with very many. A "
             f"direction **holds** where the difference in the stated direction is resolved; "
             f"it **cannot be told at this resolution** where it is not; **the opposite is "
             f"resolved** where the difference against it is. Where every run of both points "
             f"gives one value (no spread), the runs cannot show the direction: *cannot be "
             f"told*. For the claims that something hardly matters or is near-optimal, no "
             f"resolved difference is consistent with the claim but does not show it: those "
             f"lines say *no difference resolved*, with the standard errors, never *holds*. "
             f"Such a claim is a family of comparisons (every lower pressure and quantity; "
             f"every other grid point), and among many, some resolve by chance: it **does not "
             f"hold** only where a difference stays resolved after Holm's correction for the "
             f"family's size, which makes the whole family as unlikely to resolve one by "
             f"chance as a single comparison. Where the accepted runs of two compared points "
             f"come from different initial tissues (a grid run in parts whose second tissue has "
             f"not run everywhere yet, or a point where every run of one tissue failed), their "
             f"difference carries the tissues' as well as the parameters': the line says so "
             f"and compares them again on the tissues both have (near-optimal: each point "
             f"against the base on the tissues they share, Holm's correction over that "
             f"family). The verdict is the pooled comparison's. The same tissues in other "
             f"proportions are not flagged.", ""]
    lines += notes + ([""] if notes else []) + ["### Directions of the paper", ""]
    # (title, figure, point, quantity, sign[, note]) of each direction of the paper
    claims = [
        ("low beta compacts", "fig5", {"beta": 30, "eps_b": 0.4}, "delta_phi_plus", +1),
        ("low eps_b compacts", "fig5", {"beta": 100, "eps_b": 0.01}, "delta_phi_plus", +1),
        ("low beta with low eps_b (the highlighted (30, 0.01)) compacts", "fig5",
         {"beta": 30, "eps_b": 0.01}, "delta_phi_plus", +1),
        ("delta_a = 0.01 with lambda = 5 compacts", "fig4", {"lambda": 5, "delta_a": 0.01},
         "delta_phi_plus", +1),
        ("few contacts at small delta_a", "fig4", {"lambda": 5, "delta_a": 0.01}, "z_half", -1),
        ("P0 = 5e-2 compacts", "fig6", {"P0": 5e-2}, "delta_phi_plus", +1),
        ("P0 = 5e-2 gives extreme calA", "fig6", {"P0": 5e-2}, "calA_final", +1,
         "calA_final: mean calA at the run's last step.")]
    # a sweep run in parts is judged as its whole grid, whose runs are the parts' runs; a part
    # that plans every point of its whole is judged on its own as well
    in_parts = {id(part) for whole in wholes for part in whole.parts
                if part not in whole.complete}
    judged = [s for s in sweeps if id(s) not in in_parts] + list(wholes)
    for kind in ("fig5", "fig4", "fig6"):
        for k, figure_sweep in enumerate([s for s in judged if s.kind == kind] or [None]):
            if kind == "fig6":
                lines += unchanged_lines(figure_sweep, BASE["fig6"])
            for title, _, values, quantity, sign, *note in (c for c in claims if c[1] == kind):
                # a further sweep of the figure without the point (fig6_ends): nothing to say;
                # the first says "not run"
                if k and figure_sweep.at(**values) is None:
                    continue
                lines.append(claim_line(title, figure_sweep, values, BASE[kind], quantity, sign,
                                        *note))
    lines += optimal_lines(judged)
    lines += ["", "### Per grid point, and what each figure cost", ""]
    whole_of = {id(part): whole for whole in wholes for part in whole.parts}
    for one in sorted(sweeps, key=lambda s: KINDS.index(s.kind), reverse=True):
        kind = one.kind
        whole = whole_of.get(id(one))
        if whole and whole.parts[0] is one:    # the whole grid before its first part
            lines += whole.lines(rel)
        runs = len(one.rows)
        done = sum(r["status"] != "unfinished" for r in one.rows)
        rate = (f"; {one.timed / (one.wall_s / 3600):.0f} runs per partition-hour"
                if one.wall_s else "")
        seeds = sorted({r["seed"] for r in one.rows}, key=int)
        tissues = sorted({tissue_name(r) for r in one.rows})
        lines += [f"**{one.name}** ({kind}): seeds {' '.join(seeds)} x tissues "
                  f"{', '.join(tissues)} per point; runs stop {one.stopping_rule()}; "
                  f"{done} of {runs} runs done; cost "
                  f"{one.loop_s / 3600:.2f} h of LAMMPS loop time (all attempts"
                  + (f", {one.withdrawn_loop_s / 3600:.2f} h of it in withdrawn runs"
                     if one.withdrawn else "") + "), "
                  f"{one.wall_s / 3600:.2f} h of partition wall time (the finishing "
                  f"attempts of {one.timed} run{'s' if one.timed != 1 else ''}{rate}; "
                  f"on a shared machine wall times "
                  f"depend on the other jobs).", ""]
        for reason, runs in one.withdrawn.items():
            many = len(runs) > 1
            lines += [f"Withdrawn: run{'s' if many else ''} {', '.join(runs)} of {one.name} "
                      f"({reason}); {'their' if many else 'its'} outputs lie in the sweep "
                      f"folder's runs/<id>/withdrawn/ (the runs, reasons and loop times in "
                      f"`{one.name}_withdrawn.csv`), {'they count' if many else 'it counts'} as "
                      f"unfinished here, and a resumed sweep runs {'them' if many else 'it'} "
                      f"again from the start.", ""]
        lines += points_table(one) + [""]
        lines += [f"![{os.path.basename(p)}]({rel(p)})" for p in one.figures] or \
            ["No figure: no run of this sweep has an accepted status."]
        lines.append("")
    lines.append(SECTION_END)
    return "\n".join(lines) + "\n"


def write_section(doc, text):
    """Replace the section between the markers in doc; the first time, put it before the
    section of tools/validate.py --published, or at the end."""
    old = open(doc).read() if os.path.exists(doc) else ""
    start, end = old.find(SECTION_BEGIN), old.find(SECTION_END)
    published = old.find(PUBLISHED_BEGIN)
    if start >= 0 and end > start:
        rest = old[end + len(SECTION_END):].lstrip("\n")
        new = old[:start] + text + ("\n" + rest if rest else "")    # one blank line after it
    elif published >= 0:
        new = old[:published] + text + "\n" + old[published:]
    else:
        new = old.rstrip("\n") + "\n\n" + text
    with open(doc, "w") as f:
        f.write(new)


def main():
    p = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    for kind in KINDS:
        lends = ("; the first lends its P0 points to the Fig 4 and 5 sweeps that lack their "
                 "base point" if kind == "fig6" else "")
        p.add_argument(f"--{kind}", metavar="DIR|CSV", nargs="+", action="extend", default=[],
                       help=f"sweep folder of {kind}*.sweep, or the <name>_summary.csv a "
                            f"report archived from one; several (or the flag again): each gets "
                            f"the figure's directions{lends}")
    p.add_argument("--sweeps", default=SWEEP_FILES,
                   help="where an archive's sweep file <name>.sweep lies")
    p.add_argument("--out", default=os.path.join(ROOT, "validation", "sweeps"))
    p.add_argument("--doc", default=os.path.join(ROOT, "doc", "validation.md"))
    p.add_argument("--accept", action="append", default=["ok"], choices=["unconverged"],
                   help="also average runs of this status (default: ok only)")
    args = p.parse_args()
    given = [(kind, source) for kind in KINDS for source in getattr(args, kind)]
    if not given:
        p.error("give at least one sweep folder (--fig4, --fig5, --fig6)")
    for kind, source in given:
        if os.path.isfile(source):
            if archive_name(source) is None:
                p.error(f"--{kind} {source}: a file must be an archived <name>_summary.csv")
        elif not os.path.isdir(os.path.join(source, "runs")):
            p.error(f"--{kind} {source}: neither a sweep folder with runs/ (plan and run the "
                    f"sweep first) nor an archived <name>_summary.csv")
    names = [archive_name(s) if os.path.isfile(s) else sweep.planned(s)[0]
             for _, s in given]
    files = [os.path.join(args.sweeps, f"{n}.sweep") if os.path.isfile(source)
             else sweep.planned(source)[1] for n, (_, source) in zip(names, given)]
    whole_files = {sweep.SweepFile(f).part_of for f in files if os.path.isfile(f)} - {None}
    twice = sorted({n for n in names if names.count(n) > 1} |
                   ({sweep.SweepFile(w).name for w in whole_files} & set(names)))
    if twice:    # their CSVs and figures in OUT would overwrite each other
        p.error(f"two sweeps named {', '.join(twice)} (or a sweep given with its parts, whose "
                f"whole grid's figure bears its name): each sweep once")
    os.makedirs(args.out, exist_ok=True)
    started = time.time()
    sweeps = [Sweep(kind, source, args.out, set(args.accept), args.sweeps)
              for kind, source in given]
    fig6 = next((s for s in sweeps if s.kind == "fig6"), None)
    # a part is judged as its whole grid, which has its own base point or none
    notes = [s.borrow_base(fig6) for s in sweeps if s.kind != "fig6" and not s.part_of]
    # the command as typed from the package's folder, with every option that changes the
    # section (not --out and --doc, where it goes), so that it can be run again
    words = [w for kind in KINDS if getattr(args, kind)
             for w in [f"--{kind}"] + [shown(s) for s in getattr(args, kind)]]
    words += [w for status in args.accept[1:] for w in ("--accept", status)]
    if os.path.abspath(args.sweeps) != os.path.abspath(SWEEP_FILES):
        words += ["--sweeps", shown(args.sweeps)]
    command = "tools/sweep_report.py " + " ".join(shlex.quote(w) for w in words)
    wholes = wholes_of(sweeps, args.out, set(args.accept))
    write_section(args.doc, section(sweeps, os.path.dirname(os.path.abspath(args.doc)),
                                    command, [n for n in notes if n], wholes))
    print(f"wrote {args.doc} (section {SECTION_BEGIN}) and {len(sweeps)} sweeps' CSVs and PNGs "
          f"in {args.out} ({time.time() - started:.0f} s)")


if __name__ == "__main__":
    main()
