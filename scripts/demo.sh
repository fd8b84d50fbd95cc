#!/usr/bin/env bash
# Builds the main demo program (Release) and runs it on CGAL's bull.off; extra arguments are
# passed to the program. Output files land in build/demo/ (the program itself is built in
# build/demo/Symmetry_transform/, from demo/Symmetry_transform/).
set -euo pipefail
DEMO=principal_symmetries   # the demo program (one of demo/Symmetry_transform)

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
(cd "$OUT" && "$BUILD/demo/Symmetry_transform/$DEMO" "$BUILD/data/meshes/bull.off" "${args[@]}")
echo
echo "Output files in $OUT:"
find "$OUT" -maxdepth 1 -type f -exec ls -l {} + | sort -k 9
