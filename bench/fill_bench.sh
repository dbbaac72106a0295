#!/usr/bin/env bash
# Fill speed: a 10-second sketch (fixtures/sketches/walk_proud_002_legs8.glb, root and
# legs keyed every 8 frames) against the full 174-clip Bandai-Namco database, database build
# excluded (built once into an .mfdb first). Prints the per-stage times of each method from the
# fill report (best of N runs), the whole fill time inside the process, and the ratio to the
# `mean` baseline measured in the same run. `hybrid` runs twice: with the PCA model built in memory
# from the database (stage pca_model) and with a model built beforehand (`hybrid+model`, --pca);
# its report's Ceres summary is printed. Targets: hybrid under 1.5 s, its pca_fit under 200 ms.
#   bench/fill_bench.sh [build-dir] [data-dir] [runs]
# DB_FLAGS adds flags to the database build, e.g. DB_FLAGS="--mirror on" bench/fill_bench.sh.
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

echo "building the database (not timed): $data/bandai-namco-1/data ${DB_FLAGS:-}"
# shellcheck disable=SC2086 # DB_FLAGS is a list of words
"$exe" -q db build "$data/bandai-namco-1/data" -o "$tmp/bn1.mfdb" ${DB_FLAGS:-}
"$exe" -q pca build --db "$tmp/bn1.mfdb" -o "$tmp/bn1.pca"
echo "sketch: $sketch ($(nproc) cores)"

# Fill time inside the process = sum of the report's stages after loading the database
# ("fragments.<stage>" break the hybrid's "fragments" stage down and are not added again).
fill_seconds() {
  python3 -c 'import json,sys; s=json.load(open(sys.argv[1]))["stage_seconds"]; print(sum(v for k,v in s.items() if k!="load_database" and "." not in k))' "$1"
}

methods="mean nn fragment hierarchical pca hybrid hybrid+model"
declare -A best
for method in $methods; do
  best[$method]=999999
  flags=(--method "${method%+model}")
  [ "$method" = hybrid+model ] && flags+=(--pca "$tmp/bn1.pca")
  for ((i = 0; i < runs; i++)); do
    "$exe" -q fill "$sketch" -o "$tmp/out.glb" --db "$tmp/bn1.mfdb" "${flags[@]}" --report "$tmp/r.json"
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
if "pca_solver" in r:
    c = r["pca_solver"]
    print(f"{'':>12}  Ceres: {c['termination']}, {c['iterations']} iterations, cost {c['initial_cost']:.4g} -> "
          f"{c['final_cost']:.4g}, solve {1000*c['solve_seconds']:.1f} ms ({c['linear_solver']}), "
          f"model {r['pca_model']['components']} components ({r['pca_model']['source']})")
PY
done
echo
printf "%12s %10s %14s\n" method "fill ms" "ratio to mean"
for method in $methods; do
  printf "%12s %10.1f %14.1f\n" "$method" "$(echo "${best[$method]} * 1000" | bc -l)" \
    "$(echo "${best[$method]} / ${best[mean]}" | bc -l)"
done
