#!/usr/bin/env bash
# The folders' rules (docs/architecture.md), checked on the #include lines of the sources:
#   formats/ reaches processing/ only in processing/core;
#   processing/ includes nothing of formats/, library/ or converter/;
#   processing/synthesis and processing/texturing reach neither the PCA fits (Ceres) nor the
#   layers above them (hybrid, fill);
#   outside formats/fast_convert/, only ConvertFile (formats/motion_io.cc) reaches the fast
#   path, and the AVX2 variants its CPU check;
#   public headers (include/mocapfill/) include no third-party header but Eigen's.
# Prints every include that breaks a rule and exits 1 if there is one.
#   tools/check_layering.sh [source-dir]
set -uo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root" || exit 2
broken=0

# rule NAME < hits ("file:line:text"): reports the hits, if any, as breaking rule NAME.
rule() {
  local hits
  hits=$(cat)
  if [ -n "$hits" ]; then
    echo "layering: $1:"
    echo "$hits" | sed 's/^/  /'
    broken=1
  fi
}
sources() { find "$@" \( -name '*.h' -o -name '*.cc' \) 2>/dev/null | sort; }
includes() { sources "$1" | xargs -r grep -HnE "$2"; }

rule "formats/ may include only processing/core of processing/" < <(
  includes formats '#include "processing/' | grep -v '#include "processing/core/')
rule "processing/ may include nothing of formats/, library/ or converter/" < <(
  includes processing '#include "(formats|library|converter)/')
rule "synthesis/ and texturing/ may not reach the PCA fits (Ceres), hybrid/ or fill/" < <(
  { includes processing/synthesis '#include "processing/(pca|hybrid|fill)/|ceres'
    includes processing/texturing '#include "processing/(pca|hybrid|fill)/|ceres'; })
rule "outside formats/fast_convert/ only ConvertFile reaches the fast path (and the AVX2 variants its CPU check)" < <(
  sources formats converter library processing python include bench |
    grep -v '^formats/fast_convert/' | xargs -r grep -HnE '#include "formats/fast_convert/' |
    grep -vE '^formats/motion_io\.cc:[0-9]+:#include "formats/fast_convert/fast_convert\.h"' |
    grep -vE '^formats/(bvh/bvh_euler|gltf/gltf_tracks)\.cc:[0-9]+:#include "formats/fast_convert/cpu_avx2\.h"')
rule "public headers may include no third-party header but Eigen's" < <(
  includes include/mocapfill '#include <(tiny_gltf|assimp|ceres|nlohmann|glog|CLI|pybind11)')

[ "$broken" = 0 ] && echo "layering: every folder keeps its rules"
exit "$broken"
