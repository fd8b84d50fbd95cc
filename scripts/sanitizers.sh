#!/usr/bin/env bash
# Builds the tests and examples with AddressSanitizer and UndefinedBehaviorSanitizer in build-asan/
# and runs every ctest test there; any report fails the test that raised it.
# -O1 without -g: the reports still name functions, and the build is several times cheaper than -O2 -g.
# JOBS (default: the core count) bounds the build; the run takes hours on 2 cores, so CI does not call it.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${BUILD:-$ROOT/build-asan}
JOBS=${JOBS:-$(nproc)}
SANITIZER_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"

DATA_DIR=$BUILD/data bash "$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="-O1 $SANITIZER_FLAGS" \
  -DCMAKE_EXE_LINKER_FLAGS="$SANITIZER_FLAGS" \
  -DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=ON -DSYMMETRY_TRANSFORM_BUILD_TESTS=ON \
  -DSYMMETRY_TRANSFORM_DATA_DIR="$BUILD/data"
cmake --build "$BUILD" -j "$JOBS"
# The leak checker needs ptrace, which some containers deny; leaks are then not reported.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS" --timeout 7200
