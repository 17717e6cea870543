#!/usr/bin/env bash
# Fresh machine -> every test: installs dependencies, builds (Release), runs the whole CTest
# suite (unit, integration, CLI, rendering and GUI tests; GUI tests get a virtual X display).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
# GUI tests need an X server; everything else runs headless.
if command -v xvfb-run >/dev/null 2>&1 && [ -z "${DISPLAY:-}" ]; then
  xvfb-run -a -s "-screen 0 1920x1080x24" ctest --output-on-failure -j 2
else
  ctest --output-on-failure -j 2
fi
# The Debian package is built, installed, used and removed in CI (it needs root and changes
# the system, so a developer opts in with TUNNELMAP_PACKAGE_TEST=1).
if [ "${CI:-}" = "true" ] || [ "${TUNNELMAP_PACKAGE_TEST:-}" = "1" ]; then
  if [ "$(id -u)" -eq 0 ]; then bash ../scripts/package-test.sh; else echo "package test skipped: needs root"; fi
fi
# Hardening jobs, in CI or on request (TUNNELMAP_HARDENING=1): the unit and
# integration tests again under AddressSanitizer + UndefinedBehaviorSanitizer (clang), then
# every libFuzzer target for about a minute from its seed corpus. Both fail on any finding.
if [ "${CI:-}" = "true" ] || [ "${TUNNELMAP_HARDENING:-}" = "1" ]; then
  cd ..
  bash scripts/sanitize.sh
  # A fixed seed: the same commit fuzzes the same inputs first, so a finding reproduces.
  FUZZ_SECONDS=${FUZZ_SECONDS:-60} FUZZ_SEED=${FUZZ_SEED:-20261122} bash scripts/fuzz.sh
  cd build
fi
echo "test.sh: finished in $(( $(date +%s) - start )) s"
