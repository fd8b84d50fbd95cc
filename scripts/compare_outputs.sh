#!/usr/bin/env bash
# Checks that a change of the library leaves its results bit-identical: builds
# test/Symmetry_transform/output_fingerprint.cpp (every public result on one mesh, exact
# hexadecimal values and hashes of arrays) against the headers of BASE and of the working tree,
# with the same compiler flags, runs both on MESH and compares the two fingerprints.
#
# usage: scripts/compare_outputs.sh [BASE (default HEAD)] [MESH (default build/data/meshes/bull.off)] [RESOLUTION (32)]
# exit 0 when identical; prints the differing lines otherwise.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BASE=${1:-HEAD}
MESH=${2:-$ROOT/build/data/meshes/bull.off}
RESOLUTION=${3:-32}
WORK=${COMPARE_DIR:-$ROOT/build/compare}
SOURCE=$ROOT/test/Symmetry_transform/output_fingerprint.cpp

[ -f "$MESH" ] || { echo "compare_outputs.sh: no mesh $MESH (run scripts/setup.sh)" >&2; exit 2; }
mkdir -p "$WORK"
SHA=$(git -C "$ROOT" rev-parse "$BASE")
BASE_OUT=$WORK/base-$SHA-$(basename "$MESH")-$RESOLUTION.txt

# The same flags as the Release build of the project (CMakeLists.txt, CGAL's own).
build() { # build TREE OUTPUT
  local override
  override=$(find "$1/include" -type d -name parameters_override | head -n 1)
  g++ -std=c++17 -O3 -DNDEBUG -frounding-math -DCGAL_EIGEN3_ENABLED -DCGAL_USE_GMPXX=1 \
      -I"$override" -I"$1/include" -isystem /usr/include/eigen3 "$SOURCE" -o "$2" \
      $(pkg-config --cflags --libs fftw3) -lgmpxx -lmpfr -lgmp -pthread
}
pids=()
if [ ! -f "$BASE_OUT" ]; then # the base's fingerprint is kept: a base is built once
  rm -rf "$WORK/base"
  git -C "$ROOT" worktree prune
  git -C "$ROOT" worktree add --detach "$WORK/base" "$SHA" >/dev/null
  build "$WORK/base" "$WORK/fingerprint_base" & pids+=($!)
fi
build "$ROOT" "$WORK/fingerprint_head" & pids+=($!)
for p in "${pids[@]}"; do wait "$p"; done
if [ ! -f "$BASE_OUT" ]; then
  git -C "$ROOT" worktree remove --force "$WORK/base"
  "$WORK/fingerprint_base" "$MESH" "$RESOLUTION" > "$BASE_OUT.partial" && mv "$BASE_OUT.partial" "$BASE_OUT"
fi
"$WORK/fingerprint_head" "$MESH" "$RESOLUTION" > "$WORK/head.txt"
if diff "$BASE_OUT" "$WORK/head.txt"; then
  echo "compare_outputs.sh: identical results ($(wc -l < "$WORK/head.txt") lines; $BASE vs working tree; $(basename "$MESH"), grid $RESOLUTION)"
else
  echo "compare_outputs.sh: results differ ($BASE vs working tree; $(basename "$MESH"), grid $RESOLUTION)" >&2
  exit 1
fi
