#!/usr/bin/env bash
# The whole package against another CGAL than Debian's (e.g. a release of CGAL 6):
#   bash scripts/check_cgal_version.sh CGAL_DIR [BUILD_DIR]
# CGAL_DIR: the folder of a CGAL release (e.g. `git archive CGAL-6.1.1` of CGAL's release
# repository, without data/, demo/, doc_html/ and examples/), or of its CGALConfig.cmake.
# Builds every target (library, tests, examples, benchmarks) in BUILD_DIR (default
# build-cgal-<version>) with CGAL_NO_DEPRECATED_CODE, so that a deprecated CGAL header or name is
# an error; lists the compiler warnings that point into the package; runs every test. Exits with
# 1 if a target does not build, a warning points into the package, or a test fails.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ $# -lt 1 ] || [ ! -d "$1" ]; then
  echo "usage: bash scripts/check_cgal_version.sh CGAL_DIR [BUILD_DIR]" >&2
  exit 2
fi
CGAL_DIR=$(cd "$1" && pwd)
# The version of the nearest include/CGAL/version.h at or above CGAL_DIR (a release folder, or
# the folder of an installed CGALConfig.cmake such as Debian's /usr/lib/x86_64-linux-gnu/cmake/CGAL).
VERSION_FILE=""
dir=$CGAL_DIR
while [ -z "$VERSION_FILE" ] && [ "$dir" != / ]; do
  [ -f "$dir/include/CGAL/version.h" ] && VERSION_FILE=$dir/include/CGAL/version.h
  dir=$(dirname "$dir")
done
[ -n "$VERSION_FILE" ] || { echo "check_cgal_version.sh: no include/CGAL/version.h at or above $CGAL_DIR" >&2; exit 2; }
VERSION=$(sed -n 's/^#define CGAL_VERSION \([0-9.]*\).*/\1/p' "$VERSION_FILE")
BUILD=${2:-$ROOT/build-cgal-$VERSION}
JOBS=$(nproc)
echo "CGAL $VERSION ($CGAL_DIR), build in $BUILD"

DATA_DIR=$ROOT/build/data bash "$ROOT/scripts/setup.sh"
mkdir -p "$BUILD"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCGAL_DIR="$CGAL_DIR" \
  -DCMAKE_CXX_FLAGS="-DCGAL_NO_DEPRECATED_CODE" \
  -DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=ON -DSYMMETRY_TRANSFORM_BUILD_TESTS=ON \
  -DSYMMETRY_TRANSFORM_BUILD_BENCHMARKS=ON -DSYMMETRY_TRANSFORM_BUILD_DOC=OFF \
  -DSYMMETRY_TRANSFORM_DATA_DIR="$ROOT/build/data" > "$BUILD/check_configure.log"
status=0
cmake --build "$BUILD" -j "$JOBS" -- -k > "$BUILD/check_build.log" 2>&1 || status=1
# Warnings and errors whose location is a file of the package (not CGAL's, Boost's or Eigen's).
grep -E "^$ROOT/[^:]+:[0-9]+:[0-9]+: (warning|error)" "$BUILD/check_build.log" | sort -u > "$BUILD/check_diagnostics.log" || true
if [ -s "$BUILD/check_diagnostics.log" ]; then
  echo "diagnostics in the package's files ($(wc -l < "$BUILD/check_diagnostics.log")):"
  head -n 20 "$BUILD/check_diagnostics.log"
  status=1
fi
if [ $status -ne 0 ]; then
  echo "build: FAILED (see $BUILD/check_build.log)"
else
  echo "build: every target, no warning from the package"
fi
ctest --test-dir "$BUILD" -j "$JOBS" > "$BUILD/check_ctest.log" 2>&1 || status=1
grep -E "tests passed|tests failed|^\s+[0-9]+ - " "$BUILD/check_ctest.log" || true
exit $status
