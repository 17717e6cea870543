#!/usr/bin/env bash
# Builds tunnelmap_bench (Release, no GUI) in build-bench, runs every benchmark (per-frame ones
# on one thread; 5 repetitions, median) and regenerates the tables in docs/performance.md
# between <!-- bench:begin --> and <!-- bench:end -->. Takes ~4-5 min on the quiet 2-core
# machine, 8 min at load 8-10 (plus the build the first time). Raw JSON: out/bench.json.
# Usage: bash scripts/bench.sh [extra Google Benchmark flags, e.g. --benchmark_filter=Pcl]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${TUNNELMAP_BENCH_BUILD_DIR:-build-bench}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTUNNELMAP_BUILD_GUI=OFF >/dev/null
cmake --build "$BUILD_DIR" --target tunnelmap_bench -j 2 >/dev/null
mkdir -p out
# One thread everywhere: OpenMP (read by libgomp before main), OpenBLAS if PCL pulls it in;
# the binary itself calls cv::setNumThreads(1).
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
"$BUILD_DIR"/bench/tunnelmap_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
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
