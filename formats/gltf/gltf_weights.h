// Skin influences as the glTF validator accepts them, shared by reader and writer so that
// an imported mesh already is what the exporter writes.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>

namespace mocapfill::gltf_internal {

// Merges a joint listed twice, clamps negative weights, renormalises to sum 1 and points
// zero-weight slots at joint 0. Returns false (and binds the vertex fully to its first
// slot) when every weight was zero.
bool NormaliseInfluences(std::array<std::uint16_t, 4>& joints, Eigen::Vector4d& weights);

}  // namespace mocapfill::gltf_internal
