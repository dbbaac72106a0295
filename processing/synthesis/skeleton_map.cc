#include "processing/synthesis/skeleton_map.h"

namespace mocapfill {

namespace {

bool IsAncestor(const Skeleton& skeleton, int ancestor, int joint) {
  for (int p = skeleton.parent(joint); p != kNoParent; p = skeleton.parent(p))
    if (p == ancestor) return true;
  return false;
}

std::string FirstNames(const Skeleton& skeleton, int count) {
  std::string names;
  for (int j = 0; j < std::min(count, skeleton.num_joints()); ++j) names += (j ? ", " : "") + skeleton.name(j);
  return names + (skeleton.num_joints() > count ? ", ..." : "");
}

}  // namespace

Result<SkeletonMapping> MapSkeletons(const Skeleton& sketch, const MotionClip& sketch_clip, const Skeleton& database,
                                     const std::map<std::string, std::string>& rename) {
  SkeletonMapping m;
  m.db_to_sketch.assign(database.num_joints(), -1);
  m.sketch_to_db.assign(sketch.num_joints(), -1);
  int mapped = 0;
  for (int j = 0; j < sketch.num_joints(); ++j) {
    const auto renamed = rename.find(sketch.name(j));
    const std::string& name = renamed == rename.end() ? sketch.name(j) : renamed->second;
    const std::optional<int> d = database.Find(name);
    const bool keyed = j < static_cast<int>(sketch_clip.keys.size()) && !sketch_clip.keys[j].empty();
    if (!d) {
      if (keyed)
        return InvalidData("keyed joint '" + sketch.name(j) +
                           "' is not in the database skeleton; rename it with --map JSON or drop its keys");
      m.warnings.push_back("joint '" + sketch.name(j) + "' is not in the database; kept as sketched");
      continue;
    }
    if (m.db_to_sketch[*d] >= 0)
      return InvalidData("joints '" + sketch.name(m.db_to_sketch[*d]) + "' and '" + sketch.name(j) +
                         "' both map to database joint '" + name + "'");
    m.db_to_sketch[*d] = j;
    m.sketch_to_db[j] = *d;
    ++mapped;
  }
  if (mapped == 0)
    return InvalidData("no sketch joint matches the database skeleton (sketch joints: " + FirstNames(sketch, 6) +
                       "; database joints: " + FirstNames(database, 6) + "); give --map JSON to rename them");
  for (int d = 0; d < database.num_joints(); ++d) {
    const int s = m.db_to_sketch[d];
    int p = database.parent(d);
    while (p != kNoParent && m.db_to_sketch[p] < 0) p = database.parent(p);
    if (s < 0 || p == kNoParent) continue;
    if (!IsAncestor(sketch, m.db_to_sketch[p], s))
      return InvalidData("mismatched skeleton: sketch joint '" + sketch.name(s) + "' is not below '" +
                         sketch.name(m.db_to_sketch[p]) + "' as database joint '" + database.name(d) +
                         "' is below '" + database.name(p) + "'; give --map JSON to match the skeletons");
  }
  return m;
}

MotionClip ToDatabaseClip(const SkeletonMapping& mapping, const Skeleton& database, const MotionClip& sketch_clip) {
  MotionClip clip = MotionClip::RestPose(database, sketch_clip.num_frames, sketch_clip.sample_rate_hz);
  clip.name = sketch_clip.name;
  for (int d = 0; d < database.num_joints(); ++d) {
    const int s = mapping.db_to_sketch[d];
    if (s < 0) continue;
    for (int f = 0; f < clip.num_frames; ++f) {
      clip.rotation(f, d) = sketch_clip.rotation(f, s);
      if (sketch_clip.translation_animated[s]) clip.translation(f, d) = sketch_clip.translation(f, s);
    }
    clip.translation_animated[d] = sketch_clip.translation_animated[s];
    clip.keys[d] = sketch_clip.keys[s];
    if (!sketch_clip.translation_animated[s]) {
      clip.keys[d].translation_frames.clear();
      clip.keys[d].translation_times_s.clear();
      clip.keys[d].translation_values.clear();
    }
  }
  clip.MakeContinuous();
  return clip;
}

MotionClip ToSketchClip(const SkeletonMapping& mapping, const MotionClip& filled, const MotionClip& sketch_clip,
                        int database_root_joint) {
  MotionClip out = sketch_clip;
  for (int s = 0; s < out.num_joints; ++s) {
    const int d = mapping.sketch_to_db[s];
    if (d < 0) continue;
    for (int f = 0; f < out.num_frames; ++f) {
      out.rotation(f, s) = filled.rotation(f, d);
      if (d == database_root_joint) out.translation(f, s) = filled.translation(f, d);
    }
  }
  out.MakeContinuous();
  out.KeyAllFrames();
  return out;
}

}  // namespace mocapfill
