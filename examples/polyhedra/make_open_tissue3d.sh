#!/bin/sh
# Makes open27.data, the confluent adhesive tissue of 27 deformable polyhedra that
# in.open_tissue3d grows (doc/Howto_polyhedra.rst, "Growth: what opens a 3d tissue"):
#   examples/polyhedra/make_open_tissue3d.sh [OUT] [P_jam]
# OUT defaults to open27.data here, P_jam to 0.2: make_tissue3d.sh with the cells pressed at
# P_jam and the pressed shapes preferred (--prefer shape), which says why.
here=$(cd "$(dirname "$0")" && pwd)
exec "$here/make_tissue3d.sh" "${1:-$here/open27.data}" --p-jam "${2:-0.2}" --prefer shape
