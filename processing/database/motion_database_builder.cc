// MotionDatabaseBuilder: skeleton matching on Add, the parallel signal/band computation and
// the correlation table in Build.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <set>
#include <string>
#include <thread>

#include "processing/analysis/correlation.h"
#include "processing/core/kinematics.h"
#include "processing/database/motion_database_builder.h"
#include "processing/filtering/pyramid.h"
#include "processing/motion/mirror.h"
#include "processing/motion/resample.h"
#include "processing/motion/tangent_space.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

namespace {

// Runs fn(i) for i in [0, count) on `threads` workers; each index is handled exactly once,
// and results written to disjoint slots make the outcome independent of scheduling.
template <typename Fn>
void ParallelFor(int count, int threads, const Fn& fn) {
  const int workers = std::max(1, std::min(threads, count));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next.fetch_add(1); i < count; i = next.fetch_add(1)) fn(i);
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

// Index of each database joint in the clip's skeleton, or an error naming the first joint
// that differs (missing, extra, or attached to another parent).
Result<std::vector<int>> MatchSkeleton(const Skeleton& database, const std::vector<std::string>& names,
                                       const Skeleton& source, const std::string& clip_name) {
  std::vector<int> source_of(database.num_joints(), -1);
  for (int d = 0; d < database.num_joints(); ++d) {
    const auto it = std::find(names.begin(), names.end(), database.name(d));
    if (it == names.end())
      return InvalidData("clip '" + clip_name + "': joint '" + database.name(d) +
                         "' of the database skeleton is missing (use a joint-name map if it has another name)");
    source_of[d] = static_cast<int>(it - names.begin());
  }
  for (int s = 0; s < source.num_joints(); ++s)
    if (!database.Find(names[s]))
      return InvalidData("clip '" + clip_name + "': joint '" + names[s] + "' is not in the database skeleton");
  for (int d = 0; d < database.num_joints(); ++d) {
    const int sp = source.parent(source_of[d]);
    const std::string source_parent = sp == kNoParent ? "(none)" : names[sp];
    const std::string database_parent = database.parent(d) == kNoParent ? "(none)" : database.name(database.parent(d));
    if (source_parent != database_parent)
      return InvalidData("clip '" + clip_name + "': joint '" + database.name(d) + "' has parent '" + source_parent +
                         "', in the database skeleton its parent is '" + database_parent + "'");
  }
  return source_of;
}

MotionClip ReorderJoints(const MotionClip& clip, const std::vector<int>& source_of) {
  MotionClip out = clip;
  const int joints = static_cast<int>(source_of.size());
  for (int d = 0; d < joints; ++d) {
    const int s = source_of[d];
    out.translation_animated[d] = clip.translation_animated[s];
    out.keys[d] = clip.keys[s];
    for (int f = 0; f < clip.num_frames; ++f) {
      out.rotation(f, d) = clip.rotation(f, s);
      out.translation(f, d) = clip.translation(f, s);
    }
  }
  return out;
}

// Signals, translations and requested bands of one clip, written into its rows.
struct BuildOutputs {
  Eigen::MatrixXf* signals;
  Eigen::MatrixXf* translations;
  std::vector<Eigen::MatrixXf>* bands;  // one per entry of band_indices
};

void ProcessClip(const Skeleton& skeleton, const MotionClip& clip, const TangentReference& reference,
                 const std::vector<int>& translated, const std::vector<int>& band_indices, int first_row,
                 ClipRange& range, BuildOutputs out) {
  const ClipSignals s = DecomposeClip(skeleton, clip, reference);
  const int frames = clip.num_frames;
  Eigen::MatrixXf signals(frames, out.signals->cols());
  signals << s.tangent.cast<float>(), s.root_features.cast<float>();
  out.signals->middleRows(first_row, frames) = signals;
  for (size_t i = 0; i < translated.size(); ++i)
    for (int f = 0; f < frames; ++f)
      out.translations->block<1, 3>(first_row + f, 3 * i) = clip.translation(f, translated[i]).transpose().cast<float>();
  range.start_heading_rad = s.start_heading_rad;
  range.start_position_m = s.start_position_m;
  // Pyramids on the whole clip (ends clamped), so fragments cut later carry no edge effects
  // of their own (algorithms.md 2c). Float suffices: the bands are stored as float.
  Eigen::MatrixXf g = std::move(signals);
  const int top = band_indices.empty() ? -1 : band_indices.back();
  for (int k = 0; k <= top; ++k) {
    Eigen::MatrixXf next = SmoothLevel(g, k, PyramidBoundary::kClamp);
    const auto it = std::find(band_indices.begin(), band_indices.end(), k);
    if (it != band_indices.end()) (*out.bands)[it - band_indices.begin()].middleRows(first_row, frames) = g - next;
    g = std::move(next);
  }
}

// Every clip's mirror image, in order. The rig stands in the clips' mean pose (the pose the
// database's own rest is; its zero pose need not stand), which also decides its sides.
Result<std::vector<MotionClip>> MirroredClips(const Skeleton& skeleton, const std::vector<MotionClip>& clips) {
  std::vector<const MotionClip*> ptrs;
  for (const MotionClip& c : clips) ptrs.push_back(&c);
  const int root = FindMotionRoot(skeleton, ptrs);
  const RigRest rest = MeanPoseRest(skeleton, JointMeanRotations(skeleton, ptrs, root), root);
  Result<RigMapping> mapping = MapHumanoid(skeleton, rest.WorldPositions(skeleton));
  if (!mapping.ok()) return mapping.status().WithContext("database: mirroring needs a humanoid rig");
  ASSIGN_OR_RETURN(const MirrorPlan plan, PlanMirror(skeleton, *mapping, rest));
  std::vector<MotionClip> mirrored;
  mirrored.reserve(clips.size());
  for (const MotionClip& c : clips) {
    mirrored.push_back(MirrorClip(skeleton, plan, c));
    mirrored.back().name = c.name + "#mirror";
  }
  return mirrored;
}

}  // namespace

Status DatabaseOptions::Validate() const {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) return InvalidArgument("database: rate_hz must be finite and > 0");
  for (double hz : stored_band_hz)
    if (!std::isfinite(hz) || hz <= 0.0 || hz > 0.5 * rate_hz)
      return InvalidArgument("database: stored_band_hz values must be in (0, rate_hz / 2]");
  if (!std::isfinite(correlation_band_hz) || correlation_band_hz <= 0.0 || correlation_band_hz > 0.5 * rate_hz)
    return InvalidArgument("database: correlation_band_hz must be in (0, rate_hz / 2]");
  if (!std::isfinite(correlation_max_lag_s) || correlation_max_lag_s < 0.0 || correlation_max_lag_s > 10.0)
    return InvalidArgument("database: correlation_max_lag_s must be in [0, 10] s");
  if (threads < 0) return InvalidArgument("database: threads must be >= 0");
  return OkStatus();
}

MotionDatabaseBuilder::MotionDatabaseBuilder(DatabaseOptions options) : options_(std::move(options)) {}

void MotionDatabaseBuilder::SetJointNameMap(std::map<std::string, std::string> source_to_database) {
  name_map_ = std::move(source_to_database);
}

Status MotionDatabaseBuilder::Add(const Skeleton& skeleton, MotionClip clip, ClipLabels labels) {
  RETURN_IF_ERROR(options_.Validate());
  RETURN_IF_ERROR(clip.Validate(skeleton).WithContext("clip '" + clip.name + "'"));
  std::vector<std::string> names;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const auto it = name_map_.find(skeleton.name(j));
    names.push_back(it == name_map_.end() ? skeleton.name(j) : it->second);
  }
  if (!skeleton_) {
    std::vector<Joint> joints = skeleton.joints();
    for (int j = 0; j < skeleton.num_joints(); ++j) joints[j].name = names[j];
    Result<Skeleton> renamed = Skeleton::Build(std::move(joints));
    if (!renamed.ok()) return renamed.status().WithContext("clip '" + clip.name + "' after joint renaming");
    skeleton_ = std::move(renamed).value();
  } else {
    ASSIGN_OR_RETURN(const std::vector<int> source_of, MatchSkeleton(*skeleton_, names, skeleton, clip.name));
    bool identity = true;
    for (size_t d = 0; d < source_of.size(); ++d) identity = identity && source_of[d] == static_cast<int>(d);
    if (!identity) clip = ReorderJoints(clip, source_of);
  }
  if (std::abs(clip.sample_rate_hz - options_.rate_hz) <= 1e-9 * options_.rate_hz) {
    clips_.push_back(std::move(clip));  // already at the working rate: no copy
  } else {
    ResampleOptions resample;
    resample.rate_hz = options_.rate_hz;
    ASSIGN_OR_RETURN(MotionClip resampled, ResampleClip(clip, resample));
    clips_.push_back(std::move(resampled));
  }
  labels_.push_back(std::move(labels));
  return OkStatus();
}

Result<MotionDatabase> MotionDatabaseBuilder::Build() const {
  RETURN_IF_ERROR(options_.Validate());
  if (clips_.empty()) return InvalidArgument("database: no clips were added");
  const Skeleton& skeleton = *skeleton_;
  const int threads = options_.threads > 0 ? options_.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<MotionClip> with_mirrors;
  std::vector<ClipLabels> labels_with_mirrors;
  if (options_.mirror) {
    ASSIGN_OR_RETURN(std::vector<MotionClip> mirrored, MirroredClips(skeleton, clips_));
    with_mirrors = clips_;
    for (MotionClip& c : mirrored) with_mirrors.push_back(std::move(c));
    labels_with_mirrors = labels_;
    labels_with_mirrors.insert(labels_with_mirrors.end(), labels_.begin(), labels_.end());
  }
  const std::vector<MotionClip>& clips = options_.mirror ? with_mirrors : clips_;
  const std::vector<ClipLabels>& labels = options_.mirror ? labels_with_mirrors : labels_;
  std::vector<const MotionClip*> clip_ptrs;
  for (const MotionClip& c : clips) clip_ptrs.push_back(&c);

  MotionDatabase::Parts parts;
  parts.skeleton = skeleton;
  parts.rate_hz = options_.rate_hz;
  parts.reference = ComputeTangentReference(skeleton, clip_ptrs, FindMotionRoot(skeleton, clip_ptrs));
  const int root = parts.reference.root_joint;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    if (j == root) continue;
    for (const MotionClip& c : clips)
      if (c.translation_animated[j]) {
        parts.translated_joints.push_back(j);
        break;
      }
  }
  int frames = 0;
  for (size_t i = 0; i < clips.size(); ++i) {
    ClipRange range;
    range.name = clips[i].name;
    range.labels = labels[i];
    range.first_frame = frames;
    range.num_frames = clips[i].num_frames;
    parts.clips.push_back(std::move(range));
    frames += clips[i].num_frames;
  }
  const int channels = 3 * skeleton.num_joints() + (root >= 0 ? kNumRootFeatures : 0);

  // Bands by frequency: the stored ones plus the correlation band.
  constexpr int kBandSearchLevels = 16;
  std::set<int> stored;
  for (double hz : options_.stored_band_hz) stored.insert(BandForFrequency(hz, options_.rate_hz, kBandSearchLevels));
  const int correlation_band = BandForFrequency(options_.correlation_band_hz, options_.rate_hz, kBandSearchLevels);
  std::set<int> computed = stored;
  computed.insert(correlation_band);
  const std::vector<int> band_indices(computed.begin(), computed.end());

  parts.signals.resize(frames, channels);
  parts.translations.resize(frames, 3 * static_cast<Eigen::Index>(parts.translated_joints.size()));
  std::vector<Eigen::MatrixXf> bands(band_indices.size(), Eigen::MatrixXf(frames, channels));
  BuildOutputs outputs{&parts.signals, &parts.translations, &bands};
  ParallelFor(static_cast<int>(clips.size()), threads, [&](int i) {
    ProcessClip(skeleton, clips[i], parts.reference, parts.translated_joints, band_indices, parts.clips[i].first_frame,
                parts.clips[i], outputs);
  });

  const std::vector<FrameSegment> segments = [&] {
    std::vector<FrameSegment> s;
    for (const ClipRange& c : parts.clips) s.push_back({c.first_frame, c.num_frames});
    return s;
  }();
  const size_t correlation_slot = std::find(band_indices.begin(), band_indices.end(), correlation_band) - band_indices.begin();
  const int max_lag = static_cast<int>(std::lround(options_.correlation_max_lag_s * options_.rate_hz));
  ASSIGN_OR_RETURN(parts.correlation, ComputeCorrelationTable(bands[correlation_slot], segments, max_lag, threads));
  parts.correlation.band = correlation_band;
  parts.correlation.rate_hz = options_.rate_hz;
  for (size_t b = 0; b < band_indices.size(); ++b) {
    if (!stored.count(band_indices[b])) continue;
    parts.bands.push_back({band_indices[b], BandPeakHz(band_indices[b], options_.rate_hz), std::move(bands[b])});
  }
  return MotionDatabase::FromParts(std::move(parts));
}

}  // namespace mocapfill
