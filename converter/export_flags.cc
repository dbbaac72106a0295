#include "converter/export_flags.h"

namespace mocapfill::cli {

void AddExportFlags(CLI::App& command, ExportOptions& options) {
  CLI::Option* no_skin = command.add_flag_callback(
      "--no-skin", [&options] { options.gltf_skeleton = GltfSkeleton::kNodes; },
      "glTF: write the joints as bare animated nodes, without the skin that is written by default for a motion "
      "without a skinned mesh (Blender, Unity and Unreal build a skeleton only from a skin)");
  command
      .add_flag_callback(
          "--skeleton-mesh", [&options] { options.gltf_skeleton = GltfSkeleton::kSkinAndMesh; },
          "glTF: also write a stick-figure mesh bound to that skin (one thin octahedron per bone), so that Blender "
          "shows an armature; reading the file back leaves it out")
      ->excludes(no_skin);
  command
      .add_option_function<std::string>(
          "--bvh-layout", [&options](const std::string& name) { options.bvh_layout = *ParseBvhLayout(name); },
          "BVH: source (each joint's channels as the source had them; exact) or standard (three rotations on every "
          "joint, XYZ positions over a zero OFFSET only on joints that move: the same motion in readers that add "
          "position channels to the OFFSET, such as three.js, and in those that replace it)")
      ->check(CLI::IsMember({"source", "standard"}))
      ->default_str("source");
}

}  // namespace mocapfill::cli
