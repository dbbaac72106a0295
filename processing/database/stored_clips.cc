#include "processing/database/stored_clips.h"

#include <string>

namespace mocapfill {

ClipSignals ClipSignalsOf(const MotionDatabase& database, int clip_index) {
  const ClipRange& c = database.clip(clip_index);
  const Eigen::MatrixXd rows = database.ClipRows(database.signals(), clip_index).cast<double>();
  ClipSignals out;
  out.tangent = rows.leftCols(3 * database.num_joints());
  out.root_features = rows.rightCols(rows.cols() - 3 * database.num_joints());
  out.start_heading_rad = c.start_heading_rad;
  out.start_position_m = c.start_position_m;
  return out;
}

Result<MotionClip> ReconstructClip(const MotionDatabase& database, int clip_index) {
  if (clip_index < 0 || clip_index >= database.num_clips())
    return InvalidArgument("database has no clip " + std::to_string(clip_index));
  const MotionDatabase::Parts& parts = database.parts();
  const ClipRange& c = parts.clips[clip_index];
  MotionClip like = MotionClip::RestPose(database.skeleton(), c.num_frames, database.rate_hz());
  like.name = c.name;
  for (size_t i = 0; i < parts.translated_joints.size(); ++i) {
    const int j = parts.translated_joints[i];
    like.translation_animated[j] = 1;
    for (int f = 0; f < c.num_frames; ++f)
      like.translation(f, j) = parts.translations.block<1, 3>(c.first_frame + f, 3 * i).transpose().cast<double>();
  }
  if (database.root_joint() >= 0) like.translation_animated[database.root_joint()] = 1;
  like.KeyAllFrames();
  return ComposeClip(database.skeleton(), ClipSignalsOf(database, clip_index), database.reference(), like);
}

}  // namespace mocapfill
