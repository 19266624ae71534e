#!/usr/bin/env python3
"""The tools start LAMMPS on several ranks with the launcher the user names, no Open MPI flag fixed.

    check_launcher.py --lmp BUILD/lmp

1. tools/mpi_launcher.py's command line: one rank runs the program alone; the launcher, its
   rank-count flag and its flags come from the arguments, else from $MESOPHYLL_MPIRUN,
   $MESOPHYLL_NUMPROC_FLAG and $MESOPHYLL_MPIRUN_FLAGS (split as the shell splits them; flags used
   as given, also when empty); a launcher that is not Open MPI gets neither --oversubscribe nor
   Open MPI's run-as-root variables; Debian's mpirun (when it is Open MPI) gets both, as before.
2. The tools use it: tools/make_tissue.py --np 2, tools/mesophyll_run.run(ranks=2) and
   tools/run-example.sh --np 2 start LAMMPS through a stand-in launcher named by
   $MESOPHYLL_MPIRUN (a script that records its arguments and runs the program on one rank), with
   the flags of $MESOPHYLL_MPIRUN_FLAGS and the rank-count flag of $MESOPHYLL_NUMPROC_FLAG, and
   make_tissue.py's --mpirun and --mpirun-flags win over the environment; the runs finish.
"""
import argparse
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
import mpi_launcher  # noqa: E402
import mesophyll_run  # noqa: E402

LAUNCHER_ENV = ("MESOPHYLL_MPIRUN", "MESOPHYLL_NUMPROC_FLAG", "MESOPHYLL_MPIRUN_FLAGS")
OMPI_ROOT = ("OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM")
# the stand-in launcher: --version names no MPI; otherwise it appends its arguments to
# $STAND_IN_RECORD and runs the program (the first absolute path to an executable) on one rank
STAND_IN = """#!{python}
import json, os, sys
args = sys.argv[1:]
if args[-1:] == ["--version"]:
    print("stand-in launcher 1.0")
    sys.exit(0)
with open(os.environ["STAND_IN_RECORD"], "a") as f:
    f.write(json.dumps(args) + "\\n")
k = next(i for i, a in enumerate(args) if os.path.isabs(a) and os.path.isfile(a)
         and os.access(a, os.X_OK))
os.execv(args[k], args[k:])
"""
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def clean_environment():
    for name in LAUNCHER_ENV + OMPI_ROOT:
        os.environ.pop(name, None)


def check_command_line(stand_in):
    clean_environment()
    program = ["/bin/lmp", "-in", "in.x"]
    argv, env = mpi_launcher.command(1, program, mpirun=stand_in)
    check(argv == program, f"one rank: the program alone ({argv})")

    argv, env = mpi_launcher.command(2, program, mpirun=stand_in)
    check(argv == [stand_in, "-np", "2"] + program,
          f"another launcher: launcher -np 2 program, no flags ({argv})")
    check(not any(name in env for name in OMPI_ROOT),
          "another launcher: no Open MPI run-as-root variables")

    os.environ.update(MESOPHYLL_MPIRUN=f"{stand_in} --tag 'a b'", MESOPHYLL_NUMPROC_FLAG="-n",
                      MESOPHYLL_MPIRUN_FLAGS="--bind-to core --map-by slot")
    argv, _ = mpi_launcher.command(3, program)
    check(argv == [stand_in, "--tag", "a b", "-n", "3", "--bind-to", "core", "--map-by", "slot"]
          + program, f"environment: launcher, rank flag and flags split as the shell ({argv})")
    # a launcher that exists on every machine ('true'), named by argument
    argv, _ = mpi_launcher.command(3, program, mpirun="true", flags="", numproc_flag="-N")
    check(argv == ["true", "-N", "3"] + program, f"arguments win over the environment ({argv})")
    try:
        mpi_launcher.command(2, program, mpirun="no-such-launcher")
        check(False, "a launcher that does not exist is refused")
    except SystemExit as e:
        check("'no-such-launcher' not found" in str(e), f"a missing launcher is named: {e}")
    os.environ["MESOPHYLL_MPIRUN_FLAGS"] = ""
    argv, _ = mpi_launcher.command(2, program)
    check(argv == [stand_in, "--tag", "a b", "-n", "2"] + program,
          f"MESOPHYLL_MPIRUN_FLAGS empty: no flags ({argv})")
    clean_environment()

    try:
        mpi_launcher.command(0, program)
        check(False, "0 ranks refused")
    except ValueError as e:
        check("0" in str(e), f"0 ranks refused: {e}")

    if shutil.which("mpirun") and mpi_launcher.is_open_mpi("mpirun"):
        argv, env = mpi_launcher.command(2, program)
        check(argv == ["mpirun", "-np", "2", "--oversubscribe"] + program
              and all(env.get(name) == "1" for name in OMPI_ROOT),
              f"Debian's Open MPI by default: mpirun -np 2 --oversubscribe, run as root ({argv})")
        os.environ["MESOPHYLL_MPIRUN_FLAGS"] = ""
        argv, env = mpi_launcher.command(2, program)
        check(argv == ["mpirun", "-np", "2"] + program,
              f"Open MPI with MESOPHYLL_MPIRUN_FLAGS empty: no --oversubscribe ({argv})")
        clean_environment()
    else:
        print("note  mpirun is not Open MPI here: its defaults are not checked")


def records(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        records = [json.loads(line) for line in f]
    os.remove(path)
    return records


def check_tools(lmp, stand_in, work):
    record = os.path.join(work, "record.jsonl")
    clean_environment()
    os.environ.update(STAND_IN_RECORD=record, MESOPHYLL_MPIRUN=stand_in,
                      MESOPHYLL_NUMPROC_FLAG="-n", MESOPHYLL_MPIRUN_FLAGS="--stand-in-flag")

    out = os.path.join(work, "tissue.data")
    result = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "make_tissue.py"), out,
                             "--cells", "4", "--seed", "3", "--np", "2", "--lmp", lmp],
                            capture_output=True, text=True)
    launched = records(record)
    check(result.returncode == 0 and os.path.exists(out),
          f"make_tissue.py --np 2 through $MESOPHYLL_MPIRUN finished (exit {result.returncode})"
          + ("" if result.returncode == 0 else "\n" + result.stdout[-2000:] + result.stderr[-2000:]))
    check(len(launched) == 1 and launched[0][:3] == ["-n", "2", "--stand-in-flag"]
          and launched[0][3] == lmp,
          f"make_tissue.py: launcher -n 2 --stand-in-flag lmp ... ({launched})")

    result = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "make_tissue.py"), out,
                             "--cells", "4", "--seed", "3", "--np", "3", "--lmp", lmp,
                             "--mpirun", f"{stand_in} --from-option", "--mpirun-flags", ""],
                            capture_output=True, text=True)
    launched = records(record)
    check(result.returncode == 0 and len(launched) == 1
          and launched[0][:4] == ["--from-option", "-n", "3", lmp],
          f"make_tissue.py --mpirun and --mpirun-flags win over the environment ({launched})")

    run = mesophyll_run.run(lmp, "in.relax_cells", os.path.join(work, "relax"), ranks=2,
                            example=os.path.join(ROOT, "examples", "polygons"), capture=True)
    launched = records(record)
    check(run.returncode == 0 and len(run.loops) > 0, "mesophyll_run.run(ranks=2) finished")
    check(len(launched) == 1 and launched[0][:4] == ["-n", "2", "--stand-in-flag", lmp],
          f"mesophyll_run.run: launcher -n 2 --stand-in-flag lmp ... ({launched})")

    build = os.path.join(work, "build")     # run-example.sh runs under BUILD/examples/
    os.makedirs(build)
    os.symlink(lmp, os.path.join(build, "lmp"))
    result = subprocess.run([os.path.join(ROOT, "tools", "run-example.sh"), "--build-dir", build,
                             "--np", "2", "polygons", "in.relax_cells"],
                            capture_output=True, text=True)
    launched = records(record)
    check(result.returncode == 0, f"run-example.sh --np 2 finished (exit {result.returncode})"
          + ("" if result.returncode == 0 else "\n" + result.stderr[-2000:]))
    check(len(launched) == 1 and launched[0][:3] == ["-n", "2", "--stand-in-flag"],
          f"run-example.sh: launcher -n 2 --stand-in-flag lmp ... ({launched})")
    # a launcher the user named that does not exist: an error, not a quiet run on one rank
    os.environ["MESOPHYLL_MPIRUN"] = os.path.join(work, "no-such-launcher")
    result = subprocess.run([os.path.join(ROOT, "tools", "run-example.sh"), "--build-dir", build,
                             "--np", "2", "polygons", "in.relax_cells"],
                            capture_output=True, text=True)
    check(result.returncode == 2 and "no-such-launcher" in result.stderr
          and len(records(record)) == 0,
          f"run-example.sh: a missing MESOPHYLL_MPIRUN stops (exit {result.returncode}: "
          f"{result.stderr.strip()[-300:]})")
    clean_environment()


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lmp", required=True)
    args = p.parse_args()
    lmp = os.path.abspath(args.lmp)
    with tempfile.TemporaryDirectory() as work:
        stand_in = os.path.join(work, "stand-in-mpirun")
        with open(stand_in, "w") as f:
            f.write(STAND_IN.format(python=sys.executable))
        os.chmod(stand_in, os.stat(stand_in).st_mode | stat.S_IXUSR)
        check_command_line(stand_in)
        check_tools(lmp, stand_in, work)
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all launcher checks passed")


if __name__ == "__main__":
    main()
