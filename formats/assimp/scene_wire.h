// A Result<Scene> as bytes, so that a reader run in a child process (isolated_read.h) can
// hand back what it read: every field of the scene, doubles bit for bit, or the error. Both
// ends are one build of mocapfill, so the layout carries no version; a size check at compile
// time (scene_wire.cc) catches a field added to the scene types and not to the wire.
#pragma once

#include <string>
#include <string_view>

#include "formats/motion_io.h"

namespace mocapfill {

std::string EncodeSceneResult(const Result<Scene>& result);

// The scene or error that EncodeSceneResult wrote. Bytes that are cut short or inconsistent
// (a child that died mid-write) give kInvalidData naming `path`; the skeleton and clips are
// checked as an importer checks them.
Result<Scene> DecodeSceneResult(std::string_view bytes, const std::string& path);

}  // namespace mocapfill
