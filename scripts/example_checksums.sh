#!/usr/bin/env bash
# Runs the examples and demo programs as ctest does (on CGAL's sample data, grid 32: ctest -L example)
# in a build folder and prints the MD5 checksum of every file they write, one "checksum  file" line
# per file (relative to the build folder), sorted: the PLY files of the demo programs
# (demo/Symmetry_transform/) and the meshes the examples write (examples/Symmetry_transform/).
# Two builds (two revisions) write the same results when their lists are equal:
#   diff <(scripts/example_checksums.sh build-old) <(scripts/example_checksums.sh build)
#
# usage: scripts/example_checksums.sh [BUILD (default build)]
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
cd "$BUILD"
shopt -s nullglob
outputs() { echo demo/Symmetry_transform/*.ply examples/Symmetry_transform/*.off; }
# shellcheck disable=SC2046 # the file names have no spaces
rm -f -- $(outputs)
ctest --test-dir "$BUILD" -L example --output-on-failure >&2
files=$(outputs)
[ -n "$files" ] || { echo "no output files in $BUILD" >&2; exit 1; }
# shellcheck disable=SC2086
md5sum -- $files | sort -k 2
