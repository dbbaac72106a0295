#!/usr/bin/env bash
# Row-loop A/B: formats/bvh and formats/bvh_glb as in git revision REV (default HEAD) against
# the working tree, built into one program and timed file by file in turns (bvh_ab.cc).
#   bench/bvh_ab.sh [REV] [build-dir] [rounds] [FILE...]     (default files: CMU 01_01 and 01_03)
#   BVH_AB_PASSES=N (1): passes of both programs; BVH_AB_FLAGS="...": extra compiler flags for
#   the working tree's copy (e.g. code alignment), against REV built with the usual ones.
# Everything else (glTF writer, file I/O, core) is the working tree's, from the build's
# libraries (ninja -C <build> mocapfill_gltf first). Prints working tree / base per link order
# and their geometric mean; run it A/A (REV = HEAD, no change) to see the noise on this
# machine (docs/performance.md has the figures).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
rev=${1:-HEAD}
build=${2:-$root/build}
rounds=${3:-5}
shift $(( $# < 3 ? $# : 3 ))
files=("$@")
[ ${#files[@]} -gt 0 ] || files=("$root"/../shared/data/cmu/01_01.bvh "$root"/../shared/data/cmu/01_03.bvh)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The base tree: the working tree's headers, with the two folders taken from REV.
mkdir -p "$tmp/base"
cp -r "$root/formats" "$root/processing" "$tmp/base/"
rm -rf "$tmp/base/formats/bvh" "$tmp/base/formats/bvh_glb"
git -C "$root" archive "$rev" formats/bvh formats/bvh_glb | tar -x -C "$tmp/base"

flags=(-O3 -DNDEBUG -fPIC -fno-semantic-interposition -std=c++20 -isystem /usr/include/eigen3)
objects=()
compile() {  # tree name
  local tree=$1 name=$2 src
  for src in "$tree"/formats/bvh/*.cc "$tree"/formats/bvh_glb/*.cc; do
    local object="$tmp/${name}_$(basename "$src" .cc).o"
    local extra=()
    [ "$name" = x ] && read -r -a extra <<< "${BVH_AB_FLAGS:-}"
    g++ "${flags[@]}" "${extra[@]}" -I"$tree" -Dbvh="bvh_$name" -Dbvh_glb="bvh_glb_$name" -c "$src" -o "$object" &
    objects+=("$object")
  done
}
compile "$tmp/base" a
compile "$root" x
wait
# ReadBvh and WriteBvh live in namespace mocapfill, so both copies define them; the driver
# calls neither, and either copy serves. Where each copy lands in the program moves its
# speed on its own, by as much as the changes being measured, so the program is linked both
# ways round and the two ratios' geometric mean is the figure.
link() {  # output objects...
  local out=$1; shift
  g++ "${flags[@]}" -I"$root" "$root/bench/bvh_ab.cc" "$@" \
    "$build/formats/libmocapfill_gltf.a" "$build/formats/libmocapfill_format_common.a" \
    "$build/processing/libmocapfill_core.a" -lpthread -Wl,--allow-multiple-definition -o "$out"
}
base_objects=("${objects[@]:0:${#objects[@]}/2}")
work_objects=("${objects[@]:${#objects[@]}/2}")
link "$tmp/bvh_ab_1" "${base_objects[@]}" "${work_objects[@]}"
link "$tmp/bvh_ab_2" "${work_objects[@]}" "${base_objects[@]}"
ratios=()
for ((pass = 0; pass < ${BVH_AB_PASSES:-1}; pass++)); do
  for order in 1 2; do
    line=$("$tmp/bvh_ab_$order" "$rounds" "${files[@]}")
    echo "link order $order: $line"
    ratios+=("$(echo "$line" | sed -E 's/.*working\/base ([0-9.]+).*/\1/')")
  done
done
printf "%s\n" "${ratios[@]}" | awk '{s += log($1)} END {printf "working tree / base, geometric mean of %d: %.4f\n", NR, exp(s / NR)}'
