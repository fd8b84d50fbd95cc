#!/usr/bin/env bash
# Builds the examples (Release) and runs the main demo on CGAL's bull.off; extra arguments
# are passed to the program. Output files land in build/demo/.
set -euo pipefail
DEMO=principal_symmetries   # the demo program (an example of examples/Symmetry_transform)

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=$ROOT/build
OUT=$BUILD/demo

DATA_DIR=$BUILD/data bash "$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSYMMETRY_TRANSFORM_BUILD_EXAMPLES=ON \
  -DSYMMETRY_TRANSFORM_DATA_DIR="$BUILD/data" >/dev/null
cmake --build "$BUILD" -j "$(nproc)" --target "$DEMO"
mkdir -p "$OUT"
args=("$@")
case " $* " in *" --output "*) ;; *) args+=(--output "$OUT/${DEMO}_bull.ply") ;; esac
# Run from the output directory so that files the program writes by default land there too.
(cd "$OUT" && "$BUILD/examples/Symmetry_transform/$DEMO" "$BUILD/data/meshes/bull.off" "${args[@]}")
echo
echo "Output files in $OUT:"
ls -l "$OUT"
