#!/usr/bin/env bash
# Runs an example of the package in a scratch copy under the build folder and says where its
# log and outputs are; draws a development run's PNGs (tools/plot_mesophyll.py).
#   tools/run-example.sh [--build-dir DIR] [--np N] [--var NAME VALUE ...] [--resume] [EXAMPLE [INPUT]]
# Default: the paper's main run, examples/mesophyll/in.mesophyll, on as many ranks as cores (<= 2).
# --resume: continue a killed development run in its folder from its newest restart.N*.<step>
# (in.mesophyll -var resume FILE); give the same --var as the killed run.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$here/build"
np=$(( $(nproc) >= 2 ? 2 : 1 ))
vars=()
positional=()
resume=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir=$(realpath -m "$2"); shift ;;
    --np) np=$2; shift ;;
    --var) vars+=(-var "$2" "$3"); shift 2 ;;
    --resume) resume=yes ;;
    -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
    *) positional+=("$1") ;;
  esac
  shift
done
example=${positional[0]:-mesophyll}
input=${positional[1]:-in.$example}
src="$here/examples/$example"
[ -f "$src/$input" ] || { echo "run-example.sh: no input $src/$input" >&2; exit 2; }
[ -x "$build_dir/lmp" ] || { echo "run-example.sh: no $build_dir/lmp; run tools/setup.sh first" >&2; exit 2; }

# the launcher's program (tools/mpi_launcher.py's choice, below): the default mpirun missing
# means one rank, as before; a launcher the user named and that is missing is an error
read -r -a launcher <<< "${MESOPHYLL_MPIRUN:-mpirun}"
if [ "$np" -gt 1 ] && ! command -v "${launcher[0]}" >/dev/null; then
  if [ -n "${MESOPHYLL_MPIRUN:-}" ]; then
    echo "run-example.sh: MPI launcher '${launcher[0]}' (MESOPHYLL_MPIRUN) not found" >&2; exit 2
  fi
  echo "run-example.sh: no mpirun on PATH, running on 1 rank"
  np=1
fi
work="$build_dir/examples/$example"
log="log.$(basename "$input" | sed 's/^in\.//')"
if [ -n "$resume" ]; then
  # the folder of the killed run as it is; the newest complete restart file in it
  restart=$(cd "$work" 2>/dev/null && ls -t restart.N*.[0-9]* 2>/dev/null | head -n 1) || true
  [ -n "$restart" ] || { echo "run-example.sh: no restart.N*.<step> in $work to resume from" >&2; exit 2; }
  vars+=(-var resume "$restart")
  log="$log.resumed.${restart##*.}"
  echo "Resuming $example/$input from $work/$restart"
  cd "$work"
else
  rm -rf "$work"; mkdir -p "$work"; cp -rL "$src/." "$work/"
  cd "$work"
fi
if [ "$np" -gt 1 ]; then
  # the launcher as tools/mpi_launcher.py chooses it: $MESOPHYLL_MPIRUN (default mpirun),
  # $MESOPHYLL_NUMPROC_FLAG (-np), $MESOPHYLL_MPIRUN_FLAGS (default for Open MPI
  # --oversubscribe, and its run-as-root variables; for other launchers none)
  flags=""
  if "${launcher[@]}" --version 2>&1 | grep -qE "Open MPI|OpenRTE"; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    flags="--oversubscribe"
  fi
  read -r -a flags <<< "${MESOPHYLL_MPIRUN_FLAGS-$flags}"
  "${launcher[@]}" "${MESOPHYLL_NUMPROC_FLAG:--np}" "$np" "${flags[@]}" \
    "$build_dir/lmp" -in "$input" -log "$log" "${vars[@]}"
else
  "$build_dir/lmp" -in "$input" -log "$log" "${vars[@]}"
fi
echo
echo "Example '$example/$input' finished on $np rank(s). Log: $work/$log"

# a development run leaves growth.N*.txt and cells.N*.dump: draw them with Debian's matplotlib
python=""
for candidate in python3 /usr/bin/python3; do
  if "$candidate" -c 'import matplotlib, numpy' 2>/dev/null; then python=$candidate; break; fi
done
for growth in growth.N*.txt; do
  [ -f "$growth" ] || continue
  cells=${growth#growth.}; cells=${cells%.txt}
  if [ -z "$python" ]; then
    echo "No python3 with matplotlib and numpy (Debian: python3-matplotlib python3-numpy): no plots."
    break
  fi
  "$python" "$here/tools/plot_mesophyll.py" "$growth" "cells.$cells.dump" --out "mesophyll_$cells"
  echo "Growth record: $work/$growth; plots: $work/mesophyll_${cells}_{shape,packing,snapshots}.png"
  # the movie (ffmpeg, python3-matplotlib) and the ParaView series (python3-vtk9): each tool
  # says what it misses, and the run stays a success without them
  if "$python" "$here/tools/make_movie.py" "$growth" "cells.$cells.dump" --out "mesophyll_$cells"; then
    echo "Movie: $work/mesophyll_$cells.mp4 and .gif"
  fi
  if "$python" "$here/tools/write_vtk.py" "cells.$cells.dump" --growth "$growth" \
       --out "vtk/$cells" >/dev/null; then
    echo "ParaView: open $work/vtk/${cells}_cells.pvd"
  fi
done
