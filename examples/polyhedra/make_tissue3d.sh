#!/bin/sh
# Makes tissue27.data, the jammed adhesive tissue of 27 deformable polyhedra that in.tissue3d
# relaxes (doc/Howto_polyhedra.rst "A jammed adhesive 3d tissue"):
#   examples/polyhedra/make_tissue3d.sh [OUT]
# OUT defaults to tissue27.data here; scratch files go to a temporary folder. Needs build/lmp;
# one rank (seconds of CPU).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out="$here/tissue27.data"
[ $# -gt 0 ] && out=$(realpath "$1")
lmp="$root/build/lmp"
[ -x "$lmp" ] || { echo "make_tissue3d.sh: no $lmp (build it with tools/setup.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/tools/make_cells3d.py" "$work/dilute27.data" --cells 27 --level 1 --jitter 0.03 \
  --seed 7 --spacing 1.15
(cd "$work" && "$lmp" -in "$here/in.make_tissue3d" -var dilute dilute27.data \
  -var jammed jammed27.data -echo none -screen none -log log.make_tissue3d)
grep -E "^(jammed|adhere_cells):" "$work/log.make_tissue3d"
python3 "$root/tools/prefer_current_angles3d.py" "$work/jammed27.data" "$out"
