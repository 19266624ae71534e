#!/usr/bin/env python3
"""tools/sweep_report.py on sweep folders with made-up results, whose verdicts are known.

    check_sweep_report.py

Plans three small sweeps with tools/sweep.py (a Fig 6 one over P0, a Fig 5 one at P0 = 1e-5
without its base point, one at P0 = 1e-4, which the Fig 6 sweep lacks), writes for each run the
files a finished run leaves (growth table, log with fix dpoly/check lines, the marker
`finished`, times.txt) with chosen numbers instead of running LAMMPS, and runs the report into
a copy of a validation.md. Checks, against means and standard errors computed here:

  * P0 = 5e-2 compacts: holds, from the two ok runs only; the third run of that point has a
    ring that crosses itself (a FAILED check line) and an absurd delta_phi_plus, and must be
    counted as failed, never averaged;
  * P0 up to 1e-3 hardly matters: no difference resolved (the 1e-5 and 1e-7 runs differ from
    the 1e-3 ones by less than two standard errors), which the line must not call "holds";
    every lower pressure of the sweep is compared;
  * low eps_b compacts: the opposite is resolved (its runs compact less); low beta compacts:
    not resolved (equal means);
  * the Fig 5 sweep borrows the Fig 6 sweep's P0 = 1e-5 runs as its base point (same step cap); one
    capped at 5 growth steps does not borrow runs that ended at the cap of 3; the one at
    P0 = 1e-4 borrows nothing and says so; one of its runs ends at the iteration limit (fix
    dpoly/check's words in its log) and must be *unconverged*, not *failed*;
  * the verdict functions on hand-made ensembles: points whose runs all give 0 (no spread)
    cannot tell a direction (never "does not hold"); no resolved difference reads "no
    difference resolved", never "holds", and a point with too few runs is not counted as
    compared;
  * the section is replaced in place: a second report leaves one section, and the text around
    it (and a section of tools/validate.py --published) unchanged;
  * archives: the report read back from the CSVs a report archived (OUT/<name>_summary.csv)
    gives the same directions, tables, costs and withdrawn runs as the report of the folders,
    borrowing included; an archive whose sweep file now plans other runs is refused; a base
    point is borrowed only where tmaxadapt agrees (unset reads as the protocol's default: 'no'
    for in.mesophyll, 'yes' for a sweep whose own protocol says so);
  * two sweeps of one figure: each gets the figure's directions and table, the first lends the
    base point; the flag given twice reads as one; the section names each sweep by the file
    it was planned from; a sweep given twice is refused;
  * a sweep run in parts: judged as its whole grid (a point of one part against the base of
    another), its heatmaps drawn from a part's folder and, from its archive, kept where they
    were drawn from the same runs; parts that each plan only some points get no directions of
    their own; a Fig 6 whole run as two complete grids, one per tissue, pools both tissues'
    runs per point (directions, a table and P0 figure of its own, drawn again only where the
    parts given change) while each part keeps its own directions;
  * bad input: no sweep, a folder without runs, a file that is not <name>_summary.csv, a
    missing archive.
Exit 77 (skipped) without python3-matplotlib, which the figures need.
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SWEEP = os.path.join(ROOT, "tools", "sweep.py")
REPORT = os.path.join(ROOT, "tools", "sweep_report.py")
TISSUE = os.path.join(ROOT, "examples", "tissue", "tissue_N16.data")
VORONOI = os.path.join(ROOT, "examples", "tissue", "voronoi_N16.data")
problems = []

# delta_phi_plus of each run, by point and seed (seed 3 of P0 = 5e-2 is the failed run; its two
# accepted runs, 1 degree of freedom, resolve only a large difference: 80 standard errors)
DPHI = {"P0=1e-3": [0.001, 0.002, 0.003], "P0=5e-2": [0.05, 0.0502, 10.0],
        "P0=1e-5": [0.0015, 0.0025, 0.0030], "P0=1e-7": [0.0012, 0.0021, 0.0033],
        "beta=30 eps_b=0.4": [0.0015, 0.0025, 0.0030],
        "beta=100 eps_b=0.01": [0.0, 0.0001, 0.0002],
        "beta=100 eps_b=0.4": [0.0010, 0.0012, 0.0014]}
FAILED = ("P0=5e-2", "3")
FIG6_POINTS = ["P0=1e-3 ftol=1e-10", "P0=5e-2 ftol=1e-10", "P0=1e-5 ftol=1e-11",
               "P0=1e-7 ftol=1e-11"]


def expect(condition, message):
    if not condition:
        problems.append(message)
    return condition


def plan(scratch, name, parameters, points, fixed, protocol=None):
    path = os.path.join(scratch, f"{name}.sweep")
    with open(path, "w") as f:
        f.write(f"name {name}\nparameters {os.path.join(ROOT, 'potentials', parameters)}\n"
                + (f"protocol {protocol}\n" if protocol else "") +
                "set base\n" + "".join(f"point {p}\n" for p in points) +
                f"seeds 1 2 3\ntissue {TISSUE}\nfixed {fixed}\n")
    folder = os.path.join(scratch, name)
    subprocess.run([sys.executable, SWEEP, "plan", path, folder], check=True,
                   stdout=subprocess.DEVNULL)
    return folder


def fake_results(folder, unconverged=(), offset=0.0):
    """Per run the files a finished run leaves, with delta_phi_plus from DPHI (plus offset); the
    runs of unconverged ((point, seed) pairs) end on a minimum that reached the iteration
    limit."""
    import json
    for run in sorted(os.listdir(os.path.join(folder, "runs"))):
        where = os.path.join(folder, "runs", run)
        record = json.load(open(os.path.join(where, "run.json")))
        point = " ".join(p for p in record["point"].split() if not p.startswith("ftol"))
        seed = record["seed"]
        dphi = DPHI[point][int(seed) - 1] + offset
        with open(os.path.join(where, "growth.N16.txt"), "w") as f:
            f.write("# step P phi phi_patch calA z bonds dphi_plus iterations\n")
            for step, (phi, calA) in enumerate([(0.93, 1.14), (0.70, 1.5), (0.50, 2.1)], 1):
                f.write(f"{step} 1e-3 {phi - 0.1} {phi} {calA} 4.5 300 "
                        f"{dphi * (step - 1) / 2} 1000\n")
        failed = (point, seed) == FAILED
        # fix dpoly/check's words for a tangled ring and for the iteration limit
        problem = ("; FAILED; 1 rings cross themselves (first: cell 2)" if failed else
                   "; FAILED; the minimizer stopped without converging (max iterations), "
                   "shortest ring segment relative to its preferred length: 7-8 of cell 2, "
                   "0.016 long, 3.2% of l0 = 0.5"
                   if (point, seed) in unconverged else "")
        with open(os.path.join(where, "log.lammps"), "w") as f:
            for k in range(1, 4):
                f.write(f"fix dpoly/check: minimum {k} at step {k * 100}: force tolerance, "
                        f"force norm 1e-11, |P - P0|/P0 1e-10" + (problem if k == 3 else "")
                        + "\n")
            f.write("Loop time of 2.5 on 1 procs for 100 steps with 512 atoms\n")
        with open(os.path.join(where, "times.txt"), "w") as f:
            f.write(f"start {1000 + int(run) * 10}\nend {1005 + int(run) * 10}\n")
        with open(os.path.join(where, "finished"), "w") as f:
            f.write("finished\n")


def withdraw(run):
    """Withdraw a finished run: its outputs into withdrawn/, with the reason."""
    os.makedirs(os.path.join(run, "withdrawn"))
    for name in os.listdir(run):
        if name not in ("run.json", "run.lmp", "withdrawn"):
            os.replace(os.path.join(run, name), os.path.join(run, "withdrawn", name))
    with open(os.path.join(run, "withdrawn", "REASON.txt"), "w") as f:
        f.write("a made-up\nreason\n")


def mean_se(values):
    m = sum(values) / len(values)
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))
    return m, sd / math.sqrt(len(values))


def mean_se_text(values):
    """A mean and its standard error as the report prints them."""
    m, se = mean_se(values)
    return f"{m:.4g} +- {se:.2g} (n = {len(values)})"


def line_of(text, title):
    found = [line for line in text.splitlines() if line.startswith(f"- *{title}*")]
    expect(len(found) == 1, f"the section has {len(found)} lines for '{title}'")
    return found[0] if found else ""


def check_claim(text, title, point, other, verdict, counts=None):
    line = line_of(text, title)
    ok = [v for s, v in enumerate(DPHI[point], 1) if (point, str(s)) != FAILED]
    for values in (ok, DPHI[other]):
        m, se = mean_se(values)
        want = f"{m:.4g} +- {se:.2g} (n = {len(values)})"
        expect(want in line, f"'{title}': expected '{want}' in: {line}")
    m1, se1 = mean_se(ok)
    m2, se2 = mean_se(DPHI[other])
    score = (m1 - m2) / math.hypot(se1, se2)
    expect(f"difference {score:+.1f} standard errors" in line,
           f"'{title}': expected a difference of {score:+.1f} standard errors in: {line}")
    expect(verdict in line, f"'{title}': expected '{verdict}' in: {line}")
    if counts:
        expect(counts in line, f"'{title}': expected '{counts}' in: {line}")


class StubSweep:
    """What claim_line, unchanged_lines and optimal_lines read of a sweep: a name, its figure,
    its rows, the Ensemble at grid values, and the points in order."""

    def __init__(self, report, name, points, kind="fig6"):
        self.name, self.kind = name, kind
        self.rows = [dict(r, **{k: f"{x:g}" for k, x in values.items()})
                     for values, rows in points for r in rows]
        self.table = [(values, report.Ensemble(rows, {"ok"})) for values, rows in points]

    def at(self, **values):
        return next((e for v, e in self.table if v == values), None)

    def points(self):
        return [(" ".join(f"{k}={x:g}" for k, x in v.items()), e) for v, e in self.table]


def runs(quantity, values, status="ok"):
    return [{"status": status, quantity: str(v), "steps": "5", "phi_final": "0.44",
             "phi_half": "0.5"} for v in values]


def many(quantity, mean, score=0.0, n=200, d=0.02):
    """n runs of mean + score standard errors of a difference with a point of the same spread
    (values mean +- d alternating): 398 degrees of freedom, nearly normal tails."""
    shift = score * d * math.sqrt(2 / (n - 1))
    return runs(quantity, [mean + shift + (d if k % 2 else -d) for k in range(n)])


def check_verdict_rules():
    sys.path.insert(0, os.path.join(ROOT, "tools"))
    import sweep_report as report
    # every run of both points gives delta_phi_plus 0: the runs cannot show compaction
    flat = StubSweep(report, "flat", [({"beta": 30}, runs("delta_phi_plus", [0, 0, 0])),
                                      ({"beta": 100}, runs("delta_phi_plus", [0, 0, 0]))])
    line = report.claim_line("low beta compacts", flat, {"beta": 30}, {"beta": 100},
                             "delta_phi_plus", +1)
    expect("**cannot be told**" in line and "cannot show" in line and "does not hold" not in
           line, f"equal values without spread: not 'cannot be told': {line}")
    # means 1.00 and 1.02 with SE 0.0115 each: 1.2 SE apart, not resolved; a third pressure with
    # one accepted run is not compared and not counted as resolved
    close = StubSweep(report, "close", [
        ({"P0": 1e-3}, runs("delta_A_early", [0.98, 1.0, 1.02])),
        ({"P0": 1e-5}, runs("delta_A_early", [1.0, 1.02, 1.04])),
        ({"P0": 1e-4}, runs("delta_A_early", [5.0]) + runs("delta_A_early", [9.0], "failed"))])
    lines = report.unchanged_lines(close, {"P0": 1e-3})
    head = lines[0]
    expect("**no difference resolved** in 1 comparison " in head and "**holds**" not in head
           and "does not hold" not in head and "in 1 comparison " in head,
           f"no resolved difference: not 'no difference resolved' in 1 comparison: {head}")
    expect(any("difference +1.2 standard errors (SE of the difference 0.016; resolving needs "
               "2.87)" in x for x in lines),
           f"the per-line difference, its SE and what 3 runs a side need: {lines}")
    expect(any("at P0 = 0.0001" in x and "not compared" in x for x in lines),
           f"the pressure with one accepted run is not marked 'not compared': {lines}")
    # a resolved difference among the lower pressures: 'does not hold', with how many of that
    # many comparisons chance alone would resolve (4.55 % each, two-sided)
    apart = StubSweep(report, "apart", [
        ({"P0": 1e-3}, runs("delta_A_early", [0.98, 1.0, 1.02])),
        ({"P0": 1e-5}, runs("delta_A_early", [1.1, 1.12, 1.14])),
        ({"P0": 1e-6}, runs("delta_A_early", [1.0, 1.02, 1.04]))])
    head = report.unchanged_lines(apart, {"P0": 1e-3})[0]
    expect("**does not hold**: 1 of 2 stays resolved once corrected for the 2 comparisons "
           "(Holm); 1 of 2 resolves alone (with no difference at all, 2 comparisons would "
           "resolve 0.091 by chance)" in head,
           f"a resolved lower pressure (+7.3 SE): not 'does not hold' with the chance note: "
           f"{head}")
    # Student's t: 2.5 standard errors with 3 runs a side (4 degrees of freedom) are not
    # resolved, it needs 2.87; with 200 runs a side (nearly normal) they are
    few = StubSweep(report, "few", [
        ({"beta": 30}, runs("delta_phi_plus", [1.0208, 1.0408, 1.0608])),
        ({"beta": 100}, runs("delta_phi_plus", [0.98, 1.0, 1.02]))])
    line = report.claim_line("low beta compacts", few, {"beta": 30}, {"beta": 100},
                             "delta_phi_plus", +1)
    expect("difference +2.5 standard errors" in line and "**cannot be told at this resolution** "
           "(resolving needs 2.87 standard errors with these runs)" in line,
           f"2.5 SE with 3 runs a side: not 'cannot be told' with 2.87 needed: {line}")
    lots = StubSweep(report, "lots", [({"beta": 30}, many("delta_phi_plus", 1.0, 2.5)),
                                      ({"beta": 100}, many("delta_phi_plus", 1.0))])
    line = report.claim_line("low beta compacts", lots, {"beta": 30}, {"beta": 100},
                             "delta_phi_plus", +1)
    expect("difference +2.5 standard errors: **holds**" in line,
           f"2.5 SE with 200 runs a side: not 'holds': {line}")
    # Holm steps down: of two differences at 2.5 and 2.1 SE the larger needs 2.29 SE (4.55 % /
    # 2), the smaller then 2.01 SE (4.55 %; 398 degrees of freedom): both stay (Bonferroni's
    # 2.29 for both would keep one)
    stepped = StubSweep(report, "stepped", [
        ({"P0": 1e-3}, many("delta_A_early", 1.0)),
        ({"P0": 1e-5}, many("delta_A_early", 1.0, 2.5)),
        ({"P0": 1e-6}, many("delta_A_early", 1.0, -2.1))])
    head = report.unchanged_lines(stepped, {"P0": 1e-3})[0]
    expect("**does not hold**: 2 of 2 stay resolved once corrected for the 2 comparisons (Holm)"
           in head, f"differences at +2.5 and -2.1 SE: not both kept by Holm's step-down: {head}")
    # one of two differences at +2.2 SE: resolved alone (2.01 needed), but Holm asks the
    # stronger of two for a two-sided tail of 4.55 % / 2, i.e. 2.29 SE: not 'does not hold'
    borderline = StubSweep(report, "borderline", [
        ({"P0": 1e-3}, many("delta_A_early", 1.0)),
        ({"P0": 1e-5}, many("delta_A_early", 1.0, 2.2)),
        ({"P0": 1e-6}, many("delta_A_early", 1.0, 0.5))])
    head = report.unchanged_lines(borderline, {"P0": 1e-3})[0]
    expect("**no difference resolved** once corrected: 1 of 2 resolves alone" in head
           and "none stays resolved once corrected for the 2 comparisons (Holm): the strongest, "
           "2.2 standard errors in size, is below the 2.29 the correction asks of it" in head
           and "does not hold" not in head and "**holds**" not in head,
           f"one of two differences at 2.2 SE: not 'no difference resolved once corrected': "
           f"{head}")
    # Holm on Student's t: 2.4 SE with 10 runs a side (18 degrees of freedom) resolve alone
    # (2.15 needed) but not as the stronger of two (2.49; normal tails would keep it at 2.28)
    ten = StubSweep(report, "ten", [
        ({"P0": 1e-3}, many("delta_A_early", 1.0, n=10)),
        ({"P0": 1e-5}, many("delta_A_early", 1.0, 2.4, n=10)),
        ({"P0": 1e-6}, many("delta_A_early", 1.0, 0.5, n=10))])
    head = report.unchanged_lines(ten, {"P0": 1e-3})[0]
    expect("1 of 2 resolves alone" in head and "the strongest, 2.4 standard errors in size, is "
           "below the 2.49 the correction asks of it" in head and "does not hold" not in head,
           f"2.4 SE of two with 10 runs a side: not 'no difference resolved once corrected' "
           f"with 2.49 asked: {head}")
    # the base point of the default: no point resolved lower, and how many could be compared
    base = StubSweep(report, "base", [
        ({"P0": 1e-3}, runs("delta_A_early", [0.98, 1.0, 1.02])),
        ({"P0": 1e-5}, runs("delta_A_early", [1.0, 1.02, 1.04])),
        ({"P0": 1e-4}, runs("delta_A_early", [0.5]))])
    optimal = [x for x in report.optimal_lines([base]) if "delta_A_early" in x]
    expect(len(optimal) == 1 and "**holds**" not in optimal[0] and
           "no point resolved lower" in optimal[0] and "among the 1 of 2 other points" in
           optimal[0] and "rank 2 of the 3 points" in optimal[0],
           f"near-optimal without a resolved difference: {optimal}")
    # a point resolved lower than the base: 'does not hold', with the one-sided chance (2.28 %)
    lower = StubSweep(report, "lower", [
        ({"P0": 1e-3}, runs("delta_A_early", [0.98, 1.0, 1.02])),
        ({"P0": 1e-5}, runs("delta_A_early", [0.5, 0.52, 0.54])),
        ({"P0": 1e-4}, runs("delta_A_early", [1.0, 1.02, 1.04]))])
    optimal = [x for x in report.optimal_lines([lower]) if "delta_A_early" in x]
    expect(len(optimal) == 1 and "**does not hold**: resolved lower at P0=1e-05 (0.52); 1 of 2 "
           "stays resolved once corrected for the 2 comparisons (Holm); 1 of 2 resolves alone "
           "(with no difference at all, 2 comparisons would resolve 0.046 by chance)"
           in optimal[0],
           f"near-optimal with a point resolved lower: {optimal}")
    # a point lower by 2.2 SE of two: one-sided, Holm asks the stronger of two for 2.28 % / 2,
    # i.e. 2.29 SE: not 'does not hold'
    slightly = StubSweep(report, "slightly", [
        ({"P0": 1e-3}, many("delta_A_early", 1.0)),
        ({"P0": 1e-5}, many("delta_A_early", 1.0, -2.2)),
        ({"P0": 1e-4}, many("delta_A_early", 1.0, 0.5))])
    optimal = [x for x in report.optimal_lines([slightly]) if "delta_A_early" in x]
    expect(len(optimal) == 1 and "**no point resolved lower** once corrected, among the 2 of 2 "
           "other points" in optimal[0] and "resolved lower alone: P0=1e-05 (0.996)"
           in optimal[0] and "the strongest, 2.2 standard errors in size, is below the 2.29"
           in optimal[0] and "does not hold" not in optimal[0],
           f"near-optimal with a point lower by 2.2 SE of two: {optimal}")
    check_tissue_sets(report)


def from_tissue(tissue, rows):
    return [dict(r, tissue=f"examples/tissue/{tissue}") for r in rows]


def check_tissue_sets(report):
    """Points whose accepted runs come from different tissues (a whole grid with one tissue's
    part not yet run): the base pools tissues a (1.0) and b (1.2), the point beta=30 has tissue
    a alone (1.0). Pooled, beta=30 is far lower than the base; on tissue a alone, not at all:
    the report must say that the tissues differ and give the comparison on the shared one."""
    base_runs = (from_tissue("a.data", many("delta_A_early", 1.0))
                 + from_tissue("b.data", many("delta_A_early", 1.2)))
    one = from_tissue("a.data", many("delta_A_early", 1.0, 0.5))
    both = (from_tissue("a.data", many("delta_A_early", 1.0, 0.5))
            + from_tissue("b.data", many("delta_A_early", 1.2, 0.5)))
    mixed = StubSweep(report, "mixed", [({"beta": 100, "eps_b": 0.4}, base_runs),
                                        ({"beta": 30, "eps_b": 0.4}, one),
                                        ({"beta": 50, "eps_b": 0.4}, both)], kind="fig5")
    optimal = [x for x in report.optimal_lines([mixed]) if "delta_A_early" in x]
    expect(len(optimal) == 1 and "**does not hold**: resolved lower at beta=30 eps_b=0.4 (1)"
           in optimal[0]
           and "tissues differ: 1 of the 2 compared points has accepted runs from other "
           "tissues than the base's (a.data and b.data), so its difference carries" in optimal[0]
           and "(2 comparisons), none stays resolved lower once corrected (Holm)" in optimal[0],
           f"near-optimal with a point of one tissue against a base of two: the pooled verdict "
           f"without the note, or the matched family wrong: {optimal}")
    line = report.claim_line("low beta compacts", mixed, {"beta": 30, "eps_b": 0.4},
                             {"beta": 100, "eps_b": 0.4}, "delta_A_early", -1)
    expect("**holds**" in line and "Tissues differ: the accepted runs at beta = 30, eps_b = 0.4 "
           "are from a.data, at beta = 100, eps_b = 0.4 from a.data and b.data" in line
           and "on a.data alone: -0.5 standard errors, not resolved." in line,
           f"a claim between points of different tissues: no note, or not the shared tissue's "
           f"comparison: {line}")
    line = report.claim_line("low beta compacts", mixed, {"beta": 50, "eps_b": 0.4},
                             {"beta": 100, "eps_b": 0.4}, "delta_A_early", -1)
    expect("Tissues differ" not in line,
           f"a claim between points of the same tissues carries the tissue note: {line}")


def section_after(text, heading):
    """The generated section from heading on (the opening names the command and sources)."""
    body = text[text.find("<!-- sweeps"):text.find("<!-- /sweeps -->")]
    return body[body.find(heading):] if heading in body else ""


def report(args, doc, out, sweeps=None):
    command = [sys.executable, REPORT] + args + ["--out", out, "--doc", doc]
    result = subprocess.run(command + (["--sweeps", sweeps] if sweeps else []),
                            capture_output=True, text=True)
    return result, open(doc).read()


def report_without_base(scratch, fig6, doc, out, name, fixed, protocol=None):
    """The report of a Fig 5 sweep of (30, 0.4) alone, which lacks its base point, with the Fig
    6 sweep fig6 that may lend it."""
    folder = plan(scratch, name, "fig5.mesophyll", ["beta=30 eps_b=0.4"], fixed, protocol)
    fake_results(folder)
    return report(["--fig6", fig6, "--fig5", folder], doc, out)


def check_two_of_a_figure(scratch, fig6, fig5, out):
    """Two Fig 6 sweeps (fig6_u, planned from its own file with fig6_t's grid): each gets the
    figure's directions and its own table, the first lends the base point; one sweep given
    twice is refused (its files in OUT would overwrite each other), also as a copy of its
    folder under another name, which keeps the sweep's name."""
    doc = os.path.join(scratch, "doc", "validation.md")
    other = plan(scratch, "fig6_u", "fig6.mesophyll", FIG6_POINTS, "steps 3 phi_stop 0.45")
    fake_results(other)
    result, text = report(["--fig6", fig6, other, "--fig5", fig5], doc, out)
    expect(result.returncode == 0, f"two Fig 6 sweeps: {result.stderr}")
    # each sweep by the file its folder was planned from
    files = [f"`{os.path.join(scratch, name)}.sweep`" for name in ("fig5_t", "fig6_t", "fig6_u")]
    expect(f"from the sweep folders of {files[0]}, {files[1]} and {files[2]} (" in text,
           "two Fig 6 sweeps: the section does not name the sweep files the folders came from")
    for name in ("fig6_t", "fig6_u"):
        compacts = [line for line in text.splitlines()
                    if line.startswith(f"- *P0 = 5e-2 compacts* (delta_phi_plus; {name})")]
        expect(len(compacts) == 1 and "**holds**" in compacts[0]
               and f"**{name}** (fig6)" in text and f"*P0 up to 1e-3 hardly matters* ({name})"
               in text, f"two Fig 6 sweeps: {name} lacks its directions or its table")
    expect("fig6_t's P0 = 1e-05 point" in text and "fig6_u's P0" not in text,
           "two Fig 6 sweeps: the base point is not borrowed from the first")
    expect(f"--fig5 {fig5} --fig6 {fig6} {other}`" in text,
           "two Fig 6 sweeps: the section does not give the command as run")
    # the flag given twice: the same sweeps as one flag with two folders
    result, again = report(["--fig6", fig6, "--fig6", other, "--fig5", fig5], doc, out)
    expect(result.returncode == 0 and section_after(again, "### Directions") ==
           section_after(text, "### Directions"),
           "--fig6 A --fig6 B: not the report of --fig6 A B")
    result, _ = report(["--fig6", fig6, os.path.join(out, "fig6_t_summary.csv")], doc, out)
    expect(result.returncode != 0 and "two sweeps named fig6_t" in result.stderr,
           f"one sweep given twice: exit code {result.returncode}, {result.stderr.strip()}")
    # a copy of fig6_t's folder under another name is still sweep fig6_t
    copy = os.path.join(scratch, "fig6_copy")
    shutil.copytree(fig6, copy)
    result, _ = report(["--fig6", fig6, copy], doc, out)
    expect(result.returncode != 0 and "two sweeps named fig6_t" in result.stderr,
           f"a copied sweep folder: exit code {result.returncode}, {result.stderr.strip()}")
    result, text = report(["--fig6", copy], doc, out)
    expect(result.returncode == 0 and "**fig6_t** (fig6)" in text and "fig6_copy**" not in text,
           f"a renamed sweep folder is not reported as its sweep, fig6_t: {result.stderr}")
    shutil.rmtree(copy)
    # a further Fig 6 sweep without P0 = 5e-2 has no lines about that point; alone it has
    ends = plan(scratch, "fig6_v", "fig6.mesophyll", ["P0=1e-3 ftol=1e-10", "P0=1e-7 ftol=1e-11"],
                "steps 4 phi_stop 0.4")
    fake_results(ends)
    missing = "not run (fig6_v has no point P0 = 0.05)"
    result, text = report(["--fig6", fig6, ends], doc, out)
    expect(result.returncode == 0 and missing not in text and
           "*P0 up to 1e-3 hardly matters* (fig6_v)" in text,
           "a second Fig 6 sweep without P0 = 5e-2: 'not run' lines, or no lines of its own")
    result, text = report(["--fig6", ends], doc, out)
    expect(result.returncode == 0 and text.count(missing) == 2,
           "the only Fig 6 sweep without P0 = 5e-2 does not say so")
    expect("runs stop below phi_patch 0.4 or after 4 growth steps;" in text,
           "a sweep with phi_stop 0.4 and 4 steps does not give its own stopping rule")


def check_archives(scratch, fig6, from_folders_of, out):
    """A report from the CSVs a report archived reads what the report from the folders read
    (from_folders_of: {Fig 5 sweep name: the document its report with fig6 wrote}): the same
    directions, tables, costs and withdrawn runs (borrowing included, with the runs' variables
    from the plan of the sweep files); an archive the sweep file no longer plans is refused;
    tmaxadapt must agree for a base point to be borrowed (unset reads 'no')."""
    doc = os.path.join(scratch, "doc", "validation.md")
    archive = lambda name: os.path.join(out, f"{name}_summary.csv")  # noqa: E731
    for name, from_folders in from_folders_of.items():
        result, from_archives = report(["--fig6", archive("fig6_t"), "--fig5", archive(name)],
                                       doc, out, scratch)
        expect(result.returncode == 0, f"report of the archives: {result.stderr}")
        folders_part = section_after(from_folders, "### Directions of the paper")
        expect(folders_part and folders_part == section_after(from_archives,
                                                              "### Directions of the paper"),
               f"{name}: the report of the archives differs from that of the folders")
        expect(f"{name} and fig6_t are read back from the summaries" in from_archives,
               f"{name}: the section does not say that its sweeps came from archives")
        expect(f"`{os.path.join(scratch, name)}.sweep`" in from_archives,
               f"{name}: the section does not name the sweep file of --sweeps")
    expect("Withdrawn: run 1 of fig5_cap" in from_archives and
           os.path.exists(os.path.join(out, "fig5_cap_withdrawn.csv")),
           "the archive of fig5_cap lost its withdrawn run")
    # the sweep file changed since (two seeds, not three): its archive is refused
    changed = os.path.join(scratch, "changed")
    os.makedirs(changed)
    text = open(os.path.join(scratch, "fig5_t.sweep")).read()
    with open(os.path.join(changed, "fig5_t.sweep"), "w") as f:
        f.write(text.replace("seeds 1 2 3", "seeds 1 2"))
    shutil.copy(os.path.join(scratch, "fig6_t.sweep"), changed)
    result, _ = report(["--fig6", archive("fig6_t"), "--fig5", archive("fig5_t")], doc, out,
                       changed)
    expect(result.returncode != 0 and "is not the sweep" in result.stderr,
           f"an archive of another plan was read: exit {result.returncode}, {result.stderr}")
    # tmaxadapt: 'no' as a fixed value borrows from runs that leave it unset; 'yes' does not
    for value, borrows in (("no", True), ("yes", False)):
        folder = plan(scratch, f"fig5_adapt_{value}", "fig5.mesophyll",
                      ["beta=30 eps_b=0.4", "beta=100 eps_b=0.01"],
                      f"steps 3 phi_stop 0.45 P0 1e-5 ftol 1e-11 tmaxadapt {value}")
        fake_results(folder)
        result, text = report(["--fig6", fig6, "--fig5", folder], doc, out)
        borrowed = f"fig5_adapt_{value}'s base point" in text
        refused = "differ in tmaxadapt: none borrowed" in text
        expect(result.returncode == 0 and borrowed == borrows and refused != borrows,
               f"tmaxadapt {value}: borrowed {borrowed}, refused {refused}, expected "
               f"borrowed {borrows}: {result.stderr}")
    # a sweep on its own protocol, whose default is tmaxadapt yes: its runs leave tmaxadapt
    # unset, as fig6_t's do, but read 'yes' from that protocol, so they borrow nothing
    protocol = os.path.join(scratch, "protocol", "in.mesophyll")
    os.makedirs(os.path.dirname(protocol))
    text = open(os.path.join(ROOT, "examples", "mesophyll", "in.mesophyll")).read()
    default = re.compile(r"^(variable\s+tmaxadapt\s+index\s+)no\b", re.MULTILINE)
    expect(len(default.findall(text)) == 1, "in.mesophyll: no 'variable tmaxadapt index no'")
    with open(protocol, "w") as f:
        f.write(default.sub(r"\g<1>yes", text))
    result, text = report_without_base(scratch, fig6, doc, out, "fig5_own",
                                       "steps 3 phi_stop 0.45 P0 1e-5 ftol 1e-11", protocol)
    expect(result.returncode == 0 and "fig5_own has no base point; fig6_t's P0 = 1e-05 runs "
           "differ in tmaxadapt: none borrowed" in text,
           f"a sweep whose own protocol defaults to tmaxadapt yes borrowed from one that runs "
           f"'no': {result.stderr}")


def check_parts(scratch, out):
    """A sweep run in parts: a part given alone draws the heatmaps of the whole grid, its runs
    at their points and the whole's other runs unfinished, and the section says how much of
    the whole is done; from the part's archive the heatmaps are kept, not drawn again; the
    whole given with its part is refused (their figures would bear one name). The verdicts
    are the whole's: a point of one part against the base point of another."""
    whole = os.path.join(scratch, "fig5_w.sweep")
    common = (f"parameters {os.path.join(ROOT, 'potentials', 'fig5.mesophyll')}\nset base\n"
              f"seeds 1 2 3\ntissue {TISSUE}\nfixed steps 3 phi_stop 0.45 P0 1e-5 ftol 1e-11\n")
    with open(whole, "w") as f:
        f.write("name fig5_w\npoint beta=30 eps_b=0.4\npoint beta=100 eps_b=0.01\n"
                "point beta=100 eps_b=0.4\n" + common)
    folders = []
    for name, point in (("fig5_wa", "beta=30 eps_b=0.4"), ("fig5_wb", "beta=100 eps_b=0.4")):
        part = os.path.join(scratch, f"{name}.sweep")
        with open(part, "w") as f:
            f.write(f"name {name}\npart_of fig5_w.sweep\npoint {point}\n" + common)
        folders.append(os.path.join(scratch, name))
        subprocess.run([sys.executable, SWEEP, "plan", part, folders[-1]], check=True,
                       stdout=subprocess.DEVNULL)
        fake_results(folders[-1])
    folder = folders[0]
    doc = os.path.join(scratch, "doc", "validation.md")
    result, text = report(["--fig5", folder], doc, out)
    png = os.path.join(out, "fig5_w_heatmaps.png")
    expect(result.returncode == 0 and os.path.exists(png),
           f"a part alone: no heatmaps of its whole: {result.stderr}")
    expect("**fig5_w** (fig5, the whole grid of" in text and
           "3 of 9 runs done, from its part fig5_wa (3 ok, 6 unfinished)" in text and
           "![fig5_w_heatmaps.png]" in text,
           "the section does not give the whole grid's progress and heatmaps")
    alone = line_of(text, "low beta compacts")
    expect("(delta_phi_plus; fig5_w)" in alone and "[3 unfinished]" in alone and
           "fewer than two accepted runs" in alone,
           f"a part without the base: its whole's low-beta line does not say that the base is "
           f"unfinished: {alone}")
    # the base point in the second part: the first part's point is judged against it
    result, both = report(["--fig5"] + folders, doc, out)
    expect(result.returncode == 0, f"two parts: exit {result.returncode}, {result.stderr}")
    check_claim(both, "low beta compacts", "beta=30 eps_b=0.4", "beta=100 eps_b=0.4",
                "**cannot be told at this resolution** (resolving needs 4.02",
                "(delta_phi_plus; fig5_w)")
    expect("6 of 9 runs done, from its parts fig5_wa and fig5_wb" in both,
           "two parts: the whole's progress is not both parts'")
    drawn = list(csv.DictReader(open(os.path.join(out, "fig5_w_heatmaps.csv"))))
    m, _ = mean_se(DPHI["beta=30 eps_b=0.4"])
    at = {(r["beta"], r["eps_b"]): r for r in drawn if r["quantity"] == "delta_phi_plus"}
    expect(abs(float(at["30.0", "0.4"]["mean"]) - m) < 1e-12 and
           at["30.0", "0.4"]["runs"] == "3" and ("100.0", "0.01") not in at,
           f"the whole's heatmap: not the part's runs at beta 30 and none at beta 100: {at}")
    # drawn of both parts' runs, so drawn again of the one part's; then kept
    archive = os.path.join(out, "fig5_wa_summary.csv")
    result, _ = report(["--fig5", archive], doc, out, scratch)
    expect(result.returncode == 0, f"the part's archive: exit {result.returncode}, "
                                   f"{result.stderr}")
    stamp = os.path.getmtime(png)
    result, text = report(["--fig5", archive], doc, out, scratch)
    expect(result.returncode == 0 and os.path.getmtime(png) == stamp and
           "![fig5_w_heatmaps.png]" in text,
           f"from the part's archive: the whole's heatmaps drawn again or not linked: "
           f"{result.stderr}")
    expect("fig5_wa)" not in line_of(both, "low beta compacts") and
           "plans every point of the whole" not in both,
           "a part with one point of its whole's three is judged on its own")
    whole_folder = os.path.join(scratch, "fig5_w")
    subprocess.run([sys.executable, SWEEP, "plan", whole, whole_folder], check=True,
                   stdout=subprocess.DEVNULL)
    result, _ = report(["--fig5", folder, whole_folder], doc, out)
    expect(result.returncode != 0 and "each sweep once" in result.stderr,
           f"the whole given with its part: exit {result.returncode}, {result.stderr}")


def check_pooled_parts(scratch, out):
    """A Fig 6 grid from two tissues, run as two parts that each plan every point from one
    tissue (as fig6.sweep and fig6_voronoi.sweep of fig6_two_tissues.sweep): the whole's
    directions pool both parts' runs per point, each part keeps directions of its own, the
    whole gets a table and its figure against P0, drawn from the parts' archives where no
    report drew it, drawn again where one drew it from fewer parts, and kept where one drew it
    from the same runs. The second tissue's runs compact 0.01 more, so that the pooled means
    are neither part's."""
    points = "".join(f"point {p}\n" for p in FIG6_POINTS[:2])
    common = (f"parameters {os.path.join(ROOT, 'potentials', 'fig6.mesophyll')}\nset base\n"
              f"seeds 1 2 3\nfixed steps 3 phi_stop 0.45\n")
    with open(os.path.join(scratch, "fig6_pw.sweep"), "w") as f:
        f.write(f"name fig6_pw\n{points}tissue {TISSUE} {VORONOI}\n" + common)
    folders = []
    offset = 0.01
    for name, tissue, more in (("fig6_pa", TISSUE, 0.0), ("fig6_pb", VORONOI, offset)):
        with open(os.path.join(scratch, f"{name}.sweep"), "w") as f:
            f.write(f"name {name}\npart_of fig6_pw.sweep\n{points}tissue {tissue}\n" + common)
        folders.append(os.path.join(scratch, name))
        subprocess.run([sys.executable, SWEEP, "plan", os.path.join(scratch, f"{name}.sweep"),
                        folders[-1]], check=True, stdout=subprocess.DEVNULL)
        fake_results(folders[-1], offset=more)
    doc = os.path.join(scratch, "doc", "validation.md")
    result, text = report(["--fig6"] + folders, doc, out)
    expect(result.returncode == 0, f"two complete parts: exit {result.returncode}, "
                                   f"{result.stderr}")
    # seed 3 at 5e-2 fails in both parts: 4 accepted runs against the base's 6
    high = [v for s, v in enumerate(DPHI["P0=5e-2"], 1) if str(s) != FAILED[1]]
    high += [v + offset for v in high]
    base = DPHI["P0=1e-3"] + [v + offset for v in DPHI["P0=1e-3"]]
    lines = [line for line in text.splitlines() if line.startswith("- *P0 = 5e-2 compacts*")]
    pooled = [line for line in lines if "fig6_pw)" in line]
    expect(len(pooled) == 1 and mean_se_text(high) in pooled[0] and
           mean_se_text(base) in pooled[0] and "[4 ok, 2 failed]" in pooled[0],
           f"the whole's 5e-2 line does not pool both tissues' runs "
           f"({mean_se_text(high)} against {mean_se_text(base)}): {pooled}")
    expect(sum("fig6_pa)" in line for line in lines) == 1 and
           sum("fig6_pb)" in line for line in lines) == 1,
           f"the complete parts have no 5e-2 lines of their own: {lines}")
    expect("fig6_pa and fig6_pb plan every point of the whole" in text and
           "Its points pool the runs of several parts" in text and
           "| P0=1e-3 ftol=1e-10 | 6 ok | " in text and
           "![fig6_pw_against.png]" in text,
           "the whole has no table of its pooled points or no figure against P0")
    png = os.path.join(out, "fig6_pw_against.png")

    def drawn_at_high():
        """(mean, accepted runs, all runs) drawn at 5e-2."""
        return [(round(float(r["mean"]), 12), r["runs"], r["all_runs"])
                for r in csv.DictReader(open(os.path.join(out, "fig6_pw_against.csv")))
                if r["quantity"] == "delta_phi_plus" and float(r["P0"]) == 0.05]
    expect(drawn_at_high() == [(round(mean_se(high)[0], 12), "4", "6")],
           f"the whole's figure at 5e-2: not the 4 pooled runs: {drawn_at_high()}")
    archives = [os.path.join(out, f"{name}_summary.csv") for name in ("fig6_pa", "fig6_pb")]
    os.remove(png)
    result, text = report(["--fig6"] + archives, doc, out, scratch)
    expect(result.returncode == 0 and os.path.exists(png) and "![fig6_pw_against.png]" in text,
           f"from archives alone, without a figure: the whole's figure not drawn: "
           f"{result.stderr}")
    alone = [round(mean_se(high[:2])[0], 12), round(mean_se(high[2:])[0], 12)]
    report(["--fig6", archives[0]], doc, out, scratch)
    first = drawn_at_high()
    # the other tissue alone: as many runs, other means
    report(["--fig6", archives[1]], doc, out, scratch)
    second = drawn_at_high()
    result, _ = report(["--fig6"] + archives, doc, out, scratch)
    expect(first == [(alone[0], "2", "6")] and second == [(alone[1], "2", "6")] and
           drawn_at_high()[0][1:] == ("4", "6"),
           f"the whole's figure not drawn again for the parts given: at 5e-2 {first} (one "
           f"tissue), {second} (the other), then {drawn_at_high()} (both); want means {alone}")
    if not os.path.exists(png):
        return
    stamp = os.path.getmtime(png)
    result, _ = report(["--fig6"] + archives, doc, out, scratch)
    expect(result.returncode == 0 and os.path.getmtime(png) == stamp,
           "from archives alone, with a figure: the whole's figure drawn again")


def main():
    check_verdict_rules()
    os.environ["MESOPHYLL_MISSING_EXIT"] = "77"    # sweep_plot.py without matplotlib: skip
    scratch = tempfile.mkdtemp(prefix="sweep_report_")
    try:
        fig6 = plan(scratch, "fig6_t", "fig6.mesophyll", FIG6_POINTS, "steps 3 phi_stop 0.45")
        fig5 = plan(scratch, "fig5_t", "fig5.mesophyll",
                    ["beta=30 eps_b=0.4", "beta=100 eps_b=0.01"],
                    "steps 3 phi_stop 0.45 P0 1e-5 ftol 1e-11")
        fig5_other = plan(scratch, "fig5_p4", "fig5.mesophyll",
                          ["beta=30 eps_b=0.4", "beta=100 eps_b=0.01"],
                          "steps 3 phi_stop 0.45 P0 1e-4 ftol 1e-11")
        fig5_cap = plan(scratch, "fig5_cap", "fig5.mesophyll",
                        ["beta=30 eps_b=0.4", "beta=100 eps_b=0.01"],
                        "steps 5 phi_stop 0.45 P0 1e-5 ftol 1e-11")
        fake_results(fig6)
        fake_results(fig5)
        fake_results(fig5_cap)
        withdraw(os.path.join(fig5_cap, "runs", sorted(os.listdir(os.path.join(fig5_cap,
                                                                                "runs")))[0]))
        fake_results(fig5_other, unconverged={("beta=30 eps_b=0.4", "1")})
        doc = os.path.join(scratch, "doc", "validation.md")
        os.makedirs(os.path.dirname(doc))
        head = "# Validation\n\nText before the section.\n"
        tail = "<!-- published: tools/validate.py --published -->\nkept\n<!-- /published -->\n"
        with open(doc, "w") as f:
            f.write(head + "\n" + tail)
        out = os.path.join(scratch, "out")
        command = [sys.executable, REPORT, "--fig6", fig6, "--fig5", fig5, "--out", out,
                   "--doc", doc]
        for attempt in (1, 2):
            result = subprocess.run(command, capture_output=True, text=True)
            if result.returncode == 77:
                print(f"check_sweep_report: skipped, {result.stderr.strip()}")
                return 77
            expect(result.returncode == 0, f"report {attempt}: exit code {result.returncode}: "
                                           f"{result.stdout}{result.stderr}")
        text = from_fig5 = open(doc).read()
        expect(text.startswith(head), "the text before the section changed")
        expect(text.find("<!-- sweeps") < text.find("<!-- published"),
               "the section does not come before the published one")
        expect(text.count("<!-- sweeps: tools/sweep_report.py -->") == 1 and
               text.count("<!-- /sweeps -->") == 1, "not exactly one section after two reports")
        expect(tail in text, "the published section is not kept")
        expect("<!-- /sweeps -->\n\n" + tail in text,
               "the rewritten section is not followed by one blank line")
        check_claim(text, "P0 = 5e-2 compacts", "P0=5e-2", "P0=1e-3", "**holds**",
                    "[2 ok, 1 failed]")
        check_claim(text, "low eps_b compacts", "beta=100 eps_b=0.01", "P0=1e-5",
                    "the opposite is resolved")
        check_claim(text, "low beta compacts", "beta=30 eps_b=0.4", "P0=1e-5",
                    "cannot be told at this resolution")
        unchanged = line_of(text, "P0 up to 1e-3 hardly matters")
        expect("no difference resolved" in unchanged and "**holds**" not in unchanged,
               f"P0 up to 1e-3: not 'no difference resolved': {unchanged}")
        expect("in 2 comparisons" in unchanged and "6 without spread" in unchanged and all(
                   f"delta_phi_plus: {mean_se_text(DPHI[p])} at P0 = {v} against" in text
                   for p, v in (("P0=1e-5", "1e-05"), ("P0=1e-7", "1e-07"))),
               f"P0 up to 1e-3: not each lower pressure of the sweep compared: {unchanged}")
        expect("fig5_t's base point" in text and "fig6_t's P0 = 1e-05 point" in text,
               "the Fig 5 sweep did not borrow the Fig 6 sweep's P0 = 1e-5 runs")
        expect("both cap growth at 3 steps" in text, "the borrowing does not name the step cap")
        expect("**fig6_t** (fig6): seeds 1 2 3 x tissues tissue_N16.data per point; runs stop "
               "below phi_patch 0.45 or after 3 growth steps;" in text,
               "the Fig 6 sweep's paragraph does not give its stopping rule")
        for name in ("fig6_t_against.png", "fig6_t_curves.png", "fig5_t_heatmaps.png",
                     "fig5_t_summary.csv", "fig6_t_points.csv"):
            expect(os.path.exists(os.path.join(out, name)), f"{name} was not written")
        # the failed run is in the summary as failed, and not in the figure's numbers
        against = open(os.path.join(out, "fig6_t_against.csv")).read()
        m, _ = mean_se(DPHI["P0=5e-2"][:2])
        expect(re.search(rf"delta_phi_plus,0\.05,{m:.3f}", against) is not None,
               f"fig6_t_against.csv: the mean delta_phi_plus at 5e-2 is not {m:.3f}: {against}")
        # a sweep at a pressure the Fig 6 sweep lacks borrows nothing
        result = subprocess.run([sys.executable, REPORT, "--fig6", fig6, "--fig5", fig5_other,
                                 "--out", out, "--doc", doc], capture_output=True, text=True)
        text = open(doc).read()
        expect(result.returncode == 0 and "has no P0 = 0.0001" in text,
               "the P0 = 1e-4 sweep: no message that the Fig 6 sweep lacks its pressure")
        expect("not run (fig5_p4 has no point beta = 100, eps_b = 0.4)" in text,
               "the P0 = 1e-4 sweep: its low-beta line does not say the base is missing")
        # a sweep capped at 5 growth steps borrows nothing from runs capped at 3 that ended at
        # the cap (phi_patch 0.5, above phi_stop): they are not the runs it would have made
        result = subprocess.run([sys.executable, REPORT, "--fig6", fig6, "--fig5", fig5_cap,
                                 "--out", out, "--doc", doc], capture_output=True, text=True)
        text = from_fig5_cap = open(doc).read()
        expect(result.returncode == 0 and "growth-step cap of 3 against 5 here" in text and
               "none borrowed" in text, "the sweep capped at 5 steps borrowed runs capped at 3")
        expect("runs stop below phi_patch 0.45 or after 5 growth steps;" in text,
               "the sweep capped at 5 steps does not say so")
        # its withdrawn run: unfinished, and named with its reason
        statuses = [r["status"] for r in csv.DictReader(open(os.path.join(fig5_cap,
                                                                          "summary.csv")))]
        expect(statuses.count("unfinished") == 1 and
               "Withdrawn: run 1 of fig5_cap (a made-up reason)" in text and
               "0.00 h of it in withdrawn runs" in text,
               f"the withdrawn run: statuses {statuses}, or no 'Withdrawn' line")
        # a run stopped by the iteration limit is unconverged (not failed): tools/sweep.py
        # summary must read fix dpoly/check's words
        statuses = [r["status"] for r in csv.DictReader(open(os.path.join(fig5_other,
                                                                          "summary.csv")))]
        expect(statuses.count("unconverged") == 1 and statuses.count("failed") == 0,
               f"fig5_p4: one run at the iteration limit gives statuses {statuses}, not one "
               f"unconverged")
        # an option that changes the section is part of the command the section gives
        result, text = report(["--fig6", fig6, "--fig5", fig5_other, "--accept", "unconverged"],
                              doc, out)
        expect(result.returncode == 0 and
               f"Made by `tools/sweep_report.py --fig5 {fig5_other} --fig6 {fig6} --accept "
               f"unconverged`" in text, "--accept unconverged is missing from the command given")
        check_two_of_a_figure(scratch, fig6, fig5, out)
        check_archives(scratch, fig6, {"fig5_t": from_fig5, "fig5_cap": from_fig5_cap}, out)
        check_parts(scratch, out)
        check_pooled_parts(scratch, out)
        # a Fig 5 sweep that leaves P0 to its parameter set (1e-7) and lacks its base borrows
        # fig6_t's 1e-7 runs: the borrowing reads the set's P0 (a KeyError on P0 before)
        result, text = report_without_base(scratch, fig6, doc, out, "fig5_set_p0",
                                           "steps 3 phi_stop 0.45 ftol 1e-11")
        expect(result.returncode == 0 and "fig5_set_p0's base point {'beta': 100, 'eps_b': 0.4} "
               "is fig6_t's P0 = 1e-07 point" in text,
               f"a sweep with P0 from its set: exit {result.returncode}, "
               f"{result.stderr.strip()[-300:]}")
        # bad input: no folder, a folder without runs, a file that is no archive, a missing one
        not_archive = os.path.join(scratch, "fig6_t.sweep")
        for args in ([], ["--fig6", scratch], ["--fig6", not_archive],
                     ["--fig6", os.path.join(scratch, "none_summary.csv")]):
            result = subprocess.run([sys.executable, REPORT] + args, capture_output=True,
                                    text=True)
            expect(result.returncode != 0 and "error" in result.stderr,
                   f"sweep_report {' '.join(args)}: exit code {result.returncode}, "
                   f"{result.stderr.strip()}")
    finally:
        if os.environ.get("SWEEP_KEEP"):
            print(f"kept {scratch}")
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    for p in problems:
        print("FAILED:", p)
    print(f"check_sweep_report: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
