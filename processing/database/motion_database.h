// The motion capture database every fill method searches (algorithms.md 7, step 2): all
// clips of one skeleton at one working rate, in signal space (tangent coordinates about the
// database's joint means plus heading-invariant root features), with the band-pass signals
// and the joint-correlation table precomputed. Immutable once built; built in memory by
// MotionDatabaseBuilder, stored and loaded by formats/mfdb.
//
// Channel layout (columns of signals(), of every stored band and of the correlation table):
//   3j + a          tangent component a (0 x, 1 y, 2 z) of joint j, radians; for the motion
//                   root joint: its tilt about the mean tilt (heading removed)
//   3J + f          root feature f (RootFeature in tangent_space.h), when root_joint() >= 0
// Rows: the frames of all clips concatenated in clip order (clip(i).first_frame ...).
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "processing/analysis/correlation.h"
#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/filtering/pyramid.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

// Per-clip labels: "content", "style", "id", "file" (the source path) and any other
// string pairs the importer found (Bandai-Namco: from the file name and the JSON beside it).
using ClipLabels = std::map<std::string, std::string>;

struct ClipRange {
  std::string name;
  ClipLabels labels;
  int first_frame = 0;  // first row in the concatenated matrices
  int num_frames = 0;
  double start_heading_rad = 0.0;                              // root heading at the clip's frame 0
  Eigen::Vector3d start_position_m = Eigen::Vector3d::Zero();  // root world position at frame 0
};

// A Laplacian band kept in the database: L_band of every channel of every clip, each clip's
// pyramid computed on the whole clip (clamped ends) and only then concatenated.
struct StoredBand {
  int band = 0;          // Laplacian index k at the database rate
  double peak_hz = 0.0;  // BandPeakHz(band, rate_hz)
  Eigen::MatrixXf values;  // frames x channels
};

struct DatabaseOptions {
  double rate_hz = 30.0;  // working rate every clip is resampled to (slerp rotations, cubic root)
  // Bands kept in float32, chosen by frequency (nearest peak): at 30 Hz {2, 1, 0.5} Hz are
  // L2 (step), L3 (stride: default fragmentation/matching band) and L4. Other bands are
  // cheap to recompute per clip with BuildPyramid on ClipSignalRows().
  std::vector<double> stored_band_hz = {2.0, 1.0, 0.5};
  double correlation_band_hz = 1.0;    // band of the correlation table (nearest peak; L3 at 30 Hz)
  double correlation_max_lag_s = 0.25;  // lags searched: |tau| <= round(this * rate_hz) frames
  int threads = 0;                      // worker threads for Build (0 = hardware concurrency)

  // Fails with kInvalidArgument naming the field.
  Status Validate() const;
};

class MotionDatabase {
 public:
  // Everything the database stores; the mfdb reader fills one and calls FromParts.
  struct Parts {
    Skeleton skeleton;
    double rate_hz = 30.0;
    TangentReference reference;   // joint means; reference.root_joint is the motion root
    std::vector<ClipRange> clips;
    Eigen::MatrixXf signals;      // frames x channels (layout above)
    // Joints other than the root whose translation is animated in some clip, and their local
    // translations (frames x 3 per joint, metres); constant translations come from the skeleton.
    std::vector<int> translated_joints;
    Eigen::MatrixXf translations;
    std::vector<StoredBand> bands;  // ascending band index
    CorrelationTable correlation;
  };

  MotionDatabase() = default;
  // Checks that the parts are consistent (sizes, clip ranges contiguous and covering every
  // row, finite values, channel count, correlation table size) and wraps them.
  // Errors name the inconsistent part (kInvalidData).
  static Result<MotionDatabase> FromParts(Parts parts);

  const Parts& parts() const { return parts_; }
  const Skeleton& skeleton() const { return parts_.skeleton; }
  double rate_hz() const { return parts_.rate_hz; }
  const TangentReference& reference() const { return parts_.reference; }
  const std::vector<Eigen::Quaterniond>& joint_means() const { return parts_.reference.joint_means; }
  int root_joint() const { return parts_.reference.root_joint; }

  int num_clips() const { return static_cast<int>(parts_.clips.size()); }
  int num_frames() const { return static_cast<int>(parts_.signals.rows()); }
  int num_joints() const { return parts_.skeleton.num_joints(); }
  int num_channels() const { return static_cast<int>(parts_.signals.cols()); }
  const ClipRange& clip(int i) const { return parts_.clips[i]; }
  const std::vector<ClipRange>& clips() const { return parts_.clips; }
  // Index of the clip named `name`, or nullopt.
  std::optional<int> FindClip(const std::string& name) const;
  // The clips' row ranges, for per-clip processing of concatenated matrices.
  std::vector<FrameSegment> Segments() const;

  // Column of a joint's tangent component, of a root feature (or -1 without a root).
  int TangentChannel(int joint, int axis) const { return TangentColumn(joint, axis); }
  int RootFeatureChannel(int feature) const;
  // "UpperLeg_L.z", "root.forward_mps", ...
  std::string ChannelName(int channel) const;

  const Eigen::MatrixXf& signals() const { return parts_.signals; }
  // Rows of one clip of a frames x channels matrix (signals() or a stored band's values).
  auto ClipRows(const Eigen::MatrixXf& m, int clip_index) const {
    return m.middleRows(parts_.clips[clip_index].first_frame, parts_.clips[clip_index].num_frames);
  }
  const std::vector<StoredBand>& bands() const { return parts_.bands; }
  // The stored band with index k, or nullptr when it was not kept.
  const StoredBand* FindBand(int k) const;
  const CorrelationTable& correlation() const { return parts_.correlation; }

  // One clip in signal space (double precision copy of its rows).
  ClipSignals ClipSignalsOf(int clip_index) const;
  // One clip as a MotionClip at rate_hz() (rotations from the tangent coordinates, root
  // re-integrated from the features, other animated translations from storage), all frames
  // keyed. Equal to the clip given to the builder up to float32 storage rounding.
  Result<MotionClip> ReconstructClip(int clip_index) const;

  // Bytes held by the matrices (signals, translations, bands, correlation), for reports.
  size_t MemoryBytes() const;

 private:
  explicit MotionDatabase(Parts parts) : parts_(std::move(parts)) {}
  Parts parts_;
};

// Collects clips, then computes the database in Build().
class MotionDatabaseBuilder {
 public:
  explicit MotionDatabaseBuilder(DatabaseOptions options = {});

  // Renames joints of added clips before matching them against the database skeleton:
  // source joint name -> database joint name. Names not in the map are kept.
  void SetJointNameMap(std::map<std::string, std::string> source_to_database);

  // Adds one clip. The first clip's skeleton (after renaming) becomes the database's. A later
  // clip must have the same joints with the same parents, in any order (it is re-ordered);
  // otherwise kInvalidData naming the clip and the first differing joint, e.g.
  // "clip 'x': joint 'Hand_L' is missing (database skeleton has it)". Rest offsets may differ
  // (the database keeps the first skeleton's). The clip is validated and resampled to
  // options.rate_hz here. `labels` may be empty; labels["file"] is conventionally the path.
  Status Add(const Skeleton& skeleton, MotionClip clip, ClipLabels labels);

  int num_clips() const { return static_cast<int>(clips_.size()); }

  // Computes means, signals, stored bands and the correlation table. Deterministic: the same
  // clips added in the same order give identical databases, whatever the thread count.
  // Errors: no clips (kInvalidArgument), invalid options.
  Result<MotionDatabase> Build() const;

 private:
  DatabaseOptions options_;
  std::map<std::string, std::string> name_map_;
  std::optional<Skeleton> skeleton_;
  std::vector<MotionClip> clips_;
  std::vector<ClipLabels> labels_;
};

}  // namespace mocapfill
