#!/usr/bin/env bash
# Installs everything mocapfill needs to build and test on Debian 12 (run as root).
# Idempotent: skips apt when every package is already present.
# Usage: bash tools/install_deps.sh [--fuzz]   (--fuzz adds clang 14 and libFuzzer, for tools/fuzz.sh)
set -euo pipefail
packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libtinygltf-dev libassimp-dev assimp-utils libceres-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
  bc
  # The clients the tests drive: the Python module (pybind11, numpy, pytest) and Blender
  # (its glTF importer and the add-on).
  python3-dev pybind11-dev python3-numpy python3-pytest blender
)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
# Node.js runs the validator; take Debian's only when the machine has none of its own.
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# The npm packages pinned in tools/package.json: the Khronos glTF-Validator checks every glTF
# the tests write; three.js's BVHLoader reads the BVH they write (tests/clients).
here=$(cd "$(dirname "$0")" && pwd)
if [ -f "$here/package.json" ] && { [ ! -d "$here/node_modules/gltf-validator" ] || [ ! -d "$here/node_modules/three" ]; }; then
  npm install --prefix "$here" --no-audit --no-fund --silent >/dev/null
fi
