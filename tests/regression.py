#!/usr/bin/env python3
"""Rerun an example and compare its thermo output with the example's reference log.

    regression.py --lmp BUILD/lmp --example examples/NAME --input in.X --np N [--mpirun CMD]
                  [--numproc-flag FLAG] [--preflags FLAGS] [--postflags FLAGS]
                  [--rtol R] [--atol A] [--tolerance COLUMN=RTOL,ATOL ...] [--var NAME VALUE ...]
                  [--update] [--expect-difference]

The reference is examples/NAME/log.<date>.<X>.g++.<N> (the newest, if several). Every thermo
row of every run must match column by column within |new - ref| <= atol + rtol*|ref|, with the
same columns and rows; --tolerance sets a column's own pair. A minimum that fix dpoly/check
fails where the reference's passed is a difference too (the check may learn to see more than
when the reference was written). --update runs the example and writes
a new reference log instead. --var passes a variable to LAMMPS; with --expect-difference the
check passes only if the run differs from the reference (to show that a moved trajectory is
caught). With N > 1 the command is CMD FLAG N PREFLAGS lmp POSTFLAGS ..., the order of CMake's
MPIEXEC_* variables (ctest passes what CMake found). The defaults (-np, --oversubscribe and Open
MPI's OMPI_ALLOW_RUN_AS_ROOT* variables) suit Open MPI; with --preflags given, the environment is
left as it is. Standard library only.
"""
import argparse
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time


def thermo_blocks(path):
    """List of (columns, rows) for every thermo table in a LAMMPS log."""
    blocks, columns, rows = [], None, []
    with open(path) as log:
        for line in log:
            words = line.split()
            if columns is None:
                if words and words[0] == "Step":
                    columns, rows = words, []
            elif words and words[0] == "Loop":
                blocks.append((columns, rows))
                columns = None
            elif len(words) == len(columns):
                try:
                    rows.append([float(w) for w in words])
                except ValueError:
                    pass    # a warning line inside the table
    return blocks


FAILED_CHECK = re.compile(r"^fix dpoly/check: minimum (\d+) at step \d+: .*?; FAILED; (.*)$", re.M)


def failed_checks(path):
    """{minimum: problems} of the fix dpoly/check lines of a log that report a failure."""
    with open(path, errors="replace") as log:
        return {int(m.group(1)): m.group(2) for m in FAILED_CHECK.finditer(log.read())}


def compare(reference, new, rtol, atol, per_column=None):
    """Return a list of differences, empty if the logs agree. per_column: {name: (rtol, atol)}."""
    per_column = per_column or {}
    ref_blocks, new_blocks = thermo_blocks(reference), thermo_blocks(new)
    problems = []
    if len(ref_blocks) != len(new_blocks):
        return [f"{len(new_blocks)} thermo tables, reference has {len(ref_blocks)}"]
    for b, ((ref_cols, ref_rows), (new_cols, new_rows)) in enumerate(zip(ref_blocks, new_blocks)):
        if ref_cols != new_cols:
            problems.append(f"table {b}: columns {new_cols}, reference {ref_cols}")
            continue
        if len(ref_rows) != len(new_rows):
            problems.append(f"table {b}: {len(new_rows)} rows, reference has {len(ref_rows)}")
        for ref_row, new_row in zip(ref_rows, new_rows):
            for col, ref, val in zip(ref_cols, ref_row, new_row):
                col_rtol, col_atol = per_column.get(col, (rtol, atol))
                if abs(val - ref) > col_atol + col_rtol * abs(ref):
                    problems.append(f"table {b} step {int(ref_row[0])} {col}: {val!r} vs "
                                    f"reference {ref!r}")
    passed_before = failed_checks(reference)
    for minimum, text in sorted(failed_checks(new).items()):
        if minimum not in passed_before:
            problems.append(f"fix dpoly/check failed minimum {minimum} ({text}), which passed in "
                            "the reference")
    return problems


def reference_log(example, name, np):
    logs = sorted(glob.glob(os.path.join(example, f"log.*.{name}.g++.{np}")), key=os.path.getmtime)
    return logs[-1] if logs else None


def add_launcher_arguments(parser):
    """The rank count and MPI launcher options, shared with resume.py."""
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--mpirun", default="mpirun",
                        help="MPI launcher (CMake: MPIEXEC_EXECUTABLE)")
    parser.add_argument("--numproc-flag", default="-np",
                        help="its rank-count flag (MPIEXEC_NUMPROC_FLAG)")
    parser.add_argument("--preflags", default=None,
                        help="flags before the program (MPIEXEC_PREFLAGS and "
                             "MESOPHYLL_MPIEXEC_FLAGS; default --oversubscribe, with Open MPI's "
                             "run-as-root variables)")
    parser.add_argument("--postflags", default="",
                        help="flags after the program (MPIEXEC_POSTFLAGS)")


def parse_lmp_arguments(doc, add_own=lambda parser: None):
    """The command line of a script that runs lmp: --lmp (made absolute), the launcher options and
    the script's own, which add_own(parser) adds; doc's first line describes the script."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--lmp", required=True)
    add_own(parser)
    add_launcher_arguments(parser)
    args = parser.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    return args


def run_lmp(args, lmp_arguments, cwd, failure):
    """lmp with lmp_arguments in the folder cwd, on args.np ranks; exits with 'failure' if it
    fails."""
    command, env = launch(args, lmp_arguments)
    if subprocess.run(command, cwd=cwd, env=env).returncode != 0:
        sys.exit(failure)


def tissue_commands(data, after_read=""):
    """LAMMPS commands that read a tissue data file with the main example's styles and Table 1
    coefficients (segments, adhesion z bonds, bending 0.4, contacts) and the cells' hub; the
    commands in after_read come right after read_data. Shared by replicate.py and
    published_growth.py."""
    return f"""units lj
dimension 2
atom_style molecular
boundary p p p
bond_style hybrid dpoly/segment mesophyll/adhesion z bonds
angle_style dpoly/bending
fix Vertices all property/atom d_sigma d_l0 d_theta0 d_a0 ghost yes
read_data {data} fix Vertices NULL Vertices
{after_read}bond_coeff 1 dpoly/segment 1.0
bond_coeff 2 mesophyll/adhesion 1.0
angle_coeff * 0.4
pair_style dpoly/contact
pair_coeff * * 1.0
special_bonds lj 1.0 1.0 1.0
comm_modify cutoff 4.0
fix cells all dpoly/cells eps_a 1.0
"""


def launch(args, lmp_arguments):
    """The command line and environment that run lmp with lmp_arguments on args.np ranks."""
    env = dict(os.environ)
    if args.np == 1:
        return [args.lmp] + lmp_arguments, env
    if args.preflags is None:    # run by hand: Open MPI's needs, as root on few cores
        preflags = ["--oversubscribe"]
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    else:
        preflags = shlex.split(args.preflags)
    return (shlex.split(args.mpirun) + [args.numproc_flag, str(args.np)] + preflags + [args.lmp]
            + shlex.split(args.postflags) + lmp_arguments), env


def start_example(args, workdir, log_name, variables, **run_options):
    """Copy the example into workdir and run args.input there with 'variables' (name, value);
    returns the command and its subprocess.run result, whatever the exit code."""
    shutil.copytree(args.example, workdir, dirs_exist_ok=True)
    command = ["-in", args.input, "-log", log_name, "-screen", "none"]
    for name, value in variables:
        command += ["-var", name, value]
    command, env = launch(args, command)
    return command, subprocess.run(command, cwd=workdir, env=env, **run_options)


def run_example(args, workdir, log_name):
    command, result = start_example(args, workdir, log_name, args.var)
    if result.returncode != 0:
        sys.exit(f"regression: {' '.join(command)} failed with exit code {result.returncode}")
    return os.path.join(workdir, log_name)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", required=True)
    p.add_argument("--example", required=True)
    p.add_argument("--input", required=True)
    add_launcher_arguments(p)
    p.add_argument("--rtol", type=float, default=1e-8)
    p.add_argument("--atol", type=float, default=1e-12)
    p.add_argument("--tolerance", action="append", default=[], metavar="COLUMN=RTOL,ATOL",
                   help="a column's own tolerances")
    p.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    p.add_argument("--update", action="store_true", help="write a new reference log")
    p.add_argument("--expect-difference", action="store_true",
                   help="pass only if the run differs from the reference")
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    name = args.input[3:] if args.input.startswith("in.") else args.input
    per_column = {}
    for item in args.tolerance:
        column, _, pair = item.partition("=")
        per_column[column] = tuple(float(v) for v in pair.split(","))

    with tempfile.TemporaryDirectory() as workdir:
        new_log = run_example(args, workdir, "log.new")
        if args.update:
            stamp = time.strftime("%d%b%y")
            target = os.path.join(args.example, f"log.{stamp}.{name}.g++.{args.np}")
            for old in glob.glob(os.path.join(args.example, f"log.*.{name}.g++.{args.np}")):
                os.remove(old)
            shutil.copy(new_log, target)
            print(f"wrote {target}")
            return
        reference = reference_log(args.example, name, args.np)
        if reference is None:
            sys.exit(f"regression: no reference log for {name} on {args.np} ranks in {args.example}")
        problems = compare(reference, new_log, args.rtol, args.atol, per_column)
        rows = sum(len(rows) for _, rows in thermo_blocks(reference))
    if args.expect_difference:
        if not problems:
            sys.exit(f"regression: {name} with {args.var} still matches {reference}: a moved "
                     "trajectory went unnoticed")
        print(f"{name} with {args.var} differs from {os.path.basename(reference)} as it must "
              f"({len(problems)} differences, first: {problems[0]})")
        return
    if problems:
        print(f"{len(problems)} differences from {reference}:")
        print("\n".join(problems[:40]))
        sys.exit(1)
    print(f"{name} on {args.np} ranks matches {os.path.basename(reference)} ({rows} thermo rows)")


if __name__ == "__main__":
    main()
