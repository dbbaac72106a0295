#!/usr/bin/env bash
# installed_package_test.sh BUILD SOURCE [PYTHON]: installs the build into a fresh prefix,
# builds examples/cpp_fill against it with find_package(mocapfill CONFIG), and fills the
# shipped sketch with it and with examples/fill_sketch.py through the installed Python
# module; the installed command-line tool fills it too. Each must keep the keys (< 0.01 deg).
set -euo pipefail
build=$1
source=$2
python=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
sketch=$source/fixtures/sketches/walk_proud_002_legs8.glb

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in include/mocapfill/mocapfill.h include/mocapfill/version.h lib/cmake/mocapfill/mocapfillConfig.cmake \
         lib/cmake/mocapfill/mocapfillConfigVersion.cmake share/mocapfill/default_db/LICENSE; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f was not installed"; exit 1; }
done
# Nothing internal in the installed headers: they include only each other, Eigen and the standard library.
if grep -h '#include "' "$prefix"/include/mocapfill/*.h | grep -v '"mocapfill/'; then
  echo "FAIL: an installed header includes a header that is not installed"
  exit 1
fi

cmake -S "$source/examples/cpp_fill" -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/example" >/dev/null
# The default database: the prefix's share/mocapfill/default_db, found beside the installed library.
"$work/example/cpp_fill" "$sketch" "$work/cpp.glb" | tee "$work/cpp.txt"
grep -q "from default" "$work/cpp.txt"
key_error=$(sed -n 's/.*key error max \([0-9.]*\) deg.*/\1/p' "$work/cpp.txt")
awk -v e="$key_error" 'BEGIN { exit !(e < 0.01) }' || { echo "FAIL: cpp_fill key error $key_error deg"; exit 1; }
[ -s "$work/cpp.glb" ]

"$prefix/bin/mocapfill" fill "$sketch" -o "$work/cli.glb" --report "$work/cli.json" 2>/dev/null
[ -s "$work/cli.glb" ]

if [ -n "$python" ] && "$python" -c "import numpy" 2>/dev/null; then
  PYTHONPATH="$prefix/lib/python3/dist-packages" "$python" "$source/examples/fill_sketch.py" "$sketch" \
    "$work/py.glb" | tee "$work/py.txt"
  grep -q "from default" "$work/py.txt"
  # The same fill through the CLI, the C++ API and Python: the same key error.
  cpp=$(sed -n 's/.*key error max \([0-9.]*\) deg.*/\1/p' "$work/cpp.txt")
  py=$(sed -n 's/.*key error max \([0-9.]*\) deg.*/\1/p' "$work/py.txt")
  [ "$cpp" = "$py" ] || { echo "FAIL: C++ says $cpp deg, Python $py deg"; exit 1; }
  PYTHONPATH="$prefix/lib/python3/dist-packages" "$python" -c "
import mocapfill, sys
print('installed module:', mocapfill.__file__, '- default database:', mocapfill.default_database_path())
sys.exit(not (mocapfill.__file__.startswith('$prefix') and mocapfill.default_database_path().startswith('$prefix')))"
  # FBX through the Assimp plug-in installed beside the library (not the build tree's).
  MOCAPFILL_ASSIMP_MODULE= PYTHONPATH="$prefix/lib/python3/dist-packages" "$python" -c "
import mocapfill
scene = mocapfill.load('$source/fixtures/fbx/$(ls "$source/fixtures/fbx" | grep -m1 '\.fbx$')')
print('installed module reads FBX:', scene.joint_count, 'joints')"
else
  echo "SKIPPED the Python example: no Python module or numpy"
fi
echo "installed package: C++ example, CLI and Python example filled $sketch"
