#!/usr/bin/env bash
# The test command: installs dependencies, builds with warnings as errors, runs the tests
# (unit, CLI and corpus tests; corpus tests skip visibly without ../shared/data), then
# validates every glTF the tests wrote with the Khronos glTF-Validator (0 errors, 0 warnings).
# Each step prints how long it took.
#
# Usage: bash tools/test.sh [build-dir] [extra cmake args...]
# Environment:
#   MOCAPFILL_TEST_EXCLUDE  ctest labels left out, as a regex (default "perf": machine-dependent
#                           page-fault and timing checks; run them with `ctest -L perf`)
#   MOCAPFILL_BUILD_TYPE    CMake build type (default Release)
#   MOCAPFILL_BUILD_TARGET  what to build (default all; mocapfill_tests: the registered test
#                           programs and what they link, with MOCAPFILL_TEST_FOLDERS)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
exclude=${MOCAPFILL_TEST_EXCLUDE-perf}

step_start=$(date +%s)
step_done() {
  local now
  now=$(date +%s)
  printf -- '-- %s: %d min %02d s\n' "$1" $(((now - step_start) / 60)) $(((now - step_start) % 60))
  step_start=$now
}

bash "$root/tools/install_deps.sh"
step_done "install"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${MOCAPFILL_BUILD_TYPE:-Release}" \
  -DMOCAPFILL_WERROR=ON -DMOCAPFILL_UNITY_BUILD=ON "$@" >/dev/null
cmake --build "$build" -j "$(nproc)" --target "${MOCAPFILL_BUILD_TARGET:-all}"
step_done "build"
rm -rf "$build/test-output"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" ${exclude:+--label-exclude "$exclude"}
step_done "tests (labels excluded: ${exclude:-none})"
if [ -d "$build/test-output" ]; then
  node "$root/tools/validate_gltf.mjs" "$build/test-output"
else
  echo "error: the tests wrote no glTF into $build/test-output to validate" >&2
  exit 1
fi
step_done "glTF validation"
