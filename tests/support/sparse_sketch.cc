#include "tests/support/sparse_sketch.h"

#include <cmath>

#include "processing/motion/key_fidelity.h"
#include "processing/sketch_fill/sketch_keys.h"
#include "tests/formats/gltf_test_support.h"

namespace mocapfill::testing {

bool WriteSparseSketch(const Skeleton& skeleton, const MotionClip& clip, const std::vector<std::string>& joints,
                       const std::vector<double>& key_times_s, const std::string& path) {
  SketchGltf gltf;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const Eigen::Vector3d& t = skeleton.joint(j).rest_translation;
    gltf.AddNode(skeleton.name(j), skeleton.parent(j), {t.x(), t.y(), t.z()});
  }
  std::vector<float> times(key_times_s.begin(), key_times_s.end());
  for (const std::string& name : joints) {
    const std::optional<int> j = skeleton.Find(name);
    if (!j) return false;
    std::vector<float> rotations, translations;
    for (double t : key_times_s) {
      const Eigen::Quaterniond q = SampleRotationAt(clip, *j, t);
      rotations.insert(rotations.end(), {float(q.x()), float(q.y()), float(q.z()), float(q.w())});
      const Eigen::Vector3d p = SampleTranslationAt(clip, *j, t);
      translations.insert(translations.end(), {float(p.x()), float(p.y()), float(p.z())});
    }
    gltf.AddChannel("sketch", *j, "rotation", times, rotations);
    if (clip.translation_animated[*j]) gltf.AddChannel("sketch", *j, "translation", times, translations);
  }
  return gltf.Write(path);
}

std::vector<double> EveryStep(double duration_s, double step_s) {
  std::vector<double> times;
  for (int k = 0; k * step_s <= duration_s + 1e-9; ++k) times.push_back(k * step_s);
  return times;
}

}  // namespace mocapfill::testing
