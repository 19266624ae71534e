#!/bin/sh
# Makes an adhesive tissue of 27 deformable polyhedra pressed to jamming
# (doc/Howto_polyhedra.rst, "A jammed adhesive 3d tissue"):
#   examples/polyhedra/make_tissue3d.sh [OUT] [--p-jam P_jam] [--prefer theta0|shape]
# Dilute cells (tools/make_cells3d.py) are pressed to jamming at P_jam (in.make_tissue3d), their
# overlaps bonded, and the pressed shapes made preferred (tools/prefer_current_shape3d.py): every
# edge's bending angle theta0 (--prefer theta0, the default), or every edge's l0 and theta0 and
# every cell's v0 (--prefer shape). As shipped:
#   make_tissue3d.sh                                  tissue27.data (P_jam 0.05, theta0), which
#                                                     in.tissue3d relaxes
#   make_tissue3d.sh open27.data --p-jam 0.2 --prefer shape
#                                                     open27.data, which in.open_tissue3d grows:
#                                                     pressed harder, the cells flatten against
#                                                     each other and fill more of the box, and
#                                                     keep those shapes at the lower P0 = 0.05
#                                                     (make_open_tissue3d.sh)
# OUT may be left out only with the defaults (it is then tissue27.data here): a tissue made with
# other options must be named, so that it never overwrites the shipped one. Scratch files go to
# a temporary folder. Needs build/lmp; one rank (seconds of CPU).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=""
p_jam=0.05
prefer=theta0
while [ $# -gt 0 ]; do
  case "$1" in
    --p-jam) [ $# -gt 1 ] || { echo "make_tissue3d.sh: --p-jam needs a value" >&2; exit 1; }
             p_jam=$2; shift 2 ;;
    --prefer) [ $# -gt 1 ] || { echo "make_tissue3d.sh: --prefer needs a value" >&2; exit 1; }
              prefer=$2; shift 2 ;;
    -*) echo "make_tissue3d.sh: unknown option $1" >&2; exit 1 ;;
    *) [ -z "$out" ] || { echo "make_tissue3d.sh: unexpected argument '$1' (OUT is '$out')" >&2; exit 1; }
       out=$(realpath "$1"); shift ;;
  esac
done
# P_jam must be a positive number (in.make_tissue3d runs with -screen none: its error would be lost)
case "$p_jam" in
  ''|*[!0-9.eE+-]*) echo "make_tissue3d.sh: --p-jam must be a positive number, got '$p_jam'" >&2; exit 1 ;;
esac
awk -v p="$p_jam" 'BEGIN { exit !(p + 0 > 0) }' ||
  { echo "make_tissue3d.sh: --p-jam must be a positive number, got '$p_jam'" >&2; exit 1; }
if [ -z "$out" ]; then
  if [ "$p_jam" != 0.05 ] || [ "$prefer" != theta0 ]; then
    echo "make_tissue3d.sh: name the output file when --p-jam or --prefer differ from the" \
         "defaults (the default OUT is the shipped tissue27.data)" >&2
    exit 1
  fi
  out="$here/tissue27.data"
fi
case "$prefer" in
  theta0) prefer_option=--theta0-only ;;
  shape) prefer_option= ;;
  *) echo "make_tissue3d.sh: --prefer must be theta0 or shape, got '$prefer'" >&2; exit 1 ;;
esac
lmp="$root/build/lmp"
[ -x "$lmp" ] || { echo "make_tissue3d.sh: no $lmp (build it with tools/setup.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/tools/make_cells3d.py" "$work/dilute27.data" --cells 27 --level 1 --jitter 0.03 \
  --seed 7 --spacing 1.15
(cd "$work" && "$lmp" -in "$here/in.make_tissue3d" -var dilute dilute27.data \
  -var jammed jammed27.data -var P_jam "$p_jam" -echo none -screen none -log log.make_tissue3d) ||
  { echo "make_tissue3d.sh: in.make_tissue3d failed; the end of its log:" >&2
    tail -5 "$work/log.make_tissue3d" >&2; exit 1; }
grep -E "^(jammed|adhere_cells):" "$work/log.make_tissue3d"
python3 "$root/tools/prefer_current_shape3d.py" "$work/jammed27.data" "$out" $prefer_option
