#!/usr/bin/env bash
# Builds the libFuzzer target test/Symmetry_transform/fuzz with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (-O1, assertions on) in its own tree, build-fuzz/, and runs its ctest
# test (label fuzz): the fuzzer starts from seeds written at test time and must exit 0 after
# FUZZ_SECONDS (default 60) seconds. A crashing input is left in build-fuzz/test/Symmetry_transform/fuzz/.
# Where clang++ or its fuzzer runtime (Debian: clang, libclang-rt-dev; scripts/setup.sh installs
# them) is missing, says so and exits 0.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${FUZZ_BUILD:-$ROOT/build-fuzz}
FUZZ_CXX=${FUZZ_CXX:-clang++}
FUZZ_SECONDS=${FUZZ_SECONDS:-60}
JOBS=${JOBS:-$(nproc)}

probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/probe.cpp"
if ! command -v "$FUZZ_CXX" >/dev/null ||
   ! "$FUZZ_CXX" -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" 2>/dev/null; then
  echo "fuzz.sh: $FUZZ_CXX with the libFuzzer runtime is not available: the fuzzer is not run" >&2
  exit 0
fi

cmake -S "$ROOT" -B "$BUILD" -DCMAKE_CXX_COMPILER="$FUZZ_CXX" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=OFF -DSYMMETRY_TRANSFORM_BUILD_TESTS=OFF \
  -DSYMMETRY_TRANSFORM_BUILD_DOC=OFF -DSYMMETRY_TRANSFORM_BUILD_BENCHMARKS=OFF \
  -DSYMMETRY_TRANSFORM_BUILD_FUZZERS=ON -DSYMMETRY_TRANSFORM_FUZZ_SECONDS="$FUZZ_SECONDS"
cmake --build "$BUILD" -j "$JOBS"
ctest --test-dir "$BUILD" -L fuzz --output-on-failure
