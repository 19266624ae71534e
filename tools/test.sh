#!/usr/bin/env bash
# Sets up and builds what is missing (see tools/setup.sh), then runs every test with ctest.
#   tools/test.sh [setup.sh options]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$here/build"
args=("$@")
for ((k = 0; k < ${#args[@]}; k++)); do
  [ "${args[k]}" = --build-dir ] && build_dir=$(realpath -m "${args[k + 1]}")
done
"$here/tools/setup.sh" "$@"
cd "$build_dir"
ctest --output-on-failure --timeout 900
