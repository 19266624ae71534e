#!/usr/bin/env bash
# Sets up everything MESOPHYLL needs on Debian 12 and builds LAMMPS with the package.
# Idempotent: a second run only rebuilds what changed (ccache makes a fresh clone fast).
#
#   tools/setup.sh [--serial] [--build-dir DIR] [--lammps-source DIR] [--lammps-tarball FILE]
#                  [--no-install] [--run-example] [--sanitize | --sanitize-package] [--python]
#
# liblammps is a shared library (lmp, the tests and LAMMPS's Python module use the same one);
# --python also installs LAMMPS's own Python package `lammps`, from the LAMMPS source tree, into
# the virtual environment BUILD/venv (Debian's python3-venv, no downloads); examples/python/ runs
# with BUILD/venv/bin/python. Sanitizer builds link LAMMPS statically and have no Python module.
#
# --sanitize builds with AddressSanitizer and UndefinedBehaviorSanitizer (CMake option
# MESOPHYLL_SANITIZE) in build-sanitize/ (unless --build-dir names another), leaving build/ as is;
# a fresh one compiles all of LAMMPS again. --sanitize-package instruments only src/MESOPHYLL and
# the tests (LAMMPS's own objects are the plain build's, from ccache: minutes, not half an hour).
#
# LAMMPS's source is taken, in this order, from: --lammps-source (or $LAMMPS_SOURCE_DIR), a
# tarball named by --lammps-tarball (or $LAMMPS_TARBALL), or the upstream tarball of Debian's
# `lammps` source package, fetched from the mirror of this system's own apt configuration,
# checked against its SHA256 and cached in $MESOPHYLL_CACHE (default ~/.cache/mesophyll).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=""
mpi=ON
sanitize=OFF
sanitize_lammps=ON
install=1
run_example=0
python_module=0
lammps_source=${LAMMPS_SOURCE_DIR:-}
lammps_tarball=${LAMMPS_TARBALL:-}
cache=${MESOPHYLL_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/mesophyll}

while [ $# -gt 0 ]; do
  case "$1" in
    --serial) mpi=OFF ;;
    --build-dir) build_dir=$(realpath -m "$2"); shift ;;
    --lammps-source) lammps_source=$2; shift ;;
    --lammps-tarball) lammps_tarball=$2; shift ;;
    --no-install) install=0 ;;
    --run-example) run_example=1 ;;
    --sanitize) sanitize=ON; sanitize_lammps=ON ;;
    --sanitize-package) sanitize=ON; sanitize_lammps=OFF ;;
    --python) python_module=1 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

if [ -z "$build_dir" ]; then
  if [ "$sanitize" = ON ]; then build_dir="$here/build-sanitize"; else build_dir="$here/build"; fi
fi

say() { printf '\n== %s\n' "$*"; }

# The upstream tarballs of Debian's lammps source package, newest first (file, SHA256, suite).
tarballs=(
  "lammps_20260704+dfsg.orig.tar.gz cddbc45a047416bd48a4a0b87f24a5b61b3446982b74d18cafe619c22b17eb62 sid"
  "lammps_20250204+dfsg.1.orig.tar.xz 3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7 trixie"
)

packages=(build-essential cmake ninja-build ccache git libopenmpi-dev openmpi-bin libeigen3-dev
          libgtest-dev libgmock-dev libyaml-dev librandom123-dev libspectra-dev
          python3 python3-numpy python3-matplotlib python3-scipy python3-skimage python3-vtk9
          python3-venv python3-setuptools python3-wheel
          ffmpeg xz-utils ca-certificates)

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && { say "Debian packages: all present"; return; }
  say "Installing from Debian: ${missing[*]}"
  as_root apt-get update -q
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# The Debian archive's URI as this system's apt knows it (deb822 or one-line format).
debian_mirror() {
  local uri=""
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    uri=$(awk '/^URIs:/{for(i=2;i<=NF;i++) if($i ~ /debian\/?$/ && $i !~ /security/){print $i; exit}}' "$f")
    [ -n "$uri" ] && break
  done
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    uri=$(awk '$1=="deb" && $0 !~ /security/ {for(i=2;i<=NF;i++) if($i ~ /^[a-z]+:\/\//){print $i; exit}}' \
          /etc/apt/sources.list)
  fi
  [ -n "$uri" ] || { echo "setup.sh: no Debian archive found in this system's apt sources" >&2; return 1; }
  echo "${uri%/}"
}

# Fetch one orig tarball with apt's own downloader, which checks the SHA256.
fetch_tarball() {
  local file=$1 sha=$2 suite=$3 mirror aptdir url
  mirror=$(debian_mirror) || return 1
  aptdir="$cache/apt-$suite"
  mkdir -p "$aptdir/lists/partial" "$aptdir/cache/archives/partial"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror $suite main" \
    > "$aptdir/sources.list"
  local opts=(-o "Dir::Etc::SourceList=$aptdir/sources.list" -o Dir::Etc::SourceParts=-
              -o "Dir::State::Lists=$aptdir/lists" -o "Dir::Cache=$aptdir/cache")
  url=""
  if apt-get "${opts[@]}" update -q >/dev/null 2>&1; then
    url=$(apt-get "${opts[@]}" source --print-uris lammps 2>/dev/null |
          awk -v f="$file" '$2==f {gsub("\x27","",$1); print $1}')
  fi
  # The pool path is fixed by Debian's archive layout; use it if the index no longer lists it.
  [ -n "$url" ] || url="$mirror/pool/main/l/lammps/${file//+/%2b}"
  echo "fetching $url"
  /usr/lib/apt/apt-helper download-file "$url" "$cache/$file.part" "SHA256:$sha" &&
    mv "$cache/$file.part" "$cache/$file"
}

find_or_fetch_tarball() {
  mkdir -p "$cache"
  for entry in "${tarballs[@]}"; do
    set -- $entry
    if [ -f "$cache/$1" ] && echo "$2  $cache/$1" | sha256sum -c --status; then
      echo "$cache/$1"; return
    fi
  done
  for entry in "${tarballs[@]}"; do
    set -- $entry
    if fetch_tarball "$1" "$2" "$3" >&2; then echo "$cache/$1"; return; fi
    echo "setup.sh: $1 could not be fetched, trying the next one" >&2
  done
  echo "setup.sh: no LAMMPS source tarball could be fetched; name one with --lammps-tarball" >&2
  return 1
}

# Unpack into the build tree, so that ccache sees the same relative paths in every clone.
unpack_tarball() {
  local tarball=$1 dest="$build_dir/_deps/lammps" stamp
  stamp="$(basename "$tarball") $(stat -c %s "$tarball")"
  if [ -f "$dest/.mesophyll-stamp" ] && [ "$(cat "$dest/.mesophyll-stamp")" = "$stamp" ]; then
    echo "$dest"; return
  fi
  say "Unpacking $(basename "$tarball")" >&2
  rm -rf "$dest" "$dest.tmp"; mkdir -p "$dest.tmp"
  tar -xf "$tarball" -C "$dest.tmp"
  local top="$dest.tmp"
  if [ ! -d "$top/src" ]; then top=$(dirname "$(find "$dest.tmp" -maxdepth 2 -name src -type d | head -n 1)"); fi
  mv "$top" "$dest"; rm -rf "$dest.tmp"
  echo "$stamp" > "$dest/.mesophyll-stamp"
  echo "$dest"
}

[ "$install" = 1 ] && install_packages

if [ -n "$lammps_source" ]; then
  [ -f "$lammps_source/cmake/CMakeLists.txt" ] ||
    { echo "setup.sh: '$lammps_source' is not a LAMMPS source tree (no cmake/CMakeLists.txt)" >&2; exit 2; }
  lammps_dir=$(realpath "$lammps_source")
else
  if [ -n "$lammps_tarball" ]; then
    [ -f "$lammps_tarball" ] || { echo "setup.sh: tarball '$lammps_tarball' not found" >&2; exit 2; }
    tarball=$(realpath "$lammps_tarball")
  else
    tarball=$(find_or_fetch_tarball)
  fi
  lammps_dir=$(unpack_tarball "$tarball")
fi

# ccache: relative paths and no working directory in the hash, so a fresh clone hits the cache.
export CCACHE_BASEDIR="$here" CCACHE_NOHASHDIR=1
ccache --max-size=4G >/dev/null 2>&1 || true

# shared liblammps; the sanitizer builds stay static, as their leak checks were set up that way
shared=ON
[ "$sanitize" = ON ] && shared=OFF
if [ "$python_module" = 1 ] && [ "$shared" = OFF ]; then
  echo "setup.sh: --python needs the shared library, which sanitizer builds do not make" >&2; exit 2
fi

say "Configuring (LAMMPS in $lammps_dir, MPI $mpi, sanitizers $sanitize, shared library $shared)"
cmake -S "$here" -B "$build_dir" -G Ninja -DMESOPHYLL_LAMMPS_DIR="$lammps_dir" -DBUILD_MPI="$mpi" \
      -DMESOPHYLL_SANITIZE="$sanitize" -DMESOPHYLL_SANITIZE_LAMMPS="$sanitize_lammps" \
      -DBUILD_SHARED_LIBS="$shared" >/dev/null
say "Building"
cmake --build "$build_dir" --parallel "$(nproc)"
ccache --show-stats 2>/dev/null | grep -Ei 'hit|miss' | head -n 4 || true
echo "LAMMPS with MESOPHYLL: $build_dir/lmp"

# LAMMPS's Python package from its source tree into BUILD/venv, offline: pip builds it from a
# copy of python/ with the system's setuptools (--no-index --no-build-isolation), and its
# liblammps.so is a link to this build's, so a rebuild needs no reinstall. LAMMPS's own
# install.py would fetch pip, build and wheel from PyPI.
install_python_module() {
  local venv="$build_dir/venv" stage="$build_dir/python-package" site
  say "LAMMPS's Python module into $venv"
  [ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$venv"
  rm -rf "$stage"; cp -r "$lammps_dir/python" "$stage"
  (cd "$stage" && LAMMPS_VERSION_FILE="$lammps_dir/src/version.h" \
     "$venv/bin/python" -m pip install --quiet --no-index --no-build-isolation --no-deps \
     --force-reinstall .)
  rm -rf "$stage"
  site=$("$venv/bin/python" -c 'import lammps, os; print(os.path.dirname(lammps.__file__))')
  ln -sf "$build_dir/liblammps.so" "$site/liblammps.so"
  "$venv/bin/python" -c 'import lammps
lmp = lammps.lammps(cmdargs=["-nocite", "-log", "none", "-screen", "none"])
assert "MESOPHYLL" in lmp.installed_packages, lmp.installed_packages
print("lammps", lmp.version(), "with MESOPHYLL, from", lammps.__file__)
lmp.close()'
  echo "Python: $venv/bin/python examples/python/grow_tissue.py (or source $venv/bin/activate)"
}
[ "$python_module" = 1 ] && install_python_module

if [ "$run_example" = 1 ]; then
  if [ "$mpi" = ON ]; then
    "$here/tools/run-example.sh" --build-dir "$build_dir"
  else
    "$here/tools/run-example.sh" --build-dir "$build_dir" --np 1
  fi
fi
