#!/usr/bin/env bash
# The client checks (ctest label `clients`): files mocapfill writes, read by the programs users
# read them with, against mocapfill's own forward kinematics (mocapfill_fk_dump).
#   blender: BVH -> .glb (default skin, and --skeleton-mesh), imported by Blender's glTF
#            importer (blender_import_check.py), in one Blender run.
#   threejs: BVH -> BVH --bvh-layout standard, read by three.js's BVHLoader
#            (threejs_bvh_check.mjs); the source layout is measured too, for the record.
# Inputs: the shipped fixtures, and corpus clips when the corpus is there. Exit 77 (ctest's
# skip) when the client is not installed.
#
# Usage: run_client_checks.sh blender|threejs MOCAPFILL FK_DUMP OUT_DIR SOURCE_DIR DATA_DIR
set -euo pipefail
mode=$1 mocapfill=$2 fk_dump=$3 out=$4 src=$5 data=${MOCAPFILL_DATA_DIR:-$6}
here=$(cd "$(dirname "$0")" && pwd)

inputs=("$src/fixtures/bvh/bandai_walk_normal_001_short.bvh" "$src/fixtures/bvh/cmu_01_01_short.bvh"
        "$src/fixtures/bvh/boxing_interleaved.bvh")
if [ -d "$data" ]; then
  inputs+=("$data/bandai-namco-1/data/dataset-1_walk_normal_001.bvh" "$data/cmu/01_01.bvh")
else
  echo "corpus not found at '$data': fixtures only"
fi

case $mode in
  blender)
    if ! command -v blender >/dev/null 2>&1; then
      echo "SKIPPED: blender is not installed (tools/install_deps.sh installs Debian's)"
      exit 77
    fi
    dir=$out/blender
    rm -rf "$dir" && mkdir -p "$dir"
    pairs=()
    for bvh in "${inputs[@]}"; do
      stem=$(basename "$bvh" .bvh)
      "$fk_dump" "$bvh" "$dir/$stem.json"
      "$mocapfill" convert "$bvh" "$dir/$stem.glb"
      "$mocapfill" convert "$bvh" "$dir/${stem}_mesh.glb" --skeleton-mesh
      pairs+=("$dir/$stem.glb" "$dir/$stem.json" "$dir/${stem}_mesh.glb" "$dir/$stem.json")
    done
    # Blender's exit code says nothing about the script; the script's own (os._exit) does.
    blender -b --factory-startup --python "$here/blender_import_check.py" -- "${pairs[@]}" 2>&1 |
      grep -E '^(blender_import_check|Error|Traceback)' || true
    exit "${PIPESTATUS[0]}"
    ;;
  threejs)
    if ! command -v node >/dev/null 2>&1; then
      echo "SKIPPED: node is not installed"
      exit 77
    fi
    dir=$out/threejs
    rm -rf "$dir" && mkdir -p "$dir"
    checked=() reported=()
    for bvh in "${inputs[@]}"; do
      stem=$(basename "$bvh" .bvh)
      "$fk_dump" "$bvh" "$dir/$stem.json"
      "$mocapfill" convert "$bvh" "$dir/${stem}_standard.bvh" --bvh-layout standard
      "$mocapfill" convert "$bvh" "$dir/${stem}_source.bvh"
      checked+=("$dir/${stem}_standard.bvh" "$dir/$stem.json")
      reported+=("$dir/${stem}_source.bvh" "$dir/$stem.json")
    done
    exec node "$here/threejs_bvh_check.mjs" "$src/tools/node_modules" "${checked[@]}" --report-only "${reported[@]}"
    ;;
  *)
    echo "usage: run_client_checks.sh blender|threejs MOCAPFILL FK_DUMP OUT_DIR SOURCE_DIR DATA_DIR" >&2
    exit 2
    ;;
esac
