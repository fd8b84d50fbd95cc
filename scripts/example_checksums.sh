#!/usr/bin/env bash
# Runs the examples as ctest does (on bull.off, grid 32: ctest -L example) in a build folder and
# prints the MD5 checksum of every file they write, one "checksum  file" line per file, sorted.
# Two builds (two revisions) write the same results when their lists are equal:
#   diff <(scripts/example_checksums.sh build-old) <(scripts/example_checksums.sh build)
#
# usage: scripts/example_checksums.sh [BUILD (default build)]
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${1:-$ROOT/build}
OUT=$BUILD/examples/Symmetry_transform
rm -f "$OUT"/*.ply
ctest --test-dir "$BUILD" -L example --output-on-failure >&2
(cd "$OUT" && md5sum -- *.ply | sort -k 2)
