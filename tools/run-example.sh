#!/usr/bin/env bash
# Runs an example of the package in a scratch copy under the build folder and says where its
# log and outputs are.   tools/run-example.sh [--build-dir DIR] [--np N] [EXAMPLE [INPUT]]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$here/build"
np=1
positional=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir=$(realpath -m "$2"); shift ;;
    --np) np=$2; shift ;;
    -h|--help) sed -n '2,3p' "$0"; exit 0 ;;
    *) positional+=("$1") ;;
  esac
  shift
done
example=${positional[0]:-polygons}
input=${positional[1]:-in.relax_cells}
src="$here/examples/$example"
[ -f "$src/$input" ] || { echo "run-example.sh: no input $src/$input" >&2; exit 2; }
[ -x "$build_dir/lmp" ] || { echo "run-example.sh: no $build_dir/lmp; run tools/setup.sh first" >&2; exit 2; }

work="$build_dir/examples/$example"
rm -rf "$work"; mkdir -p "$work"; cp -r "$src/." "$work/"
cd "$work"
log="log.$(basename "$input" | sed 's/^in\.//')"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [ "$np" -gt 1 ]; then
  mpirun -np "$np" --oversubscribe "$build_dir/lmp" -in "$input" -log "$log"
else
  "$build_dir/lmp" -in "$input" -log "$log"
fi
echo
echo "Example '$example/$input' finished. Log: $work/$log"
