#!/usr/bin/env python3
"""The sweep driver on 2 partitions: complete, resumed after a kill, failures reported.

    check_sweep.py --lmp BUILD/lmp [--mpirun CMD] [--numproc-flag FLAG] [--preflags FLAGS]
                   [--postflags FLAGS]

Plans examples/sweep/tiny.sweep (16 cells, 2 growth steps, beta 30 and 300 x seeds 11 and 12)
with tools/sweep.py and runs examples/sweep/in.sweep as `mpirun -np 2 lmp -partition 2x1`:

  straight     the whole sweep at once: every run finished; started again, it skips them all;
  single       run 2 alone (lmp -in in.sweep -var run 2, one process, as a job-array task):
               only it finishes, with the straight sweep's growth table;
  interrupted  the same plan, sent SIGKILL as soon as one run has written its first restart file
               and is not finished (and another run is), then the same command again: the runs
               finished before the kill are skipped (their growth tables untouched, one start
               each), the killed one
               resumes from its restart file, and every growth table equals the straight
               sweep's (tests/resume.py's tolerances);
  failures     a sweep of two runs on 2 partitions: one from a tissue with a ring folded through
               itself (fix dpoly/check flags its minima), one from a data file LAMMPS cannot
               read (the error stops the job); run again, the sweep completes and the summary
               says failed and error;
  error note   a run whose log ends in an ERROR with quotes of both kinds and a $, the other
               runs finished: in.sweep on one partition marks it finished with the error,
               prints its note (no quote ends or unbalances it) and starts no run.

plan must refuse bad sweep files with a message naming the bad value. The summary of the
interrupted sweep must say what the growth tables say: steps, delta_phi_plus,
z at the step nearest phi_patch = 0.5, delta_A early and late against the reference file
(recomputed here), and status ok where the log has no failed check. SWEEP_KEEP=DIR keeps the
sweeps in DIR. Standard library only (tools/sweep_plot.py's part is skipped without
python3-matplotlib).
"""
import argparse
import csv
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from regression import add_launcher_arguments, launch  # noqa: E402
from resume import compare, kill_processes_in  # noqa: E402

SWEEP = os.path.join(ROOT, "tools", "sweep.py")
IN_SWEEP = os.path.join(ROOT, "examples", "sweep", "in.sweep")
TINY = os.path.join(ROOT, "examples", "sweep", "tiny.sweep")
REFERENCE = os.path.join(ROOT, "examples", "sweep", "reference_paper_text.txt")
problems = []


def expect(condition, message):
    if not condition:
        problems.append(message)
    return condition


def plan(sweep_file, folder):
    subprocess.run([sys.executable, SWEEP, "plan", sweep_file, folder], check=True)


def sweep_command(args):
    return launch(args, ["-partition", "2x1", "-in", IN_SWEEP])


def run_sweep(args, folder, expect_ok=True):
    command, env = sweep_command(args)
    result = subprocess.run(command, cwd=folder, env=env, timeout=args.timeout,
                            stdout=subprocess.DEVNULL)
    if expect_ok and result.returncode != 0:
        sys.exit(f"check_sweep: {' '.join(command)} in {folder} failed ({result.returncode})")
    return result.returncode


def runs_of(folder):
    return sorted(os.listdir(os.path.join(folder, "runs")))


def table_rows(path):
    with open(path) as f:
        names = f.readline().lstrip("#").split()
        return [dict(zip(names, map(float, line.split()))) for line in f if line.strip()]


def kill_when_restarted(args, folder):
    """Start the sweep, SIGKILL it once a run is finished and another has restart.N16.1 but no
    marker; return the runs finished before the kill and the killed ones."""
    command, env = sweep_command(args)
    proc = subprocess.Popen(command, cwd=folder, env=env, start_new_session=True,
                            stdout=subprocess.DEVNULL)
    deadline, caught = time.time() + args.timeout, None
    while proc.poll() is None and time.time() < deadline and caught is None:
        done = [r for r in runs_of(folder)
                if os.path.exists(os.path.join(folder, "runs", r, "finished"))]
        for run in runs_of(folder):
            path = os.path.join(folder, "runs", run)
            # caught inside its last growth step (restart.N16.2 not yet written), not in the
            # instant between its last restart file and its marker: the kill must land first
            if done and os.path.exists(os.path.join(path, "restart.N16.1")) and \
                    not os.path.exists(os.path.join(path, "restart.N16.2")) and \
                    not os.path.exists(os.path.join(path, "finished")):
                caught = run
                break
        time.sleep(0.005)
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    for run in runs_of(folder):
        kill_processes_in(os.path.join(folder, "runs", run))
    kill_processes_in(folder)
    if caught is None or proc.returncode != -signal.SIGKILL:
        sys.exit(f"check_sweep: the kill came too late (exit code {proc.returncode}): no run "
                 f"was caught between its first restart file and its end")
    finished = [r for r in runs_of(folder)
                if os.path.exists(os.path.join(folder, "runs", r, "finished"))]
    restarted = [r for r in runs_of(folder) if r not in finished and
                 os.path.exists(os.path.join(folder, "runs", r, "restart.N16.1"))]
    if not restarted:
        sys.exit("check_sweep: the kill came too late: the run caught between its first restart "
                 "file and its end had finished")
    return finished, restarted


def nearest(rows, key, target):
    return sorted(rows, key=lambda row: abs(row[key] - target))[0]


def reference_delta_A(rows, stage):
    """delta_A of one growth table, recomputed: each reference point of the stage against the
    row whose 0.975 - phi_patch is nearest its porosity."""
    diffs = []
    for line in open(REFERENCE):
        words = line.split("#")[0].split()
        if words and words[2] == stage:
            porosity, calA = float(words[0]), float(words[1])
            row = sorted(rows, key=lambda r: abs(0.975 - r["phi_patch"] - porosity))[0]
            diffs.append(row["calA"] - calA)
    return math.sqrt(sum(d * d for d in diffs) / len(diffs))


def check_summary(folder):
    subprocess.run([sys.executable, SWEEP, "summary", folder], check=True,
                   stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(folder, "summary.csv"))))
    expect(len(rows) == 4, f"summary.csv has {len(rows)} runs, not 4")
    for row in rows:
        run = os.path.join(folder, "runs", row["run"])
        table = table_rows(os.path.join(run, "growth.N16.txt"))
        log = open(os.path.join(run, "log.lammps")).read()
        failed = log.count("; FAILED;")
        name = f"run {row['run']}"
        # the run ran with its own values, not those a previous run of its partition left
        used = [line.split() for line in log.splitlines()
                if line.split()[:1] == ["fix"] and line.split()[3:4] == ["mesophyll/break"]
                and "$" not in line]
        expect(used and used[-1][4] == row["seed"] and used[-1][6] == row["beta"],
               f"{name}: planned seed {row['seed']} beta {row['beta']}, its log ran "
               f"{' '.join(used[-1]) if used else 'no fix mesophyll/break'}")
        expect(row["status"] == ("ok" if failed == 0 else row["status"]) and
               row["status"] != "unfinished", f"{name}: status {row['status']} with {failed} "
               f"failed checks in its log")
        expect(int(row["failed_checks"]) == failed,
               f"{name}: failed_checks {row['failed_checks']}, the log has {failed}")
        expect(int(row["steps"]) == len(table) == 2, f"{name}: steps {row['steps']}, the growth "
               f"table has {len(table)} rows (planned 2)")
        half = nearest(table, "phi_patch", 0.5)
        for key, value in (("delta_phi_plus", table[-1]["dphi_plus"]), ("z_half", half["z"]),
                           ("phi_half", half["phi_patch"]),
                           ("delta_A_early", reference_delta_A(table, "early")),
                           ("delta_A_late", reference_delta_A(table, "late"))):
            expect(math.isclose(float(row[key]), value, rel_tol=1e-5, abs_tol=1e-9),
                   f"{name}: {key} {row[key]} in the summary, {value:.6g} from its growth table")
        # two growth steps leave the tissue near confluence (porosity below 0.2): the late
        # point (porosity 0.465) was never reached, and the summary must say how far it was
        closest = min(abs(0.975 - r["phi_patch"] - 0.465) for r in table)
        expect(closest > 0.25 and math.isclose(float(row["porosity_gap_late"]), closest,
                                               rel_tol=1e-5),
               f"{name}: porosity_gap_late {row['porosity_gap_late']}, the growth table's "
               f"nearest porosity is {closest:.6g} from the late point's 0.465")
    points = list(csv.DictReader(open(os.path.join(folder, "points.csv"))))
    expect([p["point"] for p in points] == ["beta=30", "beta=300"],
           f"points.csv has points {[p['point'] for p in points]}")
    for p in points:
        group = [float(r["delta_phi_plus"]) for r in rows if r["point"] == p["point"]
                 and r["status"] == "ok"]
        if len(group) == 2:
            mean = sum(group) / 2
            expect(math.isclose(float(p["delta_phi_plus_mean"]), mean, rel_tol=1e-5,
                                abs_tol=1e-9), f"{p['point']}: mean delta_phi_plus "
                   f"{p['delta_phi_plus_mean']}, its runs give {mean:.6g}")


def check_plots(folder):
    """tools/sweep_plot.py on the sweep: each figure's PNG, and its CSV's means those of
    points.csv (the against figure) and of the growth tables (the curves)."""
    plot = os.path.join(ROOT, "tools", "sweep_plot.py")
    env = dict(os.environ, MESOPHYLL_MISSING_EXIT="77")
    for kind, extra in (("heatmaps", ["--x", "beta", "--y", "seed", "--mark", "30,11"]),
                        ("curves", []), ("against", ["--x", "beta"])):
        result = subprocess.run([sys.executable, plot, kind, folder] + extra, env=env)
        if result.returncode == 77:
            print(f"sweep_plot {kind}: skipped, a Debian package is missing")
            return
        expect(result.returncode == 0 and os.path.getsize(os.path.join(folder, kind + ".png")),
               f"sweep_plot {kind}: exit code {result.returncode} or no PNG")
    points = {p["point"]: p for p in csv.DictReader(open(os.path.join(folder, "points.csv")))}
    for row in csv.DictReader(open(os.path.join(folder, "against.csv"))):
        if row["quantity"] == "delta_phi_plus":
            want = points[f"beta={float(row['beta']):g}"]["delta_phi_plus_mean"]
            expect(math.isclose(float(row["mean"]), float(want), rel_tol=1e-5, abs_tol=1e-9),
                   f"against.csv: delta_phi_plus {row['mean']} at beta {row['beta']}, points.csv "
                   f"{want}")
    # the curves: the first porosity bin of beta=30 averages its runs' first growth steps
    rows = [r for r in csv.DictReader(open(os.path.join(folder, "summary.csv")))
            if r["point"] == "beta=30" and r["status"] == "ok"]
    samples = []    # each run's mean calA in the bin
    for r in rows:
        steps = [step["calA"] for step in table_rows(os.path.join(folder, "runs", r["run"],
                                                                  "growth.N16.txt"))
                 if int((0.975 - step["phi_patch"]) / 0.025) == 1]
        if steps:
            samples.append(sum(steps) / len(steps))
    curve = [c for c in csv.DictReader(open(os.path.join(folder, "curves.csv")))
             if c["point"] == "beta=30" and abs(float(c["porosity"]) - 0.0375) < 1e-9]
    expect(samples and curve and math.isclose(float(curve[0]["calA_mean"]),
                                              sum(samples) / len(samples), rel_tol=1e-9),
           f"curves.csv: beta=30 at porosity 0.0375: {curve}, growth tables {samples}")


def check_bad_plans(scratch):
    """plan refuses a bad sweep file, naming what is wrong."""
    tissue = os.path.join(ROOT, "examples", "tissue", "tissue_N16.data")
    cases = [("colour red", "unknown keyword 'colour'"),
             ("vary bogus 1 2", "'bogus' is neither a variable"),
             ("set nosuchset", "the set 'nosuchset' is not in"),
             ("seeds 0", "a seed must be a positive integer, not '0'"),
             ("vary seed 1 2", "'seed' is set by the sweep itself"),
             ("growth lots", "takes a number and an integer, not 'lots'"),
             ("tissue missing.data", "missing.data does not exist"),
             ("vary set default nosuchset", "the set 'nosuchset' is not in"),
             ("fixed steps 1e3", "steps must be a whole number above 0, not '1e3'")]
    for k, (line, message) in enumerate(cases):
        path = os.path.join(scratch, f"bad{k}.sweep")
        with open(path, "w") as f:
            f.write(f"tissue {tissue}\nseeds 1\n{line}\n")
        result = subprocess.run([sys.executable, SWEEP, "plan", path,
                                 os.path.join(scratch, f"bad{k}")], capture_output=True, text=True)
        expect(result.returncode != 0 and message in result.stderr and
               "Traceback" not in result.stderr,
               f"plan of a sweep file with '{line}': exit code {result.returncode}, "
               f"'{result.stderr.strip()}' (expected '{message}')")


def tangled_tissue(source, target):
    """source with cell 1's vertices 9..24 in reverse order along its ring: the ring runs out to
    vertex 24's place and back, its segments 8-9 and 24-25 cross."""
    lines = open(source).read().splitlines()
    start = lines.index(next(l for l in lines if l.startswith("Atoms"))) + 2
    end = start
    while end < len(lines) and lines[end].strip():
        end += 1
    atoms = {int(l.split()[0]): l.split() for l in lines[start:end]}
    ring = sorted(i for i, w in atoms.items() if w[1] == "1")
    chunk = ring[8:24]
    places = {i: atoms[i][3:9] for i in chunk}    # x y z and image flags
    for i, j in zip(chunk, reversed(chunk)):
        atoms[i][3:9] = places[j]
    lines[start:end] = [" ".join(atoms[i]) for i in sorted(atoms)]
    with open(target, "w") as f:
        f.write("\n".join(lines) + "\n")


def check_error_note(args, scratch):
    """A run whose last attempt stopped with an error the sweep must mark and skip, whatever the
    message holds: in.sweep includes the state file tools/sweep.py state writes and prints its
    note, and a quote of either kind or a $ from the message must not end or unbalance it
    (fire/nph's 'cannot settle' error names "the largest force's cell": that stopped a whole
    sweep). The sweep runs through in.sweep itself, on one partition, with every other run
    marked finished, so that nothing but the states is read."""
    folder = os.path.join(scratch, "error_note")
    plan(TINY, folder)
    first, *others = runs_of(folder)
    for other in others:
        with open(os.path.join(folder, "runs", other, "finished"), "w") as f:
            f.write("finished\n")
    run = os.path.join(folder, "runs", first)
    message = ("ERROR: min_style fire/nph: the largest force's cell; \"quoted\" ${x} $y "
               "'single' \"\"\"triple # not a comment (src/x.cpp:1)")
    with open(os.path.join(run, "log.lammps"), "w") as f:
        f.write(f"sweep: attempt 1\n{message}\n")
    result = subprocess.run([args.lmp, "-log", "none", "-in", IN_SWEEP], cwd=folder,
                            capture_output=True, text=True, timeout=args.timeout)
    note = re.search(rf"^sweep: run {first} (.*)$", result.stdout, re.M)
    expect(result.returncode == 0 and note is not None,
           f"in.sweep after an error with quotes: LAMMPS exit {result.returncode}, "
           f"{(result.stdout + result.stderr).strip().splitlines()[-2:]}")
    if note:
        expect("marked as error, skipped" in note.group(1) and
               "the largest force`s cell" in note.group(1) and "not a comment" in note.group(1),
               f"in.sweep after an error with quotes: note '{note.group(1)}'")
    expect(open(os.path.join(run, "finished")).read().startswith("error ERROR: min_style"),
           "the run stopped with an error is not marked finished with it")
    expect("sweep: attempt of run" not in result.stdout,
           "in.sweep started a run although every run was finished or marked as error")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", required=True)
    p.add_argument("--timeout", type=float, default=240, help="seconds per sweep command")
    add_launcher_arguments(p)
    args = p.parse_args()
    args.lmp, args.np = os.path.abspath(args.lmp), 2
    start = time.time()
    with tempfile.TemporaryDirectory() as scratch:
        if os.environ.get("SWEEP_KEEP"):    # a folder to keep the sweeps in, to look at
            scratch = os.environ["SWEEP_KEEP"]
        check_bad_plans(scratch)
        check_error_note(args, scratch)
        straight, interrupted = (os.path.join(scratch, n) for n in ("straight", "interrupted"))
        for folder in (straight, interrupted):
            plan(TINY, folder)
        run_sweep(args, straight)
        expect(all(os.path.exists(os.path.join(straight, "runs", r, "finished"))
                   for r in runs_of(straight)), "straight: not every run finished")
        # the finished sweep started again does nothing: every run is skipped
        tables = {r: os.stat(os.path.join(straight, "runs", r, "growth.N16.txt")).st_mtime_ns
                  for r in runs_of(straight)}
        run_sweep(args, straight)
        for r in runs_of(straight):
            again = os.stat(os.path.join(straight, "runs", r, "growth.N16.txt")).st_mtime_ns
            starts = open(os.path.join(straight, "runs", r, "times.txt")).read().count("start")
            expect(again == tables[r] and starts == 1,
                   f"straight run {r}: run again when the finished sweep was started again")

        # one run alone, as a job-array task runs it: lmp -in in.sweep -var run ID, no uloop
        single = os.path.join(scratch, "single")
        plan(TINY, single)
        result = subprocess.run([args.lmp, "-log", "none", "-in", IN_SWEEP, "-var", "run", "2"],
                                cwd=single, stdout=subprocess.DEVNULL, timeout=args.timeout)
        done = [r for r in runs_of(single)
                if os.path.exists(os.path.join(single, "runs", r, "finished"))]
        expect(result.returncode == 0 and done == ["2"],
               f"-var run 2: exit code {result.returncode}, finished runs {done}")
        problems.extend(compare(os.path.join(straight, "runs", "2"),
                                os.path.join(single, "runs", "2"), 16, "run 2 alone")[0])

        before, killed = kill_when_restarted(args, interrupted)
        print(f"killed the sweep with runs {before} finished and {killed} between their first "
              f"restart file and their end")
        untouched = {r: os.stat(os.path.join(interrupted, "runs", r, "growth.N16.txt")).st_mtime_ns
                     for r in before}
        run_sweep(args, interrupted)
        for r in runs_of(interrupted):
            run = os.path.join(interrupted, "runs", r)
            starts = sum(line.startswith("start") for line in open(os.path.join(run, "times.txt")))
            log = open(os.path.join(run, "log.lammps")).read()
            if r in before:
                expect(os.stat(os.path.join(run, "growth.N16.txt")).st_mtime_ns == untouched[r]
                       and starts == 1, f"run {r}, finished before the kill, was run again")
                expect("finished before: skipped" in log, f"run {r}: no skip in its log")
            elif r in killed:
                expect("resuming after growth step 1" in log and starts == 2,
                       f"run {r}: killed after its first restart file, but not resumed from it")
            else:    # killed before it had a restart file, or not begun
                expect("resuming after growth step" not in log and starts <= 2,
                       f"run {r}: killed without a restart file, but not started afresh")
            found, rows, snaps, worst = compare(os.path.join(straight, "runs", r), run, 16,
                                                f"run {r}")
            problems.extend(found)
            expect(os.path.exists(os.path.join(run, "finished")), f"run {r}: not finished")
        check_summary(interrupted)
        check_plots(interrupted)

        # failures: a tangled ring (failed) and an unreadable data file (error)
        failures = os.path.join(scratch, "failures")
        os.makedirs(failures)
        tangled_tissue(os.path.join(ROOT, "examples", "tissue", "tissue_N16.data"),
                       os.path.join(failures, "tangled.data"))
        with open(os.path.join(failures, "broken.data"), "w") as f:
            f.write("a data file LAMMPS cannot read: 16 atoms announced, 1 given\n\n16 atoms\n"
                    "1 atom types\n\n0 1 xlo xhi\n0 1 ylo yhi\n-0.5 0.5 zlo zhi\n\n"
                    "Atoms # molecular\n\n1 1 1 0.5 0.5 0\n")
        sweep_file = os.path.join(failures, "failures.sweep")
        with open(sweep_file, "w") as f:
            f.write(f"protocol {ROOT}/examples/mesophyll/in.mesophyll\nseeds 11\n"
                    "tissue tangled.data broken.data\nfixed steps 1 refine none\n")
        folder = os.path.join(failures, "sweep")
        plan(sweep_file, folder)
        first = run_sweep(args, folder, expect_ok=False)
        expect(first != 0, "the sweep with an unreadable data file ended with exit code 0")
        # a summary before the sweep is started again already reads the error from the log
        subprocess.run([sys.executable, SWEEP, "summary", folder], check=True,
                       stdout=subprocess.DEVNULL)
        early = [r for r in csv.DictReader(open(os.path.join(folder, "summary.csv")))
                 if r["tissue"].endswith("broken.data")]
        expect(early and early[0]["status"] == "error" and "ERROR" in early[0]["first_failure"],
               f"unreadable data file before the restart: {early}")
        run_sweep(args, folder)
        subprocess.run([sys.executable, SWEEP, "summary", folder], check=True)
        status = {r["tissue"].rsplit("/", 1)[-1]: r for r in
                  csv.DictReader(open(os.path.join(folder, "summary.csv")))}
        expect(status["tangled.data"]["status"] == "failed" and
               "cross themselves" in status["tangled.data"]["first_failure"],
               f"tangled ring: status {status['tangled.data']['status']}, first failure "
               f"'{status['tangled.data']['first_failure']}'")
        expect(status["broken.data"]["status"] == "error" and
               "ERROR" in status["broken.data"]["first_failure"],
               f"unreadable data file: status {status['broken.data']['status']}")
    for problem in problems:
        print("FAILED:", problem)
    print(f"check_sweep: {'FAILED' if problems else 'passed'} in {time.time() - start:.1f} s")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
