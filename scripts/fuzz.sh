#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan; only the readers they link) and runs each
# for FUZZ_SECONDS (default 60) from the seed corpora in tests/fuzz/corpus/<target>/, two at a
# time (FUZZ_PARALLEL). Usage: scripts/fuzz.sh [BUILD_DIR]   (default: build-fuzz, gitignored)
# Prints one line per target (executions, exit status); exits 1 on any finding, whose input is
# kept as BUILD_DIR/findings/<target>/crash-* (or leak-, timeout-, oom-): reproduce it with
#   BUILD_DIR/tests/fuzz/fuzz_<target> FILE
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=$(realpath -m "${1:-$root/build-fuzz}")
seconds=${FUZZ_SECONDS:-60}
# A fixed FUZZ_SEED makes a run repeatable (CI sets one); unset, libFuzzer picks a new seed.
seed_flag=()
[ -n "${FUZZ_SEED:-}" ] && seed_flag=("-seed=$FUZZ_SEED")
parallel=${FUZZ_PARALLEL:-2}
start=$(date +%s)

mkdir -p "$build"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DTUNNELMAP_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "${FUZZ_JOBS:-2}"
built=$(date +%s)
echo "fuzz.sh: build took $((built - start)) s; fuzzing each target for ${seconds} s"

# Longest input per target: a little above the largest seed, small enough to stay fast.
declare -A max_len=([dataset_json]=4096 [preset_json]=2048 [depth_png]=16384 [pcd]=8192 [ply]=8192 [tum_list]=4096
                   [mcap_records]=8192 [ros1_records]=8192 [cdr_messages]=4096 [oni_container]=8192 [json_depth]=4096)
targets=(dataset_json preset_json depth_png pcd ply tum_list mcap_records ros1_records cdr_messages oni_container json_depth)

run_one() {
  local t=$1 work="$build/fuzz-work/$1" findings="$build/findings/$1" log="$build/fuzz-$1.log"
  # Scratch files for targets whose reader needs a path: in RAM if possible (writes to disk
  # cut PCD and dataset executions 30-fold), removed afterwards even if the target crashed.
  local scratch="$build/fuzz-scratch/$1"
  [ -d /dev/shm ] && [ -w /dev/shm ] && scratch="/dev/shm/tunnelmap-fuzz-$$-$1"
  rm -rf "$work" "$findings" "$scratch"
  mkdir -p "$work" "$findings" "$scratch"
  local rc=0
  # A keyword dictionary where there is one (tests/fuzz/<target>.dict) reaches header paths sooner.
  local dict=()
  [ -f "$root/tests/fuzz/$1.dict" ] && dict=("-dict=$root/tests/fuzz/$1.dict")
  # New inputs go to the work dir (first corpus dir); the committed seeds stay untouched.
  TUNNELMAP_FUZZ_SCRATCH="$scratch" ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/tests/fuzz/fuzz_$t" "$work" "$root/tests/fuzz/corpus/$t" \
    -max_total_time="$seconds" -max_len="${max_len[$t]}" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$findings/" -print_final_stats=1 "${seed_flag[@]}" "${dict[@]}" >"$log" 2>&1 || rc=$?
  echo "$rc" >"$log.rc"
  rm -rf "$scratch"
}

for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  run_one "$t" &
done
wait

status=0
for t in "${targets[@]}"; do
  log="$build/fuzz-$t.log"
  rc=$(cat "$log.rc")
  execs=$(grep -aoE 'stat::number_of_executed_(runs|units): *[0-9]+' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  finding=$(find "$build/findings/$t" -type f | head -1)
  if [ "$rc" -ne 0 ] || [ -n "$finding" ]; then
    status=1
    echo "fuzz $t: FINDING (exit $rc) after ${execs:-?} executions: ${finding:-see $log}"
    grep -a -m1 -E 'ERROR: |runtime error|deadly signal|out-of-memory|timeout' "$log" || true
    # The findings folder does not outlive a CI machine: print the input so it can be rebuilt
    # with  base64 -d > crash  and replayed.
    [ -n "$finding" ] && echo "fuzz $t: input (base64): $(head -c 8192 "$finding" | base64 -w0)"
  else
    echo "fuzz $t: ok, ${execs:-?} executions in ${seconds} s, exit 0"
  fi
done
echo "fuzz.sh: finished in $(( $(date +%s) - start )) s (build $((built - start)) s)"
exit "$status"
