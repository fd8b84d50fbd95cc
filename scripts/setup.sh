#!/usr/bin/env bash
# Installs the Debian packages this project needs (only those missing; idempotent) and unpacks
# CGAL's sample data (package libcgal-demo) into DATA_DIR (default build/data), so that
# $DATA_DIR/meshes/bull.off exists for the examples, the demo and the benchmarks.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DATA_DIR=${DATA_DIR:-$ROOT/build/data}

# doxygen, graphviz (the manual's diagrams) and libjs-mathjax (its formulas, offline) build the
# manual; python3 runs scripts/longest_functions.py (the ctest test function_length); clang and
# libclang-rt-dev (its sanitizer and libFuzzer runtimes) build the fuzzer (scripts/fuzz.sh). The
# Python package (python/) is built with pybind11 against Debian's Python, installed with its pip
# into a venv, and tested with its pytest; distributed is Dask's cluster.
PACKAGES=(build-essential cmake pkg-config libcgal-dev libcgal-demo libeigen3-dev libboost-dev
          libfftw3-dev libgtest-dev libbenchmark-dev doxygen graphviz libjs-mathjax python3 libtbb-dev
          libgmp-dev libmpfr-dev clang libclang-rt-dev
          python3-dev pybind11-dev python3-numpy python3-venv python3-pip python3-setuptools python3-wheel
          python3-pytest python3-distributed)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else echo "setup.sh: must run as root (or with sudo available) to run: $*" >&2; exit 1
  fi
}

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup.sh: installing ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -q
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if [ ! -f "$DATA_DIR/meshes/bull.off" ]; then
  tarball=""
  for t in /usr/share/doc/libcgal-dev/data.tar.gz /usr/share/doc/libcgal-demo/data.tar.gz; do
    if [ -f "$t" ]; then tarball=$t; break; fi
  done
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  if [ -z "$tarball" ]; then
    # Minimal images often tell dpkg not to install /usr/share/doc: take it from the .deb.
    echo "setup.sh: data.tar.gz not under /usr/share/doc, extracting it from libcgal-demo's .deb"
    (cd "$tmp" && apt-get download libcgal-demo >/dev/null) ||
      { as_root apt-get update -q && (cd "$tmp" && apt-get download libcgal-demo >/dev/null); }
    dpkg-deb --fsys-tarfile "$tmp"/libcgal-demo_*.deb | tar -x -C "$tmp" --wildcards '*/data.tar.gz'
    tarball=$(find "$tmp" -name data.tar.gz | head -n 1)
  fi
  # Unpack beside the destination, then move: an interrupted run leaves no half data dir.
  mkdir -p "$(dirname "$DATA_DIR")"
  part=$(mktemp -d "$DATA_DIR.partial.XXXXXX")
  tar -xzf "$tarball" -C "$part" --strip-components=1
  chmod 755 "$part"  # mktemp made it private
  rm -rf "$DATA_DIR"
  mv "$part" "$DATA_DIR"
  echo "setup.sh: CGAL sample data unpacked into $DATA_DIR"
fi
