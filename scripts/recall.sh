#!/usr/bin/env bash
# Builds tunnelmap_plane_recall (Release, no GUI) in build-bench and regenerates docs/recall.md:
# plane recall / precision on simulated lab and field frames (4 seeds x 30 frames,
# grid steps 1 and 2) with a breakdown of the missed surfaces. Takes ~1 min on the
# 2-core machine at load 3 (plus the build the first time); the frames run on one thread.
# Usage: bash scripts/recall.sh [more tunnelmap_plane_recall options, e.g. --csv out/recall.csv]
# Another build directory (e.g. while scripts/bench.sh uses build-bench):
#   TUNNELMAP_BENCH_BUILD_DIR=build-recall bash scripts/recall.sh
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${TUNNELMAP_BENCH_BUILD_DIR:-build-bench}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTUNNELMAP_BUILD_GUI=OFF >/dev/null
cmake --build "$BUILD_DIR" --target tunnelmap_plane_recall -j 2 >/dev/null
mkdir -p out  # for --csv out/...
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
"$BUILD_DIR"/bench/tunnelmap_plane_recall --markdown docs/recall.md "$@" >/dev/null
echo "updated docs/recall.md"
