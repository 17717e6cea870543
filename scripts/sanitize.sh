#!/usr/bin/env bash
# Sanitizer build: the default build (core, CLI, OpenNI2 driver, unit + integration + OpenNI2
# tests; GUI and bench off) compiled by clang with AddressSanitizer + UndefinedBehaviorSanitizer
# (LeakSanitizer included), then the whole CTest suite. Any finding fails the run with a stack
# trace. Usage: scripts/sanitize.sh [BUILD_DIR] (default build-asan in the checkout).
#   TUNNELMAP_SANITIZE_EXCLUDE=REGEX  ctest -E pattern (default below)
# Not run here, and why:
#   label memory / no_sanitize  RSS bounds (tests/allocation): ASan's shadow memory and quarantine
#                               inflate RSS by design (and the 1000-frame run takes ~6 min)
#   OpenNiTest.UnpluggingMidRecording...  counts frames of a 30 fps camera; an ASan reader is too
#                               slow to see every one (fails 11 vs 12 frames, timing, not memory)
# Not instrumented, and why:
#   the simulator's ray caster  (core/sim/tunnel_geometry.cpp, tunnel_simulator.cpp) computes
#                               every simulated pixel the tests map; at -O1 under ASan it took
#                               three quarters of this run. It is built -O2 with the standard
#                               library's bounds assertions, reads nothing from outside (its
#                               geometry is a range-checked configuration) and the fuzz targets
#                               never reach it.
# The soak test runs a short stream here (TUNNELMAP_SOAK_FRAMES, default 60 frames): its memory
# bound is meaningless under ASan, its leak and file-descriptor checks are not.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-asan}
start=$(date +%s)

san="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
# -O1 + line tables: stack traces with file:line at a fraction of -O2 -g's compile time.
cmake -S "$root" -B "$build" -G Ninja \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DCMAKE_C_FLAGS="$san" -DCMAKE_CXX_FLAGS="$san" \
  -DCMAKE_EXE_LINKER_FLAGS="$san" -DCMAKE_SHARED_LINKER_FLAGS="$san" -DCMAKE_MODULE_LINKER_FLAGS="$san" \
  -DTUNNELMAP_RAYCAST_COMPILE_OPTIONS="-O2;-fno-sanitize=address,undefined;-D_GLIBCXX_ASSERTIONS" \
  -DTUNNELMAP_BUILD_GUI=OFF -DTUNNELMAP_BUILD_BENCH=OFF -DTUNNELMAP_BUILD_TESTS=ON >/dev/null

# Also in force while building: gtest test discovery runs the test executables.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:check_initialization_order=1:strict_string_checks=1:print_summary=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:print_summary=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"

ninja -C "$build" -j 2
built=$(date +%s)

cd "$build"
# ctest starts the longest tests first only if it knows their times from an earlier run here; a
# fresh folder (CI) gets those measured under ASan, so the two slots do not end with one long
# test running alone and each shared fixture's maker starts before the tests that reuse it
# (tests/support/shared_fixture.h): the first test of each such suite is listed 1000 s above its
# time. Refresh the list from Testing/Temporary/CTestCostData.txt after a run when tests were
# added or got much faster or slower.
costs=Testing/Temporary/CTestCostData.txt
if [ ! -f "$costs" ]; then mkdir -p "$(dirname "$costs")" && cp "$root/scripts/sanitize-test-costs.txt" "$costs"; fi
exclude=${TUNNELMAP_SANITIZE_EXCLUDE-OpenNiTest.UnpluggingMidRecordingKeepsWhatWasRecorded}
TUNNELMAP_SOAK_FRAMES=${TUNNELMAP_SOAK_FRAMES:-60} \
  ctest --output-on-failure -j 2 -LE 'no_sanitize|memory' ${exclude:+-E "$exclude"}
end=$(date +%s)
echo "sanitize.sh: ASan+UBSan build $(( built - start )) s, tests $(( end - built )) s, total $(( end - start )) s"
