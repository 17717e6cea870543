#!/usr/bin/env bash
# Runs the benchmarks (Release build) and regenerates the table in docs/performance.md.
# Usage: bash scripts/bench.sh [extra Google Benchmark flags]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
mkdir -p out
./build/bench/tunnelmap_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_format=json --benchmark_out=out/bench.json --benchmark_out_format=json "$@" >/dev/null
python3 scripts/bench-table.py out/bench.json > out/bench-table.md
python3 - <<'PY'
import re
doc = open("docs/performance.md").read()
table = open("out/bench-table.md").read()
doc = re.sub(r"<!-- bench:begin -->.*<!-- bench:end -->",
             "<!-- bench:begin -->\n" + table + "<!-- bench:end -->", doc, flags=re.S)
open("docs/performance.md", "w").write(doc)
PY
echo "updated docs/performance.md"
