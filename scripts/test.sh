#!/usr/bin/env bash
# Installs what is missing, builds everything (Release) in build/ and runs all tests (ctest, then
# the Python package's pytest), then builds the fuzzer with clang in build-fuzz/ and runs it for
# FUZZ_SECONDS (default 60; scripts/fuzz.sh).
# BENCHMARKS=1 also builds the benchmark programs (they are not run here).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=$ROOT/build
JOBS=$(nproc)
# Tests run in parallel too; CTEST_JOBS=1 if transforms that use every core slow each other down.
CTEST_JOBS=${CTEST_JOBS:-$JOBS}

DATA_DIR=$BUILD/data bash "$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
  -DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=ON -DSYMMETRY_TRANSFORM_BUILD_TESTS=ON \
  -DSYMMETRY_TRANSFORM_BUILD_DOC=ON \
  -DSYMMETRY_TRANSFORM_BUILD_BENCHMARKS="$([ "${BENCHMARKS:-0}" = 1 ] && echo ON || echo OFF)" \
  -DSYMMETRY_TRANSFORM_DATA_DIR="$BUILD/data"
cmake --build "$BUILD" -j "$JOBS"
ctest --test-dir "$BUILD" --output-on-failure -j "$CTEST_JOBS"
# The Python package, installed from this checkout into a venv of Debian's Python (the first
# python3 on PATH may be another, without Debian's numpy and distributed), then its tests, which
# compare with the C++ programs just built. -P: the package is imported from the venv, not the tree.
VENV=$BUILD/python-venv
[ -x "$VENV/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$VENV"
CMAKE_BUILD_PARALLEL_LEVEL=$JOBS "$VENV/bin/pip" install --no-build-isolation --quiet "$ROOT/python"
SYMMETRY_TRANSFORM_BUILD_DIR=$BUILD "$VENV/bin/python" -P -m pytest -q -p no:cacheprovider "$ROOT/python/tests"
JOBS=$JOBS bash "$ROOT/scripts/fuzz.sh"
