#!/usr/bin/env python3
"""Stress the growth protocol where methods fail and write what happened to doc/stability.md.

    bench/stability.py [--lmp build/lmp] [--out doc/stability.md] [--csv bench/results/stability.csv]

Each case runs examples/mesophyll/in.mesophyll (16 cells) with one setting pushed to or past its
limit, or a small input of its own (bench/stability/), and is classified from its log: converged
(every minimum passed fix dpoly/check), warned (fix dpoly/check reported failures and the run went
on; the first is quoted), stopped (LAMMPS stopped with an error; quoted), or silent failure (NaN
in the thermo output, or a non-zero exit without an error message: this must never happen).
Standard library only.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HERE = os.path.join(ROOT, "bench")

# name, what it stresses, input ("mesophyll" or a file under bench/stability), variables
CASES = [
    ("reference", "the default set, 5 steps", "mesophyll", {"steps": 5}),
    ("delta_a 2", "growth increment 4x the default", "mesophyll", {"steps": 5, "delta_a": 2}),
    ("delta_a 5", "growth increment 10x the default", "mesophyll", {"steps": 3, "delta_a": 5}),
    ("P0 0.1", "pressure 100x the default", "mesophyll", {"steps": 5, "P0": 0.1}),
    ("eps_b 0.01", "very soft bending", "mesophyll", {"steps": 10, "eps_b": 0.01}),
    ("beta 20", "easy stochastic breaking", "mesophyll", {"steps": 10, "beta": 20}),
    ("ftol 1e-14", "force tolerance below round-off", "mesophyll", {"steps": 3, "ftol": 1e-14}),
    ("ftol 1e-3", "force tolerance far too loose for P = P0", "mesophyll",
     {"steps": 3, "ftol": 1e-3}),
    ("P0 2 (buckling)", "tissue compressed until cells buckle", "mesophyll",
     {"steps": 2, "P0": 2.0}),
    ("pinched ring", "a ring whose preferred angles fold it through itself, no self-repulsion",
     "in.pinch", {}),
    ("unreachable P0", "fix box/relax asked for a tension (P0 = -50) the tissue cannot hold",
     "mesophyll", {"steps": 1, "P0": -50}),
]


def classify(log, returncode):
    nan = re.search(r"^\s*\d+\s.*\b(nan|inf)\b", log, re.MULTILINE | re.IGNORECASE)
    error = re.search(r"^ERROR.*$", log, re.MULTILINE)
    failed = re.findall(r"fix dpoly/check: (minimum \d+ at step \d+):.*?; FAILED; (.*)$", log,
                        re.MULTILINE)
    minima = len(re.findall(r"^fix dpoly/check: minimum", log, re.MULTILINE))
    if nan:
        return "SILENT FAILURE", f"NaN or inf in thermo output: {nan.group(0).strip()[:120]}"
    if error:
        return "stopped", error.group(0).strip()
    if returncode != 0:
        return "SILENT FAILURE", f"exit code {returncode} without an error message"
    if failed:
        where, what = failed[0]
        return "warned", f"{len(failed)} of {minima} minima failed; first: {where}: {what}"
    return "converged", f"all {minima} minima passed fix dpoly/check"


def run_case(lmp, case, workroot):
    name, _, source, variables = case
    work = os.path.join(workroot, re.sub(r"\W+", "_", name))
    shutil.copytree(os.path.join(ROOT, "examples", "mesophyll"), work, symlinks=False)
    if source == "mesophyll":
        command = [lmp, "-in", "in.mesophyll", "-var", "N", "16"]
    else:
        shutil.copy(os.path.join(HERE, "stability", source), work)
        shutil.copy(os.path.join(ROOT, "examples", "tissue", "ring32.mol"), work)
        command = [lmp, "-in", source]
    for key, value in variables.items():
        command += ["-var", key, str(value)]
    command += ["-log", "log.lammps", "-screen", "none"]
    start = time.perf_counter()
    try:
        result = subprocess.run(command, cwd=work, timeout=900, capture_output=True, text=True)
        returncode = result.returncode
    except subprocess.TimeoutExpired:
        returncode = "timeout"
    wall = time.perf_counter() - start
    log_path = os.path.join(work, "log.lammps")
    log = open(log_path).read() if os.path.exists(log_path) else ""
    if returncode == "timeout":
        return "SILENT FAILURE", "did not finish within 900 s", wall
    outcome, detail = classify(log, returncode)
    return outcome, detail, wall


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", default=os.path.join(ROOT, "build", "lmp"))
    p.add_argument("--out", default=os.path.join(ROOT, "doc", "stability.md"))
    p.add_argument("--csv", default=os.path.join(HERE, "results", "stability.csv"))
    args = p.parse_args()
    lmp = os.path.abspath(args.lmp)

    rows = []
    with tempfile.TemporaryDirectory() as workroot:
        for case in CASES:
            outcome, detail, wall = run_case(lmp, case, workroot)
            rows.append({"case": case[0], "stresses": case[1], "outcome": outcome,
                         "detail": detail, "wall_s": f"{wall:.1f}"})
            print(f"{case[0]:18s} {outcome:15s} {wall:7.1f} s  {detail[:110]}", flush=True)

    os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    lines = ["# Stability where methods fail", "",
             "Regenerated by `bench/stability.py`: each case runs the 16-cell development "
             "(`examples/mesophyll/in.mesophyll`, min_style fire/nph, fix dpoly/check with "
             "action warn) with one setting pushed to or past its limit, or a small input of "
             "`bench/stability/`. Outcomes: *converged* (every minimum passed the check), "
             "*warned* (the check reported failures and the run went on), *stopped* (an error "
             "that says what failed), *SILENT FAILURE* (NaN carried on, or an exit without a "
             "message: never acceptable).", "",
             "| case | stresses | outcome | what the log says | wall s |",
             "| --- | --- | --- | --- | --- |"]
    for r in rows:
        detail = r["detail"].replace("|", "/")
        lines.append(f"| {r['case']} | {r['stresses']} | {r['outcome']} | {detail} | "
                     f"{r['wall_s']} |")
    silent = [r["case"] for r in rows if r["outcome"] == "SILENT FAILURE"]
    lines += ["", "Silent failures: " + (", ".join(silent) if silent else "none") + "."]
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {args.out} and {args.csv}")
    return 1 if silent else 0


if __name__ == "__main__":
    raise SystemExit(main())
