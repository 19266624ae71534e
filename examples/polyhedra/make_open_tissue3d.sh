#!/bin/sh
# Makes open27.data, the confluent adhesive tissue of 27 deformable polyhedra that
# in.open_tissue3d grows (doc/Howto_polyhedra.rst, "Growth: what opens a 3d tissue"):
#   examples/polyhedra/make_open_tissue3d.sh [OUT] [P_jam]
# OUT defaults to open27.data here, P_jam to 0.2; scratch files go to a temporary folder. Needs
# build/lmp; one rank (seconds of CPU). The steps of make_tissue3d.sh with two changes: the cells
# are pressed harder (P_jam 0.2 instead of 0.05), so that they flatten against each other and
# fill more of the box, and the pressed shapes become the preferred ones (every edge's l0 and
# theta0 and every cell's v0 set to the current values, prefer_current_shape3d.py), so that the
# tissue keeps them when in.open_tissue3d relaxes it at the lower P0 = 0.05.
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out="$here/open27.data"
[ $# -gt 0 ] && out=$(realpath "$1")
p_jam=${2:-0.2}
lmp="$root/build/lmp"
[ -x "$lmp" ] || { echo "make_open_tissue3d.sh: no $lmp (build it with tools/setup.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/tools/make_cells3d.py" "$work/dilute27.data" --cells 27 --level 1 --jitter 0.03 \
  --seed 7 --spacing 1.15
(cd "$work" && "$lmp" -in "$here/in.make_tissue3d" -var dilute dilute27.data \
  -var jammed jammed27.data -var P_jam "$p_jam" -echo none -screen none -log log.make_tissue3d)
grep -E "^(jammed|adhere_cells):" "$work/log.make_tissue3d"
python3 "$here/prefer_current_shape3d.py" "$work/jammed27.data" "$out"
