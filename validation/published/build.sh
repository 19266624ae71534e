#!/usr/bin/env bash
# Builds the published driver main/meso2D/readInMesoNetwork2D.cpp of jacktreado/dpm, unmodified,
# with the compile command written at its top (g++ -O3 --std=c++11 -I src ... src/*.cpp).
#
#   build.sh [REPO] [--no-insertion] [--out DIR]
#
# REPO: a clone or bare mirror of jacktreado/dpm (git clone https://github.com/jacktreado/dpm;
# default: $DPM_REPO; the data here were made from commit 6c22e4e, README.md); its
# HEAD is exported with `git archive` into DIR/src-<commit> (default DIR: /tmp/published-dpm) and
# built there, so nothing of the published code enters this repository. Writes DIR/meso_<commit>
# and prints its path.
#
# --no-insertion builds a second binary, DIR/meso_<commit>_noinsert, from a copy of the driver
# with ONE line changed: `const int NVMAXMAG = 5;` becomes `const int NVMAXMAG = 1;`, so that
# NVMAX = NVTOT and mesoNetworkEnthalpyMin() never calls addMesophyllCellMaterial() (its guard is
# `if (NVTOT < NVMAX)`). The change is made by sed in the scratch copy and shown as a diff.
set -euo pipefail

repo=${DPM_REPO:-}
out=/tmp/published-dpm
noinsert=0
while [ $# -gt 0 ]; do
  case "$1" in
    --no-insertion) noinsert=1 ;;
    --out) out=$2; shift ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) repo=$1 ;;
  esac
  shift
done

[ -n "$repo" ] || { echo "build.sh: give a clone of jacktreado/dpm (argument REPO or DPM_REPO)" >&2; exit 2; }
commit=$(git -C "$repo" rev-parse HEAD)
src="$out/src-$commit"
mkdir -p "$out"
if [ ! -d "$src" ]; then
  mkdir -p "$src.tmp"
  git -C "$repo" archive HEAD | tar -x -C "$src.tmp"
  mv "$src.tmp" "$src"
fi
cd "$src"
driver=main/meso2D/readInMesoNetwork2D.cpp
flags=(-O3 --std=c++11 -I src)
echo "published commit $commit; $(g++ --version | head -1); flags ${flags[*]}" >&2

bin="$out/meso_$commit"
[ -x "$bin" ] || nice -n 5 g++ "${flags[@]}" "$driver" src/*.cpp -o "$bin"
echo "$bin"

if [ "$noinsert" = 1 ]; then
  sed 's/^const int NVMAXMAG = 5;/const int NVMAXMAG = 1;/' "$driver" > "$out/readInMesoNetwork2D_noinsert.cpp"
  diff "$driver" "$out/readInMesoNetwork2D_noinsert.cpp" >&2 && { echo "sed changed nothing" >&2; exit 1; }
  nb="$out/meso_${commit}_noinsert"
  [ -x "$nb" ] || nice -n 5 g++ "${flags[@]}" "$out/readInMesoNetwork2D_noinsert.cpp" src/*.cpp -o "$nb"
  echo "$nb"
fi
