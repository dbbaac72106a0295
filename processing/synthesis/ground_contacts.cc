#include "processing/synthesis/ground_contacts.h"

#include <algorithm>
#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/core/median.h"
#include "processing/database/stored_clips.h"
#include "processing/motion/foot_contacts.h"

namespace mocapfill {

namespace {

// Capture's feet stand still: the detection's speed limit is tight and needs no allowance for
// a fast body (that allowance is for filled motion, whose stance feet slide).
ContactDetection CaptureDetection() {
  ContactDetection d;
  d.max_speed_m_per_s = 0.3;
  d.max_speed_share_of_body = 0.0;
  return d;
}

constexpr double kMinStandingShare = 0.02;

}  // namespace

Result<DatabaseContacts> FindDatabaseContacts(const MotionDatabase& db, const std::vector<std::uint8_t>& eligible) {
  std::vector<int> joints;
  for (int j = 0; j < db.num_joints(); ++j)
    if (j < static_cast<int>(eligible.size()) && eligible[j]) joints.push_back(j);
  Eigen::MatrixXf down = Eigen::MatrixXf::Zero(db.num_frames(), joints.size());
  std::vector<std::vector<double>> heights(joints.size());
  const ContactDetection detection = CaptureDetection();
  const int nj = db.num_joints();
  for (int c = 0; c < db.num_clips(); ++c) {
    ASSIGN_OR_RETURN(const MotionClip clip, ReconstructClip(db, c));
    const std::vector<Eigen::Vector3d> p = ComputeWorldPositions(db.skeleton(), clip);
    std::vector<double> times(clip.num_frames);
    for (int f = 0; f < clip.num_frames; ++f) times[f] = clip.time_s(f);
    std::vector<Eigen::Vector3d> track(clip.num_frames);
    for (size_t k = 0; k < joints.size(); ++k) {
      double floor = INFINITY;
      for (int f = 0; f < clip.num_frames; ++f) {
        track[f] = p[size_t(f) * nj + joints[k]];
        floor = std::min(floor, track[f].y());
      }
      const std::vector<bool> standing = DetectContacts(track, times, floor, detection);
      for (int f = 0; f < clip.num_frames; ++f) {
        down(db.clip(c).first_frame + f, k) = standing[f] ? 1.0f : 0.0f;
        if (standing[f]) heights[k].push_back(track[f].y());
      }
    }
  }
  // Joints that hardly ever stand (knees of the few kneeling takes) are not planted.
  DatabaseContacts out;
  std::vector<int> kept;
  for (size_t k = 0; k < joints.size(); ++k)
    if (down.col(k).mean() >= kMinStandingShare) kept.push_back(static_cast<int>(k));
  out.down.resize(down.rows(), kept.size());
  for (size_t i = 0; i < kept.size(); ++i) {
    out.joints.push_back(joints[kept[i]]);
    out.down.col(i) = down.col(kept[i]);
    out.standing_height_m.push_back(UpperMedian(std::move(heights[kept[i]])));
  }
  return out;
}

std::vector<SynthesizedContacts> VotedContacts(const MotionDatabase& db, const DatabaseContacts& contacts,
                                               const std::vector<int>& columns, const Eigen::MatrixXd& votes) {
  std::vector<SynthesizedContacts> out;
  const int frames = static_cast<int>(votes.rows());
  std::vector<double> times(frames);
  for (int f = 0; f < frames; ++f) times[f] = f / db.rate_hz();
  for (int k : columns) {
    std::vector<bool> standing(frames);
    for (int f = 0; f < frames; ++f) standing[f] = votes(f, k) >= 0.5;
    TidyContacts(times, CaptureDetection(), standing);
    SynthesizedContacts c{db.skeleton().name(contacts.joints[k]), contacts.joints[k], {}, contacts.standing_height_m[k]};
    for (const auto& [first, last] : ContactRuns(standing)) c.runs.push_back({first, last});
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace mocapfill
