#!/usr/bin/env bash
# Sets up and builds what is missing (see tools/setup.sh), then runs every test with ctest.
#   tools/test.sh [setup.sh options]   (--sanitize[-package]: ASan+UBSan build in build-sanitize/)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$here/build"
args=("$@")
named_dir=0
for ((k = 0; k < ${#args[@]}; k++)); do
  [ "${args[k]}" = --build-dir ] && { build_dir=$(realpath -m "${args[k + 1]}"); named_dir=1; }
done
timeout=900
for a in "$@"; do
  [ "$a" = --sanitize ] || [ "$a" = --sanitize-package ] || continue
  [ "$named_dir" = 0 ] && build_dir="$here/build-sanitize"
  timeout=3600    # ASan's slow unwinder and shadow memory make the longest tests a few times slower
done
"$here/tools/setup.sh" "$@"
cd "$build_dir"
ctest --output-on-failure --timeout "$timeout"
