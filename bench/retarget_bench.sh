#!/usr/bin/env bash
# What retargeting costs, measured against the plain job in the same run:
#   bench/retarget_bench.sh [build-dir] [data-dir]      (RETARGET_BENCH_RUNS=3: rounds)
# 1. A 10-minute 60 fps clip (CMU 01_01 at 60 Hz, looped) converted to .glb, plain against
#    --retarget onto Geno (75 joints): seconds, frames/s and the ratio.
# 2. `rig show` on Geno.fbx (mapping and rest pose of a 75-joint skinned character).
# 3. Fill of the shipped sketch on the Bandai-Namco rig against the same sketch put onto the Geno
#    rig (hips and legs kept): the retargeting overhead of a fill on a user's rig.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
data=${2:-$root/../shared/data}
exe=$build/converter/mocapfill
runs=${RETARGET_BENCH_RUNS:-3}
[ -x "$exe" ] || { echo "error: $exe not built" >&2; exit 1; }
[ -f "$data/geno/Geno.fbx" ] || { echo "error: $data/geno/Geno.fbx missing (the shared corpus)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The long clip: CMU 01_01's hierarchy, every other 120 Hz row (60 Hz), looped to 36,000 frames.
python3 - "$data/cmu/01_01.bvh" "$tmp/long60.bvh" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
m = next(i for i, l in enumerate(lines) if l.strip() == "MOTION")
rows = [l for l in lines[m + 3:] if l.strip()][::2]
out = lines[:m + 1] + ["Frames: 36000", "Frame Time: .0166667"]
out += [rows[i % len(rows)] for i in range(36000)]
open(sys.argv[2], "w").write("\n".join(out) + "\n")
PY

tick() { t=$EPOCHREALTIME; }
since() { echo "$EPOCHREALTIME - $t" | bc -l; }
minimum() { printf "%s\n" "$@" | sort -g | head -1; }

# Turns: plain, then retargeted, each round (this VM's speed drifts; see convert_bench.sh).
plain=() retarget=() rig=()
for ((r = 0; r < runs; r++)); do
  tick; "$exe" -q convert "$tmp/long60.bvh" "$tmp/plain.glb"; plain+=("$(since)")
  tick; "$exe" -q convert "$tmp/long60.bvh" "$tmp/geno.glb" --retarget "$data/geno/Geno.fbx"; retarget+=("$(since)")
  tick; "$exe" -q rig show "$data/geno/Geno.fbx" >/dev/null; rig+=("$(since)")
done
p=$(minimum "${plain[@]}") q=$(minimum "${retarget[@]}") g=$(minimum "${rig[@]}")
printf "10-min 60 fps clip (36,000 frames), CMU rig -> .glb:   plain %.3f s (%.0f frames/s)\n" "$p" "$(echo "36000 / $p" | bc -l)"
printf "  onto Geno.fbx (--retarget):                         %.3f s (%.0f frames/s), %.2fx the plain conversion\n" \
  "$q" "$(echo "36000 / $q" | bc -l)" "$(echo "$q / $p" | bc -l)"
printf "rig show Geno.fbx:                                    %.3f s\n" "$g"

# The shipped sketch, baked on each rig, hips and legs kept.
sketch=$root/fixtures/sketches/walk_proud_002_legs8.glb
"$exe" -q convert "$sketch" "$tmp/bandai_sketch.glb"
"$exe" -q convert "$sketch" "$tmp/geno_sketch.glb" --retarget "$data/geno/Geno.fbx"
bandai_keep=Hips,UpperLeg_L,LowerLeg_L,Foot_L,Toes_L,UpperLeg_R,LowerLeg_R,Foot_R,Toes_R
geno_keep=Hips,LeftUpLeg,LeftLeg,LeftFoot,LeftToeBase,RightUpLeg,RightLeg,RightFoot,RightToeBase
on_bandai=() on_geno=()
for ((r = 0; r < runs; r++)); do
  tick; "$exe" -q fill "$tmp/bandai_sketch.glb" -o "$tmp/b.glb" --keep "$bandai_keep" --report "$tmp/b.json"
  on_bandai+=("$(since)")
  tick; "$exe" -q fill "$tmp/geno_sketch.glb" -o "$tmp/g.glb" --keep "$geno_keep" --report "$tmp/g.json"
  on_geno+=("$(since)")
done
b=$(minimum "${on_bandai[@]}") g=$(minimum "${on_geno[@]}")
stage() { python3 -c "import json,sys; d=json.load(open(sys.argv[1]))['stage_seconds']; print(sum(v for k, v in d.items() if k.startswith('retarget')))" "$1"; }
printf "fill of the shipped sketch (304 frames, default database): Bandai rig %.3f s, Geno rig %.3f s: %.2fx\n" \
  "$b" "$g" "$(echo "$g / $b" | bc -l)"
printf "  retargeting stages inside the fill: Bandai rig %.1f ms, Geno rig %.1f ms\n" \
  "$(echo "1000 * $(stage "$tmp/b.json")" | bc -l)" "$(echo "1000 * $(stage "$tmp/g.json")" | bc -l)"
