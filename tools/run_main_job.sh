#!/usr/bin/env bash
# The main job on the embedded default data: fill a shipped sketch (root and legs keyed every
# 8th frame) from the embedded default database and write a validator-clean glb plus a report.
# Usage: bash tools/run_main_job.sh [output-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out}
build=$root/build
bash "$root/tools/install_deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target mocapfill
mkdir -p "$out"
sketch=$(ls "$root"/fixtures/sketches/*.glb | head -n 1)
"$build/converter/mocapfill" fill "$sketch" -o "$out/enriched.glb" --report "$out/fill.json"
echo "wrote $out/enriched.glb and $out/fill.json"
