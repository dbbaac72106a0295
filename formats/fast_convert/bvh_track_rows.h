// The MOTION rows of a BVH file parsed straight into the float32 tracks of a .glb's binary
// chunk (gltf_tracks.h), with no double-precision clip in between: each row is composed into
// one frame of local transforms (bvh_motion_rows.h, as ReadBvh does), which is packed at
// once, while it is in cache. Large sections are parsed on two threads. The floats are the
// ones WriteGlb packs from ReadBvh's clip; anything irregular makes it give up, and the
// caller converts through the clip instead, which reports the exact error or warning.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string_view>
#include <vector>

#include "formats/bvh/bvh_motion_rows.h"
#include "formats/gltf/gltf_tracks.h"

namespace mocapfill::fast_convert {

// Where the rows go. `layout.moving` counts every joint with position channels while the rows
// are parsed: slot k of the translation tracks holds joint position_joints[k].
struct TrackTarget {
  const std::vector<bvh::rows::JointSampler>* samplers = nullptr;
  const std::vector<bvh::rows::ChannelGroup>* groups = nullptr;
  int channels = 0;
  double metres_per_unit = 1.0;
  std::vector<int> position_joints;
  // Per position joint: the channel group holding all of its position channels (a frame whose
  // text repeats it has the translation of the frame before), or -1.
  std::vector<int> position_groups;
  ClipTrackLayout layout;  // frames: the declared frame count, which the rows must match
  float* tracks = nullptr;  // layout.TotalFloats() floats; the time track is left alone
};

// Per joint with position channels: its translation (metres) at frame 0, and the least and
// greatest value of each coordinate over the clip.
struct PositionRange {
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  // Whether some frame is off frame 0 by more than ReadBvh's tolerance (1e-9 m) in some
  // coordinate: the same answer as its frame-by-frame test, since rounded subtraction is
  // monotonic.
  bool Moves() const;
};

// Parses every row of `rows_text` (the text after the Frame Time line) into `target`,
// on two threads when `threads` allows and the text is large. Returns false when the rows
// are not exactly layout.frames complete, valid rows, the tracks then being unspecified.
bool PackRows(std::string_view rows_text, const TrackTarget& target, int threads, std::vector<PositionRange>& ranges);

}  // namespace mocapfill::fast_convert
