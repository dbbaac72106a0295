#!/usr/bin/env bash
# Conversion speed of mocapfill against Assimp's CLI, measured in the same run.
#   bench/convert_bench.sh [build-dir] [data-dir]      (CONVERT_BENCH_RUNS=3: rounds of paired runs)
# Prints, for the 174 Bandai-Namco clips (one process per file, and one batch process) and for
# each CMU clip: seconds, MB/s, frames/s, and the speed-up over `assimp export IN OUT -f glb2`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
data=${2:-$root/../shared/data}
exe=$build/converter/mocapfill
command -v assimp >/dev/null || { echo "error: assimp CLI missing (apt-get install assimp-utils)" >&2; exit 1; }
[ -x "$exe" ] || { echo "error: $exe not built" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The binary is timed as installed (copied, as `cmake --install` and packages do), not as
# the linker left it: the kernel's page cache holds a freshly linked file in a way that makes
# each process slower to start, which is no property of the program (docs/performance.md).
cp "$exe" "$tmp/mocapfill"
exe=$tmp/mocapfill

# bash's own clock ($EPOCHREALTIME): forking date(1) for every reading would add about a
# millisecond to each measured command, much of a few-millisecond CMU conversion.
frames_of() { awk '/^Frames:/ {s += $2} END {print s}' "$@"; }
bytes_of() { cat "$@" | wc -c; }

bandai=("$data"/bandai-namco-1/data/*.bvh)
mb=$(echo "$(bytes_of "${bandai[@]}") / 1000000" | bc -l)
frames=$(frames_of "${bandai[@]}")

# A shared machine's vCPUs change speed from one second to the next, so the two tools take
# turns: Assimp then mocapfill on each file (or clip run). Two figures come out: the best run
# of each side against the other's best, and the median over the pairs of each pair's own
# ratio, which a slow stretch shifts for both sides at once. Measured one side after the
# other, a ratio would move with the machine rather than with the programs.
tick() { t=$EPOCHREALTIME; }
add() { echo "$1 + $2 - $3" | bc -l; }
minimum() { printf "%s\n" "$@" | sort -g | head -1; }
median() { printf "%s\n" "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# One paired pass over the set, one process per file: sets pass_as, pass_mf (seconds).
per_file_pass() {
  pass_as=0; pass_mf=0
  local f t0 t1 t2
  for f in "${bandai[@]}"; do
    tick; t0=$t; assimp export "$f" "$tmp/as.glb" -f glb2 >/dev/null 2>&1
    tick; t1=$t; "$exe" convert "$f" "$tmp/mf.glb" >/dev/null 2>&1
    tick; t2=$t
    pass_as=$(add "$pass_as" "$t1" "$t0"); pass_mf=$(add "$pass_mf" "$t2" "$t1")
  done
}
batch_once() {
  local t0; tick; t0=$t; "$exe" convert "${bandai[@]}" -o "$tmp/batch" >/dev/null 2>&1; tick
  echo "$t - $t0" | bc -l
}

runs=${CONVERT_BENCH_RUNS:-3}
as_runs=(); mf_runs=(); mf_pairs=(); batch_runs=(); batch_pairs=()
for ((r = 0; r < runs; r++)); do
  per_file_pass
  as_runs+=("$pass_as"); mf_runs+=("$pass_mf"); mf_pairs+=("$(echo "$pass_as / $pass_mf" | bc -l)")
  # Batch runs right after the pass whose Assimp time they are compared with.
  for ((b = 0; b < 3; b++)); do
    tb=$(batch_once); batch_runs+=("$tb"); batch_pairs+=("$(echo "$pass_as / $tb" | bc -l)")
  done
done

printf "%-38s %9s %9s %11s %10s %14s\n" "case" "seconds" "MB/s" "frames/s" "vs assimp" "paired median"
row() {
  printf "%-38s %9.3f %9.1f %11.0f %10s %14s\n" "$1" "$2" "$(echo "$3 / $2" | bc -l)" "$(echo "$4 / $2" | bc -l)" "$5" "$6"
}
times() { printf '%.1fx' "$1"; }
t_as=$(minimum "${as_runs[@]}"); t_mf=$(minimum "${mf_runs[@]}"); t_batch=$(minimum "${batch_runs[@]}")
row "bandai 174 clips, assimp per file" "$t_as" "$mb" "$frames" "1.0x" ""
row "bandai 174 clips, mocapfill per file" "$t_mf" "$mb" "$frames" "$(times "$(echo "$t_as / $t_mf" | bc -l)")" \
  "$(times "$(median "${mf_pairs[@]}")")"
row "bandai 174 clips, mocapfill batch" "$t_batch" "$mb" "$frames" "$(times "$(echo "$t_as / $t_batch" | bc -l)")" \
  "$(times "$(median "${batch_pairs[@]}")")"
for clip in "$data"/cmu/*.bvh; do
  name=$(basename "$clip" .bvh)
  c_mb=$(echo "$(bytes_of "$clip") / 1000000" | bc -l)
  c_frames=$(frames_of "$clip")
  c_as=(); c_mf=(); c_pairs=()
  for ((i = 0; i < 5 * runs; i++)); do
    tick; t0=$t; assimp export "$clip" "$tmp/as.glb" -f glb2 >/dev/null 2>&1
    tick; t1=$t; "$exe" convert "$clip" "$tmp/mf.glb" >/dev/null 2>&1
    tick; t2=$t
    d_as=$(echo "$t1 - $t0" | bc -l); d_mf=$(echo "$t2 - $t1" | bc -l)
    c_as+=("$d_as"); c_mf+=("$d_mf"); c_pairs+=("$(echo "$d_as / $d_mf" | bc -l)")
  done
  best_as=$(minimum "${c_as[@]}"); best_mf=$(minimum "${c_mf[@]}")
  row "cmu $name, assimp" "$best_as" "$c_mb" "$c_frames" "1.0x" ""
  row "cmu $name, mocapfill" "$best_mf" "$c_mb" "$c_frames" "$(times "$(echo "$best_as / $best_mf" | bc -l)")" \
    "$(times "$(median "${c_pairs[@]}")")"
done
# The ratios move with the machine: in a slow phase (page faults and process starts several
# times dearer) Assimp, which takes many more page faults per clip, slows down more than
# mocapfill does. Each side's cost of a process that does nothing useful, measured in turns,
# says which phase the figures above were taken in.
fl_mf=(); fl_as=()
for ((i = 0; i < 10 * runs; i++)); do
  tick; t0=$t; assimp version >/dev/null 2>&1
  tick; t1=$t; "$exe" convert "$tmp/missing.bvh" "$tmp/missing.glb" >/dev/null 2>&1 || true
  tick; t2=$t
  fl_as+=("$(echo "$t1 - $t0" | bc -l)"); fl_mf+=("$(echo "$t2 - $t1" | bc -l)")
done
printf "process floor (median): mocapfill failing on a missing input %.2f ms, assimp version %.2f ms\n" \
  "$(echo "$(median "${fl_mf[@]}") * 1000" | bc -l)" "$(echo "$(median "${fl_as[@]}") * 1000" | bc -l)"
echo "targets: >= 5x per file over the whole set, >= 20x on each CMU clip, >= 50x in batch mode"
