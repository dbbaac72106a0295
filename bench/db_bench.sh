#!/usr/bin/env bash
# Motion database speed: build an .mfdb from the 174 Bandai-Namco clips and load it, and
# print times and peak memory against the targets (build < 1 s, load < 50 ms, loaded
# database < 64 MB; docs/performance.md). Builds nothing: pass the build directory holding
# converter/mocapfill.
#
#   bench/db_bench.sh build-db [data_dir] [runs]
#
# Each step runs `runs` times (default 3); the best wall time is reported, with CPU time
# (user + sys) beside it because the machine is shared: when other jobs load it, wall time
# grows while CPU time stays put.
set -euo pipefail

build_dir=${1:?usage: bench/db_bench.sh BUILD_DIR [DATA_DIR] [RUNS]}
data_dir=${2:-$(cd "$(dirname "$0")/../.." && pwd)/shared/data/bandai-namco-1/data}
runs=${3:-3}
exe="$build_dir/converter/mocapfill"
[[ -x "$exe" ]] || { echo "error: $exe not found (build the mocapfill target first)" >&2; exit 1; }
[[ -d "$data_dir" ]] || { echo "error: $data_dir not found" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "error: /usr/bin/time is needed (apt-get install time)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
db="$work/bn1.mfdb"
clips=$(find "$data_dir" -name '*.bvh' | wc -l)

# Runs "$@" under /usr/bin/time -v; prints "wall_s cpu_s max_rss_kb" and keeps stdout in $work/out.
measure() {
  /usr/bin/time -v -o "$work/time" "$@" > "$work/out"
  awk -F': ' '
    /Elapsed \(wall clock\)/ { n = split($2, p, ":"); wall = (n == 3) ? p[1] * 3600 + p[2] * 60 + p[3] : p[1] * 60 + p[2] }
    /User time/ { user = $2 } /System time/ { sys = $2 } /Maximum resident/ { rss = $2 }
    END { printf "%.3f %.3f %d\n", wall, user + sys, rss }' "$work/time"
}

best() {  # keeps the run with the smallest first field
  sort -n | head -1
}

echo "mocapfill db bench: $clips clips from $data_dir, best of $runs runs"
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"

build_best=$(for _ in $(seq "$runs"); do measure "$exe" -q db build "$data_dir" -o "$db"; done | best)
read -r build_wall build_cpu build_rss <<< "$build_best"
size_mb=$(awk -v b="$(stat -c %s "$db")" 'BEGIN { printf "%.1f", b / 1e6 }')

info_best=$(for _ in $(seq "$runs"); do
  line=$(measure "$exe" db info "$db" --json)
  load=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["load_ms"], d["load_cpu_ms"])' "$work/out")
  echo "$load $line"
done | best)
read -r load_ms load_cpu_ms info_wall info_cpu info_rss <<< "$info_best"
frames=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["frames"], d["memory_bytes"])' "$work/out")
read -r db_frames db_bytes <<< "$frames"

verdict() { awk -v v="$1" -v t="$2" 'BEGIN { print (v < t) ? "ok" : "MISSED" }'; }
printf '\n%-34s %12s %12s %10s  %s\n' "step" "measured" "target" "ratio" "verdict"
printf '%-34s %10.3f s %10.3f s %10.2f  %s\n' "db build, wall ($clips clips)" "$build_wall" 1 \
  "$(awk -v a="$build_wall" 'BEGIN { print a / 1 }')" "$(verdict "$build_wall" 1)"
printf '%-34s %10.3f s %12s %10s\n' "db build, CPU time (user+sys)" "$build_cpu" "-" "-"
printf '%-34s %10.1f ms %9.1f ms %10.2f  %s\n' "load (inside db info, load_ms)" "$load_ms" 50 \
  "$(awk -v a="$load_ms" 'BEGIN { print a / 50 }')" "$(verdict "$load_ms" 50)"
printf '%-34s %10.1f ms %12s %10s\n' "load, CPU time (same run)" "$load_cpu_ms" "-" "-"
printf '%-34s %10.3f s %12s %10s\n' "db info process, wall" "$info_wall" "-" "-"
printf '%-34s %10.1f MB %9.1f MB %10.2f  %s\n' "db info peak RSS (loaded database)" "$(awk -v k="$info_rss" 'BEGIN { print k / 1024 }')" 64 \
  "$(awk -v k="$info_rss" 'BEGIN { print k / 1024 / 64 }')" "$(verdict "$(awk -v k="$info_rss" 'BEGIN { print k / 1024 }')" 64)"
printf '%-34s %10.1f MB\n' "db build peak RSS" "$(awk -v k="$build_rss" 'BEGIN { print k / 1024 }')"
printf '%-34s %10s MB (%s frames, %.1f MB of matrices)\n' ".mfdb file size" "$size_mb" "$db_frames" \
  "$(awk -v b="$db_bytes" 'BEGIN { print b / 1e6 }')"
