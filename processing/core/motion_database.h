// The motion capture database every fill method searches (algorithms.md 7, step 2), as the
// data it stores: all clips of one skeleton at one working rate, in signal space (tangent
// coordinates about the database's joint means plus heading-invariant root features), with
// the band-pass signals and the joint-correlation table precomputed. Immutable once made.
//
// It lives in core, beside PcaModel, because both the algorithms and the .mfdb file format
// (formats/mfdb) need it and formats may depend only on core. Computing a database is an
// algorithm (MotionDatabaseBuilder, processing/database/motion_database_builder.h), and so is
// turning a stored clip back into motion (processing/database/stored_clips.h).
//
// Channel layout (columns of signals(), of every stored band and of the correlation table):
//   3j + a          tangent component a (0 x, 1 y, 2 z) of joint j, radians; for the motion
//                   root joint: its tilt about the mean tilt (heading removed)
//   3J + f          root feature f (RootFeature in processing/core/signal_layout.h), when
//                   root_joint() >= 0
// Rows: the frames of all clips concatenated in clip order (clip(i).first_frame ...).
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "processing/core/correlation_table.h"
#include "processing/core/signal_layout.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

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
  // A joint's local rotation from its three tangent channels (a row segment of signals() or of
  // a synthesised signal): the joint's reference rotation times their exponential map.
  Eigen::Quaterniond LocalRotation(int joint, const Eigen::Vector3d& channels) const;
  // Rows of one clip of a frames x channels matrix (signals() or a stored band's values).
  auto ClipRows(const Eigen::MatrixXf& m, int clip_index) const {
    return m.middleRows(parts_.clips[clip_index].first_frame, parts_.clips[clip_index].num_frames);
  }
  const std::vector<StoredBand>& bands() const { return parts_.bands; }
  // The stored band with index k, or nullptr when it was not kept.
  const StoredBand* FindBand(int k) const;
  const CorrelationTable& correlation() const { return parts_.correlation; }

  // Bytes held by the matrices (signals, translations, bands, correlation), for reports.
  size_t MemoryBytes() const;

 private:
  explicit MotionDatabase(Parts parts) : parts_(std::move(parts)) {}
  Parts parts_;
};

}  // namespace mocapfill
