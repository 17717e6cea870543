#!/usr/bin/env bash
# Builds tunnelmap_bench (Release, no GUI) in build-bench, runs every benchmark (per-frame ones
# on one thread pinned to one core, `taskset -c $TUNNELMAP_BENCH_CPU`, default 1; 5 repetitions,
# median) and regenerates the tables in docs/performance.md between <!-- bench:begin --> and
# <!-- bench:end -->. Takes ~4-5 min on the quiet 2-core machine, 8 min at load 8-10 (plus the
# build the first time). Raw JSON: out/bench.json.
# When CAPE's timing harness is beside the checkout (../shared/peers/cape), it is built in
# $BUILD_DIR/cape-peer and timed on the same frames on the same core, alternating with
# TunnelMap's plane extraction (3 rounds x 50 runs each, pooled medians); the table goes between
# <!-- cape:begin --> and <!-- cape:end -->. Without it that table is skipped with a message.
# Usage: bash scripts/bench.sh [extra Google Benchmark flags, e.g. --benchmark_filter=Pcl]
# TUNNELMAP_BENCH_BUILD_DIR=DIR uses an existing build folder as it is configured (no
# reconfigure); TUNNELMAP_BUILD_LOCK=FILE builds under `flock FILE` (a shared machine's lock).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${TUNNELMAP_BENCH_BUILD_DIR:-build-bench}
CPU=${TUNNELMAP_BENCH_CPU:-1}
LOCK=()
if [[ -n "${TUNNELMAP_BUILD_LOCK:-}" ]]; then LOCK=(flock "$TUNNELMAP_BUILD_LOCK"); fi
# Configure only our own default folder: a folder named by the caller keeps its configuration.
if [[ -z "${TUNNELMAP_BENCH_BUILD_DIR:-}" || ! -f "$BUILD_DIR/CMakeCache.txt" ]]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTUNNELMAP_BUILD_GUI=OFF >/dev/null
fi
"${LOCK[@]}" cmake --build "$BUILD_DIR" --target tunnelmap_bench -j 2 >/dev/null
BENCH=("$BUILD_DIR"/bench/tunnelmap_bench)
if command -v taskset >/dev/null; then BENCH=(taskset -c "$CPU" "${BENCH[@]}"); fi
mkdir -p out
# One thread everywhere: OpenMP (read by libgomp before main), OpenBLAS if PCL pulls it in;
# the binary itself calls cv::setNumThreads(1).
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
"${BENCH[@]}" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_min_time=0.2 --benchmark_out=out/bench.json --benchmark_out_format=json "$@" >/dev/null
python3 scripts/bench-table.py out/bench.json > out/bench-table.md
python3 - <<'PY'
import re
doc = open("docs/performance.md").read()
table = open("out/bench-table.md").read()
doc, n = re.subn(r"<!-- bench:begin -->.*<!-- bench:end -->",
                 lambda _: "<!-- bench:begin -->\n" + table + "<!-- bench:end -->", doc, flags=re.S)
if n != 1:
    raise SystemExit("docs/performance.md: no <!-- bench:begin --> ... <!-- bench:end --> block")
tmp = "docs/performance.md.tmp"
open(tmp, "w").write(doc)
import os
os.replace(tmp, "docs/performance.md")
PY
echo "updated docs/performance.md (raw results: out/bench.json)"
bash scripts/bench-cape.sh "$BUILD_DIR" "$CPU" "${LOCK[@]}"
