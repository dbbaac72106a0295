#!/usr/bin/env bash
# BVH parse throughput against Assimp's importer, both in one process (see bvh_read_bench.cc).
#   bench/bvh_read_bench.sh [build-dir] [data-dir] [rounds]
# Needs the build's mocapfill_bvh libraries (ninja -C <build> mocapfill_bvh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
data=${2:-$root/../shared/data}
rounds=${3:-7}
exe=$(mktemp -d)/bvh_read_bench
trap 'rm -rf "$(dirname "$exe")"' EXIT
g++ -O3 -DNDEBUG -std=c++20 -I"$root" -isystem /usr/include/eigen3 "$root/bench/bvh_read_bench.cc" \
  "$build/formats/libmocapfill_bvh.a" "$build/formats/libmocapfill_format_common.a" \
  "$build/processing/libmocapfill_core.a" -lassimp -o "$exe"
for clip in "$data"/cmu/*.bvh "$data"/assimp/*.bvh; do
  echo "$(basename "$clip"):"
  "$exe" "$rounds" "$clip"
done
echo "bandai-namco-1 (all clips):"
"$exe" "$(( (rounds + 2) / 3 ))" "$data"/bandai-namco-1/data/*.bvh
