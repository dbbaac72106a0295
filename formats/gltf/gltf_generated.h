// The name the glTF writer gives the skin and stick-figure mesh it makes for a scene without
// a skinned mesh of its own (ExportOptions::gltf_skeleton); the reader leaves a mesh of that
// name out when asset.extras.mocapfill.generated_skeleton records it, so that converting our
// output again makes them afresh (or not, as that conversion's options say) instead of
// carrying them along as the scene's own geometry.
#pragma once

namespace mocapfill::gltf_internal {

inline constexpr const char* kGeneratedSkeletonName = "mocapfill_skeleton";

}  // namespace mocapfill::gltf_internal
