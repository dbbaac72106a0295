#include "tests/fuzz/fuzz_targets.h"

namespace mocapfill::fuzz {

const std::vector<FuzzTarget>& AllFuzzTargets() {
  static const std::vector<FuzzTarget> targets = {
      {"bvh", FuzzBvh}, {"gltf", FuzzGltf},         {"mfdb", FuzzMfdb},
      {"pca", FuzzPca}, {"pipeline", FuzzPipeline}, {"maps", FuzzMaps},
      {"fbx", FuzzFbx}, {"wire", FuzzWire},
  };
  return targets;
}

}  // namespace mocapfill::fuzz
