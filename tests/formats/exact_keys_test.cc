// Exact key times and values: glTF sketches keyed at 24 Hz, 60 Hz and irregular times keep
// their keys through import (JointKeys::rotation_times_s / values); a clip with explicit
// frame times is written as a glTF time accessor and re-imports with the same times; key
// fidelity is measured at the keys' own times; BVH refuses a non-uniform clip.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "processing/motion/key_fidelity.h"
#include "processing/motion/resample.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

constexpr double kDegPerRadian = 180.0 / 3.14159265358979323846;

double Degrees(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.normalized().angularDistance(b.normalized()) * kDegPerRadian;
}

std::string OutPath(const std::string& name) { return testing::TestOutputDir("exact_keys") + "/" + name; }

Scene ShippedSketch() {
  Result<Scene> scene = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips.size(), 1u);
  return std::move(*scene);
}

// A sketch file keyed at `times` (s): every joint keyed in the shipped sketch gets a LINEAR
// rotation channel (and translation where it has translation keys) with the shipped clip's
// pose at time * stretch, written with tinygltf (not our writer). Returns the float32 times
// and, per joint name, the float32 rotation values as written.
struct WrittenSketch {
  std::vector<float> times;
  std::map<std::string, std::vector<float>> rotations;
  std::map<std::string, std::vector<float>> translations;
};

WrittenSketch WriteSketch(const Scene& source, const std::vector<double>& times, const std::string& path) {
  const Skeleton& skel = source.skeleton;
  const MotionClip& clip = source.clips[0];
  const double stretch = clip.duration_s() / times.back();
  testing::SketchGltf gltf;
  WrittenSketch written;
  for (double t : times) written.times.push_back(static_cast<float>(t));
  for (int j = 0; j < skel.num_joints(); ++j) {
    const Eigen::Vector3d& r = skel.joint(j).rest_translation;
    EXPECT_EQ(gltf.AddNode(skel.name(j), skel.parent(j), {r.x(), r.y(), r.z()}), j);
  }
  for (int j = 0; j < skel.num_joints(); ++j) {
    if (clip.keys[j].empty()) continue;
    std::vector<float>& rot = written.rotations[skel.name(j)];
    for (double t : times) {
      const Eigen::Quaterniond q = SampleRotationAt(clip, j, t * stretch);
      for (double c : {q.x(), q.y(), q.z(), q.w()}) rot.push_back(static_cast<float>(c));
    }
    gltf.AddChannel("sketch", j, "rotation", written.times, rot);
    if (!clip.keys[j].translation_frames.empty()) {
      std::vector<float>& tr = written.translations[skel.name(j)];
      for (double t : times) {
        const Eigen::Vector3d v = SampleTranslationAt(clip, j, t * stretch);
        for (double c : {v.x(), v.y(), v.z()}) tr.push_back(static_cast<float>(c));
      }
      gltf.AddChannel("sketch", j, "translation", written.times, tr);
    }
  }
  EXPECT_TRUE(gltf.Write(path));
  return written;
}

// The keyed joints of `scene` hold exactly the written key times and values.
void ExpectExactKeys(const Scene& scene, const WrittenSketch& written) {
  const MotionClip& clip = scene.clips[0];
  int joints = 0;
  for (const auto& [name, rot] : written.rotations) {
    const auto j = scene.skeleton.Find(name);
    ASSERT_TRUE(j) << name;
    const JointKeys& k = clip.keys[*j];
    ASSERT_EQ(k.rotation_times_s.size(), written.times.size()) << name;
    ASSERT_EQ(k.rotation_values.size(), written.times.size()) << name;
    for (size_t i = 0; i < written.times.size(); ++i) {
      EXPECT_EQ(k.rotation_times_s[i], static_cast<double>(written.times[i])) << name << " key " << i;
      const Eigen::Quaterniond expected(rot[4 * i + 3], rot[4 * i], rot[4 * i + 1], rot[4 * i + 2]);
      EXPECT_LT(Degrees(k.rotation_values[i], expected), 1e-5) << name << " key " << i;
    }
    if (const auto t = written.translations.find(name); t != written.translations.end()) {
      ASSERT_EQ(k.translation_times_s.size(), written.times.size()) << name;
      for (size_t i = 0; i < written.times.size(); ++i) {
        EXPECT_EQ(k.translation_times_s[i], static_cast<double>(written.times[i]));
        EXPECT_LT((k.translation_values[i] - Eigen::Vector3d(t->second[3 * i], t->second[3 * i + 1], t->second[3 * i + 2]))
                      .norm(),
                  1e-7);
      }
    }
    ++joints;
  }
  EXPECT_GT(joints, 0);
}

std::vector<double> IrregularTimes() {
  return {0.0, 0.137, 0.29, 0.5013, 0.77, 1.033, 1.21, 1.4871, 1.9, 2.05, 2.333};
}

// A clip with explicit frame times: one frame per key time of `sketch` (irregular), the
// keyed joints holding their exact key values there and the others the sketch's grid clip
// sampled at those times; keyed joints keyed at every frame.
MotionClip NonUniformFromSketch(const Scene& sketch) {
  const MotionClip& grid = sketch.clips[0];
  std::vector<double> times;
  for (const JointKeys& k : grid.keys)
    if (k.has_exact_rotations()) {
      times = k.rotation_times_s;
      break;
    }
  EXPECT_FALSE(times.empty());
  MotionClip out = MotionClip::RestPose(sketch.skeleton, static_cast<int>(times.size()), grid.sample_rate_hz);
  out.name = "nonuniform";
  out.frame_times_s = times;
  out.frame_times_s[0] = 0.0;
  out.translation_animated = grid.translation_animated;
  for (int f = 0; f < out.num_frames; ++f)
    for (int j = 0; j < out.num_joints; ++j) {
      out.rotation(f, j) = SampleRotationAt(grid, j, times[f]);
      out.translation(f, j) = SampleTranslationAt(grid, j, times[f]);
    }
  for (int j = 0; j < out.num_joints; ++j) {
    const JointKeys& k = grid.keys[j];
    if (k.empty()) continue;
    for (size_t i = 0; i < k.rotation_values.size(); ++i) {
      EXPECT_EQ(k.rotation_times_s[i], times[i]);
      out.rotation(static_cast<int>(i), j) = k.rotation_values[i];
      out.keys[j].rotation_frames.push_back(static_cast<int>(i));
    }
    for (size_t i = 0; i < k.translation_values.size(); ++i) {
      out.translation(static_cast<int>(i), j) = k.translation_values[i];
      out.keys[j].translation_frames.push_back(static_cast<int>(i));
    }
  }
  out.MakeContinuous();
  EXPECT_TRUE(out.Validate(sketch.skeleton).ok());
  return out;
}

TEST(ExactKeysTest, ShippedSketchKeepsExactKeysOnItsGrid) {
  const Scene scene = ShippedSketch();
  const MotionClip& clip = scene.clips[0];
  int keyed = 0;
  for (int j = 0; j < clip.num_joints; ++j) {
    const JointKeys& k = clip.keys[j];
    if (k.rotation_frames.empty()) {
      EXPECT_TRUE(k.rotation_times_s.empty());
      continue;
    }
    ++keyed;
    // Keys on the grid: one exact key per keyed frame, at that frame's time, with its value.
    ASSERT_EQ(k.rotation_times_s.size(), k.rotation_frames.size());
    for (size_t i = 0; i < k.rotation_frames.size(); ++i) {
      EXPECT_NEAR(k.rotation_times_s[i], clip.time_s(k.rotation_frames[i]), 1e-6);
      EXPECT_LT(Degrees(k.rotation_values[i], clip.rotation(k.rotation_frames[i], j)), 1e-4);
    }
  }
  EXPECT_GT(keyed, 0);
  Result<KeyErrors> errors = MeasureKeyErrors(scene.skeleton, clip, clip);
  ASSERT_TRUE(errors.ok()) << errors.status().message();
  EXPECT_GT(errors->rotation_count, 0);
  EXPECT_LT(errors->rotation_max_deg, 1e-4);
  EXPECT_LT(errors->translation_max_m, 1e-6);
}

TEST(ExactKeysTest, SketchKeyedAt24HzKeepsTimesAndValues) {
  const Scene source = ShippedSketch();
  std::vector<double> times;
  for (int k = 0; k <= 12; ++k) times.push_back(k * 5 / 24.0);
  const std::string path = OutPath("sketch_keys_24hz.gltf");
  const WrittenSketch written = WriteSketch(source, times, path);
  Result<Scene> scene = ImportFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips[0].sample_rate_hz, 24.0);
  ExpectExactKeys(*scene, written);
  Result<KeyErrors> errors = MeasureKeyErrors(scene->skeleton, scene->clips[0], scene->clips[0]);
  ASSERT_TRUE(errors.ok());
  EXPECT_LT(errors->rotation_max_deg, 1e-4);  // every key time is a frame of the grid
}

TEST(ExactKeysTest, SketchKeyedAt60HzKeepsTimesAndValues) {
  const Scene source = ShippedSketch();
  std::vector<double> times;
  for (int k = 0; k <= 15; ++k) times.push_back(k * 7 / 60.0);  // fits no grid below 60 Hz
  const std::string path = OutPath("sketch_keys_60hz.gltf");
  const WrittenSketch written = WriteSketch(source, times, path);
  Result<Scene> scene = ImportFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips[0].sample_rate_hz, 60.0);
  ExpectExactKeys(*scene, written);
}

TEST(ExactKeysTest, SketchKeyedAtIrregularTimesKeepsTimesAndValues) {
  const Scene source = ShippedSketch();
  const std::string path = OutPath("sketch_keys_irregular.gltf");
  const WrittenSketch written = WriteSketch(source, IrregularTimes(), path);
  Result<Scene> scene = ImportFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips[0].sample_rate_hz, 30.0);  // no grid fits: 30 Hz, with a warning
  EXPECT_FALSE(scene->warnings.empty());
  ExpectExactKeys(*scene, written);
  // The 30 Hz grid misses the keys: measured at the keys' own times, the grid clip is off
  // (this is what a report at resampled frames hid).
  Result<KeyErrors> errors = MeasureKeyErrors(scene->skeleton, scene->clips[0], scene->clips[0]);
  ASSERT_TRUE(errors.ok());
  EXPECT_GT(errors->rotation_count, 0);
  std::cout << "irregular sketch on its 30 Hz grid: key error max " << errors->rotation_max_deg << " deg, mean "
            << errors->rotation_mean_deg << " deg over " << errors->rotation_count << " keys\n";
}

TEST(ExactKeysTest, NonUniformClipWritesItsTimesAndReimports) {
  const Scene source = ShippedSketch();
  const std::string sketch_path = OutPath("nonuniform_source.gltf");
  WriteSketch(source, IrregularTimes(), sketch_path);
  Result<Scene> sketch = ImportFile(sketch_path);
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  Scene scene = *sketch;
  scene.clips = {NonUniformFromSketch(*sketch)};
  const MotionClip& clip = scene.clips[0];
  ASSERT_FALSE(clip.uniform());

  // The non-uniform clip holds the sketch's keys exactly at their times.
  Result<KeyErrors> exact = MeasureKeyErrors(scene.skeleton, clip, sketch->clips[0]);
  ASSERT_TRUE(exact.ok()) << exact.status().message();
  EXPECT_GT(exact->rotation_count, 0);
  EXPECT_LT(exact->rotation_max_deg, 1e-4);
  EXPECT_LT(exact->translation_max_m, 1e-6);

  for (const std::string name : {"nonuniform.glb", "nonuniform.gltf"}) {
    SCOPED_TRACE(name);
    const std::string path = OutPath(name);
    ASSERT_TRUE(ExportFile(scene, path).ok());
    Result<Scene> back = ImportFile(path);
    ASSERT_TRUE(back.ok()) << back.status().message();
    ASSERT_EQ(back->clips.size(), 1u);
    const MotionClip& b = back->clips[0];
    EXPECT_TRUE(b.uniform());  // imported onto the grid of the recorded rate
    for (int j = 0; j < clip.num_joints; ++j) {
      const JointKeys& k = b.keys[j];
      const JointKeys& original = clip.keys[j];
      ASSERT_EQ(k.rotation_frames.empty(), original.rotation_frames.empty()) << scene.skeleton.name(j);
      if (original.rotation_frames.empty()) continue;
      ASSERT_EQ(k.rotation_times_s.size(), original.rotation_frames.size());
      for (size_t i = 0; i < original.rotation_frames.size(); ++i) {
        const int f = original.rotation_frames[i];
        EXPECT_EQ(k.rotation_times_s[i], static_cast<double>(static_cast<float>(clip.time_s(f))));
        EXPECT_LT(Degrees(k.rotation_values[i], clip.rotation(f, j)), 1e-4);
      }
      ASSERT_EQ(k.translation_times_s.size(), original.translation_frames.size());
      for (size_t i = 0; i < original.translation_frames.size(); ++i) {
        const int f = original.translation_frames[i];
        EXPECT_EQ(k.translation_times_s[i], static_cast<double>(static_cast<float>(clip.time_s(f))));
        EXPECT_LT((k.translation_values[i] - clip.translation(f, j)).norm(), 1e-6);
      }
    }
    // Measured against the re-imported exact keys, the written clip is exact too.
    Result<KeyErrors> again = MeasureKeyErrors(back->skeleton, clip, scene.skeleton, b);
    ASSERT_TRUE(again.ok());
    EXPECT_LT(again->rotation_max_deg, 1e-4);
  }

  // The time accessor of the .gltf: the explicit times as float32, with min and max.
  std::ifstream in(OutPath("nonuniform.gltf"));
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json json = nlohmann::json::parse(text.str());
  const int input = json["animations"][0]["samplers"][0]["input"];
  const nlohmann::json& accessor = json["accessors"][input];
  EXPECT_EQ(accessor["count"], clip.num_frames);
  EXPECT_EQ(accessor["min"][0].get<double>(), 0.0);
  EXPECT_EQ(accessor["max"][0].get<double>(), static_cast<double>(static_cast<float>(clip.frame_times_s.back())));
  EXPECT_EQ(json["asset"]["extras"]["mocapfill"]["clips"][0]["frame_times"], "explicit");
}

TEST(ExactKeysTest, MeasureKeyErrorsDetectsOneDegreeAtAKey) {
  const Scene source = ShippedSketch();
  const std::string sketch_path = OutPath("perturbed_source.gltf");
  WriteSketch(source, IrregularTimes(), sketch_path);
  Result<Scene> sketch = ImportFile(sketch_path);
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  MotionClip clip = NonUniformFromSketch(*sketch);
  int joint = -1;
  for (int j = 0; j < clip.num_joints && joint < 0; ++j)
    if (!clip.keys[j].rotation_frames.empty()) joint = j;
  ASSERT_GE(joint, 0);
  const int frame = 4;
  clip.rotation(frame, joint) =
      (clip.rotation(frame, joint) * Eigen::Quaterniond(Eigen::AngleAxisd(1.0 / kDegPerRadian, Eigen::Vector3d::UnitX())))
          .normalized();
  Result<KeyErrors> errors = MeasureKeyErrors(sketch->skeleton, clip, sketch->clips[0]);
  ASSERT_TRUE(errors.ok());
  EXPECT_NEAR(errors->rotation_max_deg, 1.0, 1e-3);
  for (const KeyError& e : errors->joints) {
    if (e.joint == sketch->skeleton.name(joint)) {
      EXPECT_NEAR(e.rotation_max_deg, 1.0, 1e-3);
      EXPECT_NEAR(e.rotation_max_at_s, clip.time_s(frame), 1e-9);
    } else {
      EXPECT_LT(e.rotation_max_deg, 1e-4) << e.joint;
    }
  }
}

TEST(ExactKeysTest, SamplingAtTimesMatchesFramesAndSlerp) {
  const Scene scene = ShippedSketch();
  const MotionClip& clip = scene.clips[0];
  for (int j = 0; j < clip.num_joints; ++j) {
    for (int f : {0, 1, clip.num_frames / 2, clip.num_frames - 1}) {
      EXPECT_LT(Degrees(SampleRotationAt(clip, j, clip.time_s(f)), clip.rotation(f, j)), 1e-9);
      EXPECT_LT((SampleTranslationAt(clip, j, clip.time_s(f)) - clip.translation(f, j)).norm(), 1e-12);
    }
    const double mid = 0.5 * (clip.time_s(3) + clip.time_s(4));
    EXPECT_LT(Degrees(SampleRotationAt(clip, j, mid), clip.rotation(3, j).slerp(0.5, clip.rotation(4, j))), 1e-9);
    // Clamped ends.
    EXPECT_LT(Degrees(SampleRotationAt(clip, j, -1.0), clip.rotation(0, j)), 1e-9);
    EXPECT_LT(Degrees(SampleRotationAt(clip, j, 1e6), clip.rotation(clip.num_frames - 1, j)), 1e-9);
  }
  // The same clip with its times made explicit samples the same.
  MotionClip explicit_times = clip;
  for (int f = 0; f < clip.num_frames; ++f) explicit_times.frame_times_s.push_back(clip.time_s(f));
  ASSERT_TRUE(explicit_times.Validate(scene.skeleton).ok());
  for (double t : {0.0, 0.011, 0.5, 1.234, clip.duration_s()})
    for (int j = 0; j < clip.num_joints; ++j)
      EXPECT_LT(Degrees(SampleRotationAt(explicit_times, j, t), SampleRotationAt(clip, j, t)), 1e-9);
}

TEST(ExactKeysTest, ResampleBringsANonUniformClipOntoAGrid) {
  const Scene source = ShippedSketch();
  const std::string sketch_path = OutPath("resample_source.gltf");
  WriteSketch(source, IrregularTimes(), sketch_path);
  Result<Scene> sketch = ImportFile(sketch_path);
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  const MotionClip clip = NonUniformFromSketch(*sketch);
  ResampleOptions options;
  options.rate_hz = 30.0;
  options.translation = TranslationInterpolation::kLinear;
  Result<MotionClip> out = ResampleClip(clip, options);
  ASSERT_TRUE(out.ok()) << out.status().message();
  EXPECT_TRUE(out->uniform());
  EXPECT_EQ(out->num_frames, static_cast<int>(std::floor(IrregularTimes().back() * 30 + 1e-6)) + 1);
  EXPECT_TRUE(out->Validate(sketch->skeleton).ok());
  for (int f = 0; f < out->num_frames; ++f)
    for (int j = 0; j < out->num_joints; ++j) {
      EXPECT_LT(Degrees(out->rotation(f, j), SampleRotationAt(clip, j, f / 30.0)), 1e-6);
      EXPECT_LT((out->translation(f, j) - SampleTranslationAt(clip, j, f / 30.0)).norm(), 1e-9);
    }
  // Keys land on the frames nearest their times (the last one on the last frame: the grid
  // stops at 2.3 s, before the last key at 2.333 s, as a resampled clip never gains time).
  for (int j = 0; j < clip.num_joints; ++j) {
    ASSERT_EQ(out->keys[j].rotation_frames.size(), clip.keys[j].rotation_frames.size());
    for (size_t i = 0; i < out->keys[j].rotation_frames.size(); ++i) {
      const double time = clip.time_s(clip.keys[j].rotation_frames[i]);
      const int expected = std::min(static_cast<int>(std::lround(time * 30.0)), out->num_frames - 1);
      EXPECT_EQ(out->keys[j].rotation_frames[i], expected) << "key at " << time << " s";
    }
  }
  EXPECT_EQ(RequireUniform(clip, "filter").code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(RequireUniform(*out, "filter").ok());
}

TEST(ExactKeysTest, BvhRefusesANonUniformClip) {
  const Scene source = ShippedSketch();
  const std::string sketch_path = OutPath("bvh_refusal_source.gltf");
  WriteSketch(source, IrregularTimes(), sketch_path);
  Result<Scene> sketch = ImportFile(sketch_path);
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  Scene scene = *sketch;
  scene.clips = {NonUniformFromSketch(*sketch)};
  const std::string path = testing::ScratchDir("ExactKeysBvh") + "/nonuniform.bvh";
  const Status status = ExportFile(scene, path);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(status.message().find("BVH holds uniformly sampled frames only"), std::string::npos) << status.message();
  EXPECT_FALSE(std::ifstream(path).good());  // nothing written
}

TEST(ExactKeysTest, FbxKeysAreExactAtTheirTimes) {
  Result<Scene> scene = ImportFile(testing::FixturePath("fbx/animation_with_skeleton.fbx"));
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_FALSE(scene->clips.empty());
  const MotionClip& clip = scene->clips[0];
  int keys = 0;
  for (int j = 0; j < clip.num_joints; ++j) {
    const JointKeys& k = clip.keys[j];
    ASSERT_EQ(k.rotation_times_s.size(), k.rotation_values.size());
    for (size_t i = 0; i < k.rotation_times_s.size(); ++i) {
      // Keys on the grid must agree with the clip's frame there.
      const double u = k.rotation_times_s[i] * clip.sample_rate_hz;
      if (std::abs(u - std::round(u)) > 1e-6 || std::round(u) >= clip.num_frames) continue;
      EXPECT_LT(Degrees(k.rotation_values[i], clip.rotation(static_cast<int>(std::round(u)), j)), 1e-6);
      ++keys;
    }
  }
  EXPECT_GT(keys, 0);
}

}  // namespace
}  // namespace mocapfill
