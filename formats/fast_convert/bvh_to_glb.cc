#include "formats/fast_convert/bvh_to_glb.h"

#include <algorithm>
#include <cstring>
#include <new>
#include <utility>
#include <vector>

#include "formats/bvh/bvh_hierarchy.h"
#include "formats/bvh/bvh_lexer.h"
#include "formats/bvh/bvh_motion.h"
#include "formats/bvh/bvh_scene.h"
#include "formats/fast_convert/bvh_track_rows.h"
#include "formats/fast_convert/large_buffer.h"
#include "formats/gltf/gltf_writer.h"

namespace mocapfill::fast_convert {

namespace {

// Moves the tracks of the joints that move down over the slots of those that do not
// (slot k to slot m <= k, in order, so nothing is overwritten before it is moved).
void CompactTranslations(const ClipTrackLayout& parsed, const std::vector<bool>& moves, float* tracks) {
  size_t m = 0;
  for (size_t k = 0; k < moves.size(); ++k) {
    if (!moves[k]) continue;
    if (m != k)
      std::memmove(tracks + parsed.TranslationTrack(m), tracks + parsed.TranslationTrack(k),
                   3 * parsed.frames * sizeof(float));
    ++m;
  }
}

// The channel group holding exactly the joint's position channels, or -1 (positions split
// by rotations, or sharing a group with another joint's).
int PositionGroup(const bvh::ParsedJoint& joint, const std::vector<bvh::rows::ChannelGroup>& groups) {
  int first = -1, count = 0;
  for (size_t i = 0; i < joint.layout.channels.size(); ++i) {
    if (bvh::IsRotation(joint.layout.channels[i])) continue;
    if (first < 0) first = joint.first_channel + static_cast<int>(i);
    ++count;
  }
  for (size_t g = 0; g < groups.size(); ++g)
    if (groups[g].first == first && groups[g].count == count) return static_cast<int>(g);
  return -1;
}

}  // namespace

std::optional<StreamedGlb> StreamBvhToGlb(std::string_view text, const std::string& path,
                                          const ImportOptions& options, const ExportOptions& export_options,
                                          int threads) {
  if (!bvh::CheckImportOptions(options).ok() || options.up == "z") return std::nullopt;
  bvh::BvhLexer lexer(bvh::WithoutByteOrderMark(text), path);
  Result<bvh::ParsedHierarchy> hierarchy = bvh::ParseHierarchy(lexer);
  if (!hierarchy.ok() || !hierarchy->warnings.empty() || hierarchy->num_channels == 0) return std::nullopt;
  Result<bvh::MotionHeader> header = bvh::ParseMotionHeader(lexer);
  if (!header.ok()) return std::nullopt;
  Result<Skeleton> skeleton = bvh::BuildSkeleton(*hierarchy, path);
  if (!skeleton.ok()) return std::nullopt;
  const Result<UnitChoice> unit = bvh::ResolveBvhUnit(*skeleton, options);
  if (!unit.ok()) return std::nullopt;

  // Room for the declared frames; a declared count the rest of the text cannot hold (every
  // value takes at least two bytes) is left to the clip path, which reports it.
  const size_t joints = hierarchy->joints.size();
  const size_t channels = static_cast<size_t>(hierarchy->num_channels);
  const int64_t frames = header->declared_frames;
  const int64_t max_rows = static_cast<int64_t>(lexer.remaining_bytes() / (2 * channels)) + 1;
  if (frames <= 0 || frames > max_rows || static_cast<size_t>(frames) * joints > bvh::rows::kMaxJointFrames)
    return std::nullopt;

  const std::vector<bvh::rows::JointSampler> samplers = bvh::rows::MakeSamplers(*hierarchy);
  const std::vector<bvh::rows::ChannelGroup> groups = bvh::rows::MakeChannelGroups(*hierarchy);
  TrackTarget target;
  target.samplers = &samplers;
  target.groups = &groups;
  target.channels = hierarchy->num_channels;
  target.metres_per_unit = unit->scale_to_m;
  for (size_t j = 0; j < joints; ++j)
    if (bvh::HasPositionChannels(skeleton->joint(static_cast<int>(j)))) {
      target.position_joints.push_back(static_cast<int>(j));
      target.position_groups.push_back(PositionGroup(hierarchy->joints[j], groups));
    }
  target.layout = {static_cast<size_t>(frames), joints, target.position_joints.size()};
  StreamedGlb glb;
  try {
    glb.tracks = LargeBuffer(target.layout.TotalFloats() * sizeof(float));
  } catch (const std::bad_alloc&) {
    return std::nullopt;  // the clip path says how much it needed
  }
  target.tracks = reinterpret_cast<float*>(glb.tracks.data());
  std::vector<PositionRange> ranges;
  if (!PackRows(lexer.TextFromHere(), target, threads, ranges)) return std::nullopt;

  Scene scene;
  scene.skeleton = std::move(*skeleton);
  ScaleScene(scene, unit->scale_to_m);
  scene.source = bvh::BvhSource(path, *header, *unit, false);
  MotionClip clip;
  clip.name = bvh::ClipName(path);
  clip.sample_rate_hz = bvh::SnapFrameRate(header->frame_time_s);
  clip.num_frames = static_cast<int>(frames);
  clip.num_joints = static_cast<int>(joints);
  clip.translation_animated.assign(joints, 0);
  std::vector<bool> moves(target.position_joints.size());
  for (size_t k = 0; k < moves.size(); ++k) {
    const int j = target.position_joints[k];
    moves[k] = ranges[k].Moves();
    clip.translation_animated[j] = moves[k];
    if (!moves[k]) bvh::AdoptConstantPosition(scene.skeleton.mutable_joint(j), ranges[k].first);
  }
  float* tracks = target.tracks;
  if (!PackFrameTimes(clip.name, target.layout.frames, clip.sample_rate_hz, tracks).ok()) return std::nullopt;
  CompactTranslations(target.layout, moves, tracks);
  const ClipTrackLayout layout{target.layout.frames, joints,
                               static_cast<size_t>(std::count(moves.begin(), moves.end(), true))};
  const float first_s = tracks[0], last_s = tracks[layout.frames - 1];
  scene.clips.push_back(std::move(clip));
  Result<GlbFile> head = WriteGlbHeadForTracks(scene, layout, first_s, last_s, export_options);
  if (!head.ok()) return std::nullopt;
  glb.head = std::move(head->head);
  glb.tail = std::move(head->bin);
  glb.tracks.resize(layout.TotalFloats() * sizeof(float));
  return glb;
}

}  // namespace mocapfill::fast_convert
