#!/usr/bin/env bash
# Fuzzes every reader of the tool (tests/fuzz/fuzz_targets.h) with libFuzzer, AddressSanitizer
# and UndefinedBehaviorSanitizer: builds the fuzz programs with clang into their own build
# folder, seeds them from fixtures/, runs each for SECONDS, and prints one line per target
# (executions, corpus size, result). Exits 1 when any target found a crash, leak, timeout or
# out-of-memory; the input that did it is left in <build>/fuzz-findings/<target>/. Keep it as
# a regression fixture under tests/fuzz/regressions/<target>/ once fixed.
#
# Usage: bash tools/fuzz.sh [SECONDS]        (default 60 per target)
# Environment:
#   MOCAPFILL_FUZZ_BUILD    build folder (default build-fuzz); a folder already configured
#                           with MOCAPFILL_FUZZ=ON (the CI's sanitizer build) is reused as is
#   MOCAPFILL_FUZZ_TARGETS  targets to run (default: all), e.g. "bvh gltf"
#   MOCAPFILL_FUZZ_JOBS     targets run at once (default: the number of cores)
set -euo pipefail
seconds=${1:-60}
if ! [[ $seconds =~ ^[0-9]+$ ]] || ((seconds == 0)); then
  echo "usage: bash tools/fuzz.sh [SECONDS]   (a positive whole number; got '$seconds')" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MOCAPFILL_FUZZ_BUILD:-$root/build-fuzz}
targets=${MOCAPFILL_FUZZ_TARGETS:-bvh gltf mfdb pca pipeline maps fbx wire}
jobs=${MOCAPFILL_FUZZ_JOBS:-$(nproc)}

bash "$root/tools/install_deps.sh" --fuzz
if ! grep -q '^MOCAPFILL_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
    -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" -DMOCAPFILL_SANITIZE=ON -DMOCAPFILL_FUZZ=ON -DMOCAPFILL_UNITY_BUILD=ON >/dev/null
fi
cmake --build "$build" -j "$(nproc)" --target fuzzers mocapfill_full

# Seeds: the fixtures of each format and, when ../shared/data is there, its files of those
# formats; a database and a PCA model built from a fixture clip; a few maps. Files over 64 KiB
# are left out (libFuzzer mutates best around small inputs).
seeds=$build/fuzz-seeds
rm -rf "$seeds"
for t in bvh gltf mfdb pca pipeline maps fbx wire; do mkdir -p "$seeds/$t"; done
shared_data=$root/../shared/data
copy_small() {  # copy_small <target> <find name patterns...>   (pipelines: the fixtures' only)
  local target=$1 from=("$root/fixtures")
  shift
  [ -d "$shared_data" ] && [ "$target" != pipeline ] && from+=("$shared_data")
  find "${from[@]}" -type f \( "$@" \) -size -64k -print0 | while IFS= read -r -d '' f; do
    cp "$f" "$seeds/$target/$(basename "$(dirname "$f")")_$(basename "$f")"
  done
}
copy_small bvh -name '*.bvh'
copy_small gltf -name '*.gltf' -o -name '*.glb'
copy_small pipeline -name '*.json'
copy_small fbx -name '*.fbx'
full=$build/converter/mocapfill-full
export ASAN_OPTIONS=detect_leaks=0
"$full" db build "$root/fixtures/bvh/bandai_walk_normal_001_short.bvh" -o "$seeds/mfdb/walk.mfdb" >/dev/null
"$full" pca build --db "$seeds/mfdb/walk.mfdb" -o "$seeds/pca/walk.pca" >/dev/null
unset ASAN_OPTIONS
printf '{"LHipJoint": "UpperLeg_L", "RHipJoint": "UpperLeg_R"}' >"$seeds/maps/joint_names.json"
printf '{"LeftUpLeg": "leftUpperLeg", "Spine1": "", "Neck1": null}' >"$seeds/maps/rig_map.json"
printf '{}' >"$seeds/maps/empty.json"
printf 'patch' >"$seeds/wire/patch.bin"  # the wire target patches a valid answer of its own

# One run per target, JOBS at a time; each writes its log, the summary is printed at the end.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
run_target() {
  local t=$1 corpus=$build/fuzz-corpus/$1 findings=$build/fuzz-findings/$1
  mkdir -p "$corpus" "$findings"
  local dict=()
  [ -f "$root/tests/fuzz/dict/$t.dict" ] && dict=(-dict="$root/tests/fuzz/dict/$t.dict")
  set +e
  "$build/tests/fuzz_$t" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$findings/" "${dict[@]}" "$corpus" "$seeds/$t" >"$build/fuzz-$t.log" 2>&1
  echo $? >"$build/fuzz-$t.status"
}
export -f run_target
export build seeds seconds root
echo "fuzzing $targets for $seconds s each, $jobs at a time (logs: $build/fuzz-<target>.log)"
printf '%s\n' $targets | xargs -P "$jobs" -I{} bash -c 'run_target {}'

failed=0
total=0
printf '%-9s %12s %8s  %s\n' target executions corpus result
for t in $targets; do
  log=$build/fuzz-$t.log
  status=$(cat "$build/fuzz-$t.status")
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  corpus=$(find "$build/fuzz-corpus/$t" -type f | wc -l)
  result=ok
  if [ "$status" != 0 ]; then
    failed=1
    result="FAILED (exit $status): $(grep -m1 -oE 'ERROR: [^ ]+: [^(]*|ERROR: libFuzzer: [a-z-]+' "$log" || echo 'see log')"
    result+="; input in $build/fuzz-findings/$t/"
  fi
  total=$((total + ${execs:-0}))
  printf '%-9s %12s %8s  %s\n' "$t" "${execs:-?}" "$corpus" "$result"
done
echo "total executions: $total"
exit $failed
