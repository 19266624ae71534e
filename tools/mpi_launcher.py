"""The command line that starts a program on several MPI ranks, for the tools that run LAMMPS.

    import mpi_launcher     # with tools/ on sys.path
    command, env = mpi_launcher.command(ranks, [lmp, "-in", "in.mesophyll"])

No MPI implementation's flags are fixed here; each part comes from an argument, else from an
environment variable, else from a default that suits Debian's Open MPI:

  launcher      argument mpirun, else $MESOPHYLL_MPIRUN, else "mpirun"; a command line split as
                the shell splits it ("srun --mpi=pmix", "mpiexec -hosts a,b")
  rank count    argument numproc_flag, else $MESOPHYLL_NUMPROC_FLAG, else "-np" (srun: "-n")
  flags         argument flags, else $MESOPHYLL_MPIRUN_FLAGS (used as given, also when empty),
                else "--oversubscribe" for Open MPI (its --version says so: more ranks than
                cores are then allowed, as the tests' MESOPHYLL_MPIEXEC_FLAGS allow them), nothing
                for any other launcher

For Open MPI the environment also gets its run-as-root variables (OMPI_ALLOW_RUN_AS_ROOT*:
Open MPI refuses to start as root without them; other launchers ignore them).

The command is LAUNCHER RANK-FLAG RANKS FLAGS PROGRAM...; on one rank the program alone, without
a launcher. Standard library only.
"""
import functools
import os
import shlex
import shutil
import subprocess

DEFAULT_LAUNCHER = "mpirun"
DEFAULT_NUMPROC_FLAG = "-np"
OPEN_MPI_ROOT_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}


@functools.lru_cache(maxsize=None)
def is_open_mpi(launcher):
    """True when `launcher --version` names Open MPI (asked once per launcher)."""
    try:
        result = subprocess.run(shlex.split(launcher) + ["--version"], capture_output=True,
                                text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return False
    text = result.stdout + result.stderr
    return "Open MPI" in text or "OpenRTE" in text


def launcher(mpirun=None):
    return mpirun or os.environ.get("MESOPHYLL_MPIRUN") or DEFAULT_LAUNCHER


def command(ranks, program, mpirun=None, flags=None, numproc_flag=None, env=None):
    """(argv, environment) that run program (a list) on ranks MPI ranks."""
    if ranks < 1:
        raise ValueError(f"mpi_launcher: ranks must be at least 1, got {ranks}")
    env = dict(os.environ if env is None else env)
    if ranks == 1:
        return list(program), env
    name = launcher(mpirun)
    numproc_flag = numproc_flag or os.environ.get("MESOPHYLL_NUMPROC_FLAG") or DEFAULT_NUMPROC_FLAG
    open_mpi = is_open_mpi(name)
    if open_mpi:
        env.update(OPEN_MPI_ROOT_ENV)
    if flags is None:
        flags = os.environ.get("MESOPHYLL_MPIRUN_FLAGS")
    if flags is None:
        flags = "--oversubscribe" if open_mpi else ""
    words = shlex.split(name)
    if not words or shutil.which(words[0]) is None:
        # a clear stop rather than a FileNotFoundError traceback from subprocess
        raise SystemExit(f"mpi_launcher: MPI launcher '{name}' not found; set MESOPHYLL_MPIRUN "
                         f"(or the tool's --mpirun) to your MPI's launcher, e.g. mpirun or srun")
    argv = words + [numproc_flag, str(ranks)] + shlex.split(flags) + list(program)
    return argv, env
