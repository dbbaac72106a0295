// texture: gives a keyframed sketch the high-frequency detail of a captured (or filled)
// motion (Pullen and Bregler's texturing; processing/texturing/texture_channels.h
// TextureChannels): each chosen channel becomes the sketch's smooth bands plus the source's
// bands above the keys' Nyquist rate. Both motions are decomposed about the sketch's mean
// rotations so the channels agree; the keys are then re-pinned (RepinKeys), as the fill's
// texturing stage does.
#include <algorithm>

#include "processing/core/median.h"
#include "processing/graph/nodes/node_support.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/motion/tangent_space.h"
#include "processing/texturing/repin_keys.h"
#include "processing/texturing/texture_channels.h"

namespace mocapfill::graph {

namespace {

// Median spacing of the keyed joints' rotation keys, in frames; 0 without keys.
int MedianKeySpacing(const MotionClip& clip) {
  std::vector<int> gaps;
  for (const JointKeys& keys : clip.keys)
    for (size_t k = 1; k < keys.rotation_frames.size(); ++k)
      gaps.push_back(keys.rotation_frames[k] - keys.rotation_frames[k - 1]);
  if (gaps.empty()) return 0;
  return UpperMedian(std::move(gaps));
}

// Frames [start, start + frames) of `clip`.
MotionClip Slice(const MotionClip& clip, int start, int frames) {
  MotionClip out = clip;
  const auto first = static_cast<std::ptrdiff_t>(start) * clip.num_joints;
  const auto count = static_cast<std::ptrdiff_t>(frames) * clip.num_joints;
  out.rotations.assign(clip.rotations.begin() + first, clip.rotations.begin() + first + count);
  out.translations.assign(clip.translations.begin() + first, clip.translations.begin() + first + count);
  out.num_frames = frames;
  return out;
}

// Key frames of every tangent channel: its joint's rotation key frames, as RepinKeys reads them.
std::vector<std::vector<int>> KeyFramesOf(const MotionClip& sketch) {
  std::vector<std::vector<int>> key_frames(3 * static_cast<size_t>(sketch.num_joints));
  for (int j = 0; j < sketch.num_joints; ++j)
    for (int axis = 0; axis < 3; ++axis) key_frames[TangentColumn(j, axis)] = sketch.keys[j].rotation_frames;
  return key_frames;
}

class TextureNode : public Node {
 public:
  TextureNode(int bands, std::vector<std::string> joints, int start, bool repin)
      : bands_(bands), joints_(std::move(joints)), start_(start), repin_(repin) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext&) const override {
    const Scene& sketch_scene = inputs.Motion("sketch");
    const Scene& source_scene = inputs.Motion("source");
    ASSIGN_OR_RETURN(const MotionClip* sketch, FirstClip(sketch_scene, "sketch"));
    ASSIGN_OR_RETURN(const MotionClip* source_clip, FirstClip(source_scene, "source"));
    const Skeleton& skeleton = sketch_scene.skeleton;
    RETURN_IF_ERROR(CheckSameJoints(skeleton, source_scene.skeleton, "sketch", "source"));
    ASSIGN_OR_RETURN(const MotionClip resampled, AtRate(*source_clip, sketch->sample_rate_hz));
    if (resampled.num_frames < start_ + sketch->num_frames)
      return InvalidData("source: " + std::to_string(resampled.num_frames) + " frames at " +
                         std::to_string(sketch->sample_rate_hz) + " Hz, but source_start_frame " + std::to_string(start_) +
                         " + the sketch's " + std::to_string(sketch->num_frames) + " frames are needed");
    const MotionClip source = Slice(resampled, start_, sketch->num_frames);
    ASSIGN_OR_RETURN(const std::vector<int> channels, Channels(skeleton, *sketch));
    int bands = bands_;
    if (bands == 0) {
      const int spacing = MedianKeySpacing(*sketch);
      if (spacing < 2) return InvalidData("sketch: keys are not spaced (set option \"bands\" explicitly)");
      bands = TextureBandCount(spacing, sketch->sample_rate_hz);
    }
    const MotionClip* clips[] = {sketch};
    const int root = FindMotionRoot(skeleton, clips);
    const TangentReference reference = ComputeTangentReference(skeleton, clips, root);
    ClipSignals signals = DecomposeClip(skeleton, *sketch, reference);
    const ClipSignals detail = DecomposeClip(skeleton, source, reference);
    Eigen::MatrixXd out = signals.tangent;
    TextureChannels(signals.tangent, detail.tangent, channels, bands, sketch->sample_rate_hz, out);
    if (repin_) RepinKeys(signals.tangent, KeyFramesOf(*sketch), channels, out);
    signals.tangent = std::move(out);
    ASSIGN_OR_RETURN(MotionClip textured, ComposeClip(skeleton, signals, reference, *sketch));
    return WithClip(sketch_scene, std::move(textured));
  }

 private:
  // Tangent columns of the named joints, or of every joint with rotation keys.
  Result<std::vector<int>> Channels(const Skeleton& skeleton, const MotionClip& sketch) const {
    std::vector<int> joints;
    for (const std::string& name : joints_) {
      ASSIGN_OR_RETURN(const int j, FindJointNamed(skeleton, name, "sketch (option joints)", ErrorCode::kInvalidData));
      joints.push_back(j);
    }
    if (joints_.empty())
      for (int j = 0; j < skeleton.num_joints(); ++j)
        if (!sketch.keys[j].rotation_frames.empty()) joints.push_back(j);
    if (joints.empty()) return InvalidData("sketch: no keyed joint to texture (name them in option \"joints\")");
    std::vector<int> channels;
    for (int j : joints)
      for (int axis = 0; axis < 3; ++axis) channels.push_back(TangentColumn(j, axis));
    return channels;
  }

  int bands_;
  std::vector<std::string> joints_;
  int start_;
  bool repin_;
};

Result<std::unique_ptr<Node>> CreateTexture(const NodeOptions& o) {
  return std::unique_ptr<Node>(new TextureNode(o.Int("bands"), o.StringList("joints"), o.Int("source_start_frame"),
                                                 o.Bool("repin_keys")));
}

}  // namespace

NodeTypeSpec TextureNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "texture";
  spec.summary = "Add a source motion's high-frequency bands to the sketch's keyed joints";
  spec.inputs = {{"sketch", PortType::kMotion, false, "smooth motion (keyframed sketch or a PCA fit)"},
                 {"source", PortType::kMotion, false, "detailed motion on the same skeleton (capture or fill result)"}};
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the sketch with the source's texture (sketch's frames and rate)"};
  spec.options = {
      IntOption("bands", 0, 0, 16, "texture bands (0 = those above the keys' Nyquist rate: 3 for keys every 8 frames at 30 Hz)"),
      ListOption("joints", OptionType::kStringList, "joints to texture (empty = every joint with rotation keys)"),
      IntOption("source_start_frame", 0, 0, std::nullopt, "first source frame aligned with the sketch's frame 0", "frames"),
      BoolOption("repin_keys", true, "restore the sketch's rotation keys after texturing (displacement map)"),
  };
  spec.create = CreateTexture;
  return spec;
}

}  // namespace mocapfill::graph
