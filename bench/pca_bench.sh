#!/usr/bin/env bash
# Speed of the PCA key fit (target: 300 frames, 30 components, Ceres fit < 200 ms),
# stage by stage, against a direct sparse solve of the same problem in the same run.
#   bench/pca_bench.sh [build-dir] [data-dir] [repeats]
# Configures the build dir with MOCAPFILL_BUILD_BENCHMARKS=ON and builds only pca_bench.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
data=${2:-$root/../shared/data}
repeats=${3:-5}
cmake -S "$root" -B "$build" -G Ninja -DMOCAPFILL_BUILD_BENCHMARKS=ON >/dev/null
ninja -C "$build" pca_bench >/dev/null
"$build/tests/pca_bench" "$data" "$repeats"
