#!/usr/bin/env bash
# Same-run comparison with CAPE (Proença & Gao 2018), called by scripts/bench.sh; runs alone too.
# CAPE's timing harness lives outside the project (../shared/peers/cape beside the checkout,
# MIT, never copied here): it is built in BUILD_DIR/cape-peer. The bench frames are written as
# depth PNGs (tunnelmap_bench --export-frames), then 3 rounds alternate, on one pinned core:
# tunnelmap_bench --timed-runs 50 (TunnelMap's plane extraction by cells, the default, and on the
# pixel grid, full detection, OpenCV FALS + RgbdPlane incl. depthTo3d, PCL IINE + OMPS) and cape_bench
# (REPS=50) on each frame. Medians of the pooled 150 runs per frame and method go to
# docs/performance.md between <!-- cape:begin --> and <!-- cape:end -->; raw output in out/cape/.
# Usage: bash scripts/bench-cape.sh [BUILD_DIR [CPU [lock command...]]]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build-bench}
CPU=${2:-1}
LOCK=("${@:3}")
CAPE_DIR="$(cd .. && pwd)/shared/peers/cape"
if [[ ! -f "$CAPE_DIR/cape_bench.cpp" ]]; then
  echo "CAPE comparison skipped: no CAPE harness at $CAPE_DIR (docs/performance.md keeps its last table)"
  exit 0
fi
ROUNDS=${TUNNELMAP_CAPE_ROUNDS:-3}
REPS=${TUNNELMAP_CAPE_REPS:-50}
PIN=()
if command -v taskset >/dev/null; then PIN=(taskset -c "$CPU"); fi
"${LOCK[@]}" cmake -S "$CAPE_DIR" -B "$BUILD_DIR/cape-peer" -DCMAKE_BUILD_TYPE=Release >/dev/null
"${LOCK[@]}" cmake --build "$BUILD_DIR/cape-peer" -j 2 >/dev/null
rm -rf out/cape && mkdir -p out/cape
"$BUILD_DIR"/bench/tunnelmap_bench --export-frames out/cape/frames
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for r in $(seq 1 "$ROUNDS"); do
  "${PIN[@]}" "$BUILD_DIR"/bench/tunnelmap_bench --timed-runs "$REPS" > "out/cape/round$r-tunnelmap.txt"
  while IFS=$'\t' read -r name png fx fy cx cy; do
    DUMP_RAW=1 REPS=$REPS "${PIN[@]}" "$BUILD_DIR/cape-peer/cape_bench" "$png" "$fx" "$fy" "$cx" "$cy" \
      > "out/cape/round$r-cape-$name.txt"
  done < out/cape/frames/frames.tsv
done
python3 - "$CPU" "$ROUNDS" "$REPS" <<'PY'
import datetime, glob, os, re, statistics, sys
cpu, rounds, reps = sys.argv[1:4]
runs, planes = {}, {}
for path in sorted(glob.glob("out/cape/round*-tunnelmap.txt")):
    for line in open(path):
        if line.startswith("RAW|"):
            _, frame, method, n, values = line.rstrip("\n").split("|")
            runs.setdefault((frame, method), []).extend(float(v) for v in values.split())
            planes[(frame, method)] = n
for path in sorted(glob.glob("out/cape/round*-cape-*.txt")):
    frame = re.match(r".*round\d+-cape-(.*)\.txt", path).group(1)
    for line in open(path):
        if line.startswith("  RAW|total"):
            runs.setdefault((frame, "cape"), []).extend(float(v) for v in line.split("|")[2].split())
        m = re.search(r"planes=(\d+)", line)
        if m:
            planes[(frame, "cape")] = m.group(1)
frames = [l.split("\t")[0] for l in open("out/cape/frames/frames.tsv")]
med = lambda f, m: statistics.median(runs[(f, m)])
load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
out = [f"Measured {datetime.datetime.now(datetime.timezone.utc).isoformat(timespec='seconds')} by "
       f"scripts/bench-cape.sh, pinned to CPU {cpu} (taskset), load average {load}; median wall ms "
       f"of {rounds} alternating rounds x {reps} runs per frame and method (warm-up runs dropped); "
       "(N planes) in brackets.", "",
       "| frame | TunnelMap plane extraction | CAPE | TunnelMap / CAPE | TunnelMap detection, / CAPE | "
       "pixel grid (grow.cell_px=0), / CAPE | OpenCV FALS + RgbdPlane incl. depthTo3d | PCL IINE + OMPS |",
       "|---|---|---|---|---|---|---|---|"]
for f in frames:
    tm, grid, cape = med(f, "tunnelmap"), med(f, "tunnelmap-pixel-grid"), med(f, "cape")
    detection = med(f, "tunnelmap-detection")
    out.append(f"| {f} | {tm:.2f} ({planes[(f, 'tunnelmap')]}) | {cape:.2f} ({planes[(f, 'cape')]}) | "
               f"{tm / cape:.2f}× | {detection:.2f} ms, {detection / cape:.2f}× | "
               f"{grid:.2f} ({planes[(f, 'tunnelmap-pixel-grid')]}), {grid / cape:.2f}× | "
               f"{med(f, 'opencv'):.2f} ({planes[(f, 'opencv')]}) | "
               f"{med(f, 'pcl'):.2f} ({planes[(f, 'pcl')]}) |")
table = "\n".join(out) + "\n"
open("out/cape/table.md", "w").write(table)
doc = open("docs/performance.md").read()
doc, n = re.subn(r"<!-- cape:begin -->.*<!-- cape:end -->",
                 lambda _: "<!-- cape:begin -->\n" + table + "<!-- cape:end -->", doc, flags=re.S)
if n != 1:
    raise SystemExit("docs/performance.md: no <!-- cape:begin --> ... <!-- cape:end --> block")
tmp = "docs/performance.md.tmp"
open(tmp, "w").write(doc)
os.replace(tmp, "docs/performance.md")
print(table, end="")
PY
