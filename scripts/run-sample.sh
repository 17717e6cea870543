#!/usr/bin/env bash
# Fresh machine -> the main job on the bundled sample: installs dependencies, builds, detects
# the tunnel in resources/sample/lab and writes out/sample.json and out/sample_map.ply.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Only the command-line tool: the tests, benchmarks and GUI are built by scripts/test.sh.
TUNNELMAP_BUILD_TARGETS=tunnelmap-cli bash scripts/build.sh
mkdir -p out
./build/app/tunnelmap-cli detect resources/sample/lab --params resources/presets/lab.json \
  --json out/sample.json --ply out/sample_map.ply
echo "results: out/sample.json, tunnel map: out/sample_map.ply"
