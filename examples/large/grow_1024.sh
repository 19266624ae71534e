#!/usr/bin/env bash
# A 1024-cell tissue grown as the main example grows its 64 cells, to phi_patch <= 0.5.
#   examples/large/grow_1024.sh [--np N] [--resume]      (from anywhere; default 2 ranks)
# The tissue is four periodic copies (2 x 2, tools/replicate_tissue.py, seconds) of the shipped
# 256-cell tissue examples/tissue/voronoi_N256.data: its cells repeat every half box. For 1024
# independent cells make one with tools/make_tissue.py (about 20 minutes of CPU) and give it as
# TISSUE=FILE. The run is examples/mesophyll/in.mesophyll with -var N 1024 -var tissue FILE
# -var phi_stop 0.5 -var restart_every 1 -var fnorm rms -var ftol 1e-12, in
# build/examples/mesophyll/ (tools/run-example.sh): every minimization stops when the root mean
# square force per degree of freedom is below 1e-12 (about what the 2-norm of 1e-10 of the
# 64-cell example asks per vertex; the 2-norm would ask 4 times more of 1024 cells and 16 times
# more of their pressure). It writes a restart file after every growth step, and --resume
# continues a killed run there.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
np=2
resume=()
while [ $# -gt 0 ]; do
  case "$1" in
    --np) np=$2; shift ;;
    --resume) resume=(--resume) ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "grow_1024.sh: unknown argument '$1' (--np N, --resume)" >&2; exit 2 ;;
  esac
  shift
done
tissue=${TISSUE:-$here/build/voronoi_N1024.data}
if [ -z "${TISSUE:-}" ] && [ ! -f "$tissue" ]; then
  mkdir -p "$(dirname "$tissue")"
  python3 "$here/tools/replicate_tissue.py" "$here/examples/tissue/voronoi_N256.data" \
    "$tissue" --copies 2 2
fi
[ -f "$tissue" ] || { echo "grow_1024.sh: no tissue file $tissue" >&2; exit 2; }
exec "$here/tools/run-example.sh" --np "$np" "${resume[@]}" --var N 1024 \
  --var tissue "$(realpath "$tissue")" --var phi_stop 0.5 --var restart_every 1 \
  --var fnorm rms --var ftol 1e-12 mesophyll
