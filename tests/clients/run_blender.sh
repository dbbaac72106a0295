#!/usr/bin/env bash
# run_blender.sh TEST_SCRIPT [ARGS...]: runs a Python test script in a headless Blender
# (factory settings, so a user's add-ons and preferences do not interfere); the script's
# failure becomes Blender's exit code. Exits 77 (skipped) when Blender is not installed,
# so that a machine without it says so rather than failing.
set -u
script=$1
shift
blender=${BLENDER:-blender}
if ! command -v "$blender" >/dev/null 2>&1; then
  echo "SKIPPED: no Blender ($blender) on PATH (apt-get install blender, or set BLENDER=/path/to/blender)"
  exit 77
fi
exec "$blender" -b --factory-startup --python-exit-code 1 --python "$script" -- "$@"
