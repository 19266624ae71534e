"""Run a MESOPHYLL input in a scratch copy of an example folder and read what the run left.

    import mesophyll_run    # with tools/ on sys.path
    r = mesophyll_run.run(lmp, "in.mesophyll", work, {"N": 16, "steps": 3}, ranks=2)
    r.growth[16]["phi_patch"], r.loops[-1].seconds, r.failures

scratch(workdir, example=EXAMPLE, files=())
    Copies the example folder (and the extra files) into workdir, leaving out growth tables a
    run in the example folder may have left; returns workdir.
run(lmp, input, workdir, variables=None, ranks=1, example=EXAMPLE, files=(), log="log.lammps",
    mpirun=None, mpirun_flags=None, check=True, capture=False, timeout=None)
    Runs `lmp -in input -var NAME VALUE ... -log log -screen none` in workdir (first made by
    scratch() unless example is None), when ranks > 1 under the MPI launcher of
    tools/mpi_launcher.py (mpirun and mpirun_flags, else $MESOPHYLL_MPIRUN and
    $MESOPHYLL_MPIRUN_FLAGS, else Debian's Open MPI: mpirun --oversubscribe, allowed as
    root). check: raise subprocess.CalledProcessError on a non-zero
    exit; capture: keep LAMMPS's stdout and stderr off the terminal (in Run.output); timeout:
    seconds, subprocess.TimeoutExpired past it. Returns a Run.
read(workdir, log="log.lammps", returncode=None, wall=0.0, output="")
    The Run of a finished run's folder, without running anything (run() ends with it).
Run: workdir, returncode, wall (seconds of the LAMMPS process), output (captured stdout and
    stderr, or ""), log (the log's text, "" without a log), thermo, loops, minimizations,
    checks as the functions below return them, failures (the checks that FAILED), growth
    ({N: growth_table()} of every growth.N<N>.txt in workdir).
thermo_blocks(path)  -> [(columns, rows)] of every thermo table (tests/regression.py's reader).
loop_times(log)      -> [Loop(seconds, procs, steps, atoms, cpu, minimization)] per "Loop time
                        of ..." line; cpu: the "% CPU use" that follows, as a fraction (None if
                        absent); minimization: whether "Minimization stats:" follows before the
                        next loop (a minimize, not a run such as ftol_scale area's run 0).
minimization_loops(loops) -> those of loop_times()' loops that are minimizations, in the
                        order of minimizations(log).
minimizations(log)   -> [(iterations, force evaluations)] per minimization.
check_lines(log)     -> [Check(minimum, step, text, failed, problems)] per fix dpoly/check line
                        ("fix dpoly/check: minimum K at step S: TEXT[; FAILED; PROBLEMS]").
growth_table(path)   -> {column: [float per growth step]} of a growth.N<N>.txt ("# step P ...").
Standard library only.
"""
import collections
import glob
import os
import re
import resource
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLE = os.path.join(ROOT, "examples", "mesophyll")
sys.path.insert(0, os.path.join(ROOT, "tests"))
from regression import thermo_blocks  # noqa: E402,F401  (the thermo-table reader of the tests)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mpi_launcher  # noqa: E402

Loop = collections.namedtuple("Loop", "seconds procs steps atoms cpu minimization")
Check = collections.namedtuple("Check", "minimum step text failed problems")
Run = collections.namedtuple("Run", "workdir returncode wall output log thermo loops "
                                    "minimizations checks failures growth")

LOOP = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")
CPU_USE = re.compile(r"^([0-9.]+)% CPU use")
MINIMIZATION_STATS = "Minimization stats:"
EVALS = re.compile(r"Iterations, force evaluations = (\d+) (\d+)")
CHECK = re.compile(r"^fix dpoly/check: minimum (\d+) at step (\d+): (.*?)(?:; FAILED; (.*))?$",
                   re.MULTILINE)
GROWTH = re.compile(r"growth\.N(\d+)\.txt$")


def children_cpu_seconds():
    """User + system CPU seconds of this process's finished children (lmp, mpirun and what
    they ran): take the difference around a run to get its CPU time."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def loop_times(log):
    loops = []
    for line in log.splitlines():
        m = LOOP.match(line)
        if m:
            loops.append(Loop(float(m.group(1)), int(m.group(2)), int(m.group(3)),
                              int(m.group(4)), None, False))
        m = CPU_USE.match(line)
        if m and loops and loops[-1].cpu is None:
            loops[-1] = loops[-1]._replace(cpu=float(m.group(1)) / 100)
        if line.startswith(MINIMIZATION_STATS) and loops:
            loops[-1] = loops[-1]._replace(minimization=True)
    return loops


def minimization_loops(loops):
    return [loop for loop in loops if loop.minimization]


def minimizations(log):
    return [(int(m.group(1)), int(m.group(2))) for m in EVALS.finditer(log)]


def check_lines(log):
    return [Check(int(m.group(1)), int(m.group(2)), m.group(3), m.group(4) is not None,
                  m.group(4) or "") for m in CHECK.finditer(log)]


def growth_table(path):
    with open(path) as f:
        names = f.readline().lstrip("#").split()
        rows = [[float(w) for w in line.split()] for line in f if line.strip()]
    return {name: [row[k] for row in rows] for k, name in enumerate(names)}


def scratch(workdir, example=EXAMPLE, files=()):
    shutil.copytree(example, workdir, symlinks=False, dirs_exist_ok=True)
    for path in glob.glob(os.path.join(workdir, "growth.N*.txt")):
        os.remove(path)
    for path in files:
        shutil.copy(path, workdir)
    return workdir


def read(workdir, log="log.lammps", returncode=None, wall=0.0, output=""):
    log_path = os.path.join(workdir, log)
    text = open(log_path).read() if os.path.exists(log_path) else ""
    checks = check_lines(text)
    growth = {int(GROWTH.search(path).group(1)): growth_table(path)
              for path in glob.glob(os.path.join(workdir, "growth.N*.txt"))}
    return Run(workdir, returncode, wall, output, text, thermo_blocks(log_path) if text else [],
               loop_times(text), minimizations(text), checks, [c for c in checks if c.failed],
               growth)


def run(lmp, input, workdir, variables=None, ranks=1, example=EXAMPLE, files=(),
        log="log.lammps", mpirun=None, mpirun_flags=None, check=True, capture=False,
        timeout=None):
    if example is not None:
        scratch(workdir, example, files)
    command = [lmp, "-in", input]
    for name, value in (variables or {}).items():
        command += ["-var", name, str(value)]
    command += ["-log", log, "-screen", "none"]
    command, env = mpi_launcher.command(ranks, command, mpirun, mpirun_flags)
    start = time.perf_counter()
    result = subprocess.run(command, cwd=workdir, env=env, capture_output=capture, text=True,
                            timeout=timeout)
    wall = time.perf_counter() - start
    output = (result.stdout or "") + (result.stderr or "")
    if check and result.returncode != 0:
        raise subprocess.CalledProcessError(result.returncode, command, result.stdout,
                                            result.stderr)
    return read(workdir, log, result.returncode, wall, output)
