#!/usr/bin/env bash
# The test command: installs dependencies, builds with warnings as errors, runs every test
# (unit, CLI and corpus tests; corpus tests skip visibly without ../shared/data), then
# validates every glTF the tests wrote with the Khronos glTF-Validator (0 errors, 0 warnings).
# Usage: bash tools/test.sh [build-dir] [extra cmake args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
bash "$root/tools/install_deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMOCAPFILL_WERROR=ON "$@" >/dev/null
cmake --build "$build" -j "$(nproc)"
rm -rf "$build/test-output"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
if [ -d "$build/test-output" ]; then
  node "$root/tools/validate_gltf.mjs" "$build/test-output"
else
  echo "error: the tests wrote no glTF into $build/test-output to validate" >&2
  exit 1
fi
