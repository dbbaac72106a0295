#!/usr/bin/env bash
# Fill speed (issue #4): a 10-second sketch (fixtures/sketches/walk_proud_002_legs8.glb, root and
# legs keyed every 8 frames) against the full 174-clip Bandai-Namco database, database build
# excluded (built once into an .mfdb first). Prints the per-stage times of each method from the
# fill report (best of N runs), the whole fill time inside the process, and the ratio to the
# `mean` baseline measured in the same run.
#   bench/fill_bench.sh [build-dir] [data-dir] [runs]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
data=${2:-$root/../shared/data}
runs=${3:-3}
exe=$build/converter/mocapfill
sketch=$root/fixtures/sketches/walk_proud_002_legs8.glb
[ -x "$exe" ] || { echo "error: $exe not built" >&2; exit 1; }
command -v python3 >/dev/null || { echo "error: python3 is needed to read the reports" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "building the database (not timed): $data/bandai-namco-1/data"
"$exe" -q db build "$data/bandai-namco-1/data" -o "$tmp/bn1.mfdb"
echo "sketch: $sketch ($(nproc) cores)"

# Fill time inside the process = sum of the report's stages after loading the database.
fill_seconds() {
  python3 -c 'import json,sys; s=json.load(open(sys.argv[1]))["stage_seconds"]; print(sum(v for k,v in s.items() if k!="load_database"))' "$1"
}

declare -A best
for method in mean nn fragment hierarchical; do
  best[$method]=999999
  for ((i = 0; i < runs; i++)); do
    "$exe" -q fill "$sketch" -o "$tmp/out_$method.glb" --db "$tmp/bn1.mfdb" --method "$method" --report "$tmp/r.json"
    t=$(fill_seconds "$tmp/r.json")
    if (( $(echo "$t < ${best[$method]}" | bc -l) )); then
      best[$method]=$t
      cp "$tmp/r.json" "$tmp/best_$method.json"
    fi
  done
  python3 - "$tmp/best_$method.json" "$method" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
stages = ", ".join(f"{k} {1000*v:.1f} ms" for k, v in r["stage_seconds"].items())
print(f"{sys.argv[2]:>12}: {stages}")
PY
done
echo
printf "%12s %10s %14s\n" method "fill ms" "ratio to mean"
for method in mean nn fragment hierarchical; do
  printf "%12s %10.1f %14.1f\n" "$method" "$(echo "${best[$method]} * 1000" | bc -l)" \
    "$(echo "${best[$method]} / ${best[mean]}" | bc -l)"
done
