#include "tests/formats/bvh_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "formats/bvh/bvh_reader.h"
#include "processing/core/rotation.h"
#include "tests/support/test_paths.h"

namespace mocapfill::testing {

Result<Scene> ReadFixture(const std::string& name, const ImportOptions& options) {
  const std::string path = FixturePath("bvh/" + name);
  return ReadBvh(ReadText(path), path, options);
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string EnlargeMotion(const std::string& text, size_t min_bytes, int frames_delta) {
  const size_t frame_time = text.find("Frame Time");
  const size_t rows_begin = text.find('\n', frame_time) + 1;
  std::string rows = text.substr(rows_begin);
  if (!rows.empty() && rows.back() != '\n') rows += '\n';
  const std::string eol = rows.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  int64_t per_copy = 0;
  for (size_t p = 0; (p = rows.find('\n', p)) != std::string::npos; ++p) ++per_copy;
  std::string motion;
  int64_t frames = 0;
  while (motion.size() < min_bytes) {
    motion += rows;
    frames += per_copy;
  }
  const size_t frames_line = text.find("Frames:");
  const size_t frames_end = text.find('\n', frames_line);
  return text.substr(0, frames_line) + "Frames: " + std::to_string(frames + frames_delta) + eol +
         text.substr(frames_end + 1, rows_begin - frames_end - 1) + motion;
}

std::vector<std::vector<double>> MotionRows(const std::string& bvh_text) {
  std::string text = bvh_text;
  std::replace(text.begin(), text.end(), '\r', '\n');
  std::istringstream in(text.substr(text.find("Frame Time")));
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::vector<double> values;
    double v;
    while (row >> v) values.push_back(v);
    if (!values.empty()) rows.push_back(values);
  }
  return rows;
}

std::vector<std::vector<std::string>> ChannelLines(const std::string& bvh_text) {
  std::string text = bvh_text.substr(0, bvh_text.find("MOTION"));
  std::replace(text.begin(), text.end(), '\r', '\n');
  std::istringstream in(text);
  std::string line;
  std::vector<std::vector<std::string>> joints;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    int count = 0;
    if (!(words >> keyword) || keyword != "CHANNELS" || !(words >> count)) continue;
    std::vector<std::string> names(count);
    for (std::string& name : names) words >> name;
    joints.push_back(names);
  }
  return joints;
}

Eigen::Quaterniond RotationFromChannels(const std::vector<std::string>& channels, const double* values) {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (size_t c = 0; c < channels.size(); ++c) {
    if (channels[c].find("rotation") == std::string::npos) continue;
    const int axis = channels[c][0] - 'X';
    q = q * Eigen::AngleAxisd(values[c] * kPi / 180.0, Eigen::Vector3d::Unit(axis));
  }
  return q;
}

double MaxRotationChannelJumpDeg(const std::string& bvh_text) {
  std::vector<bool> is_rotation;
  for (const auto& joint : ChannelLines(bvh_text))
    for (const std::string& name : joint) is_rotation.push_back(name.find("rotation") != std::string::npos);
  const auto rows = MotionRows(bvh_text);
  double worst = 0.0;
  for (size_t f = 1; f < rows.size(); ++f) {
    EXPECT_EQ(rows[f].size(), is_rotation.size());
    for (size_t c = 0; c < is_rotation.size() && c < rows[f].size(); ++c)
      if (is_rotation[c]) worst = std::max(worst, std::abs(rows[f][c] - rows[f - 1][c]));
  }
  return worst;
}

MotionDifference CompareMotion(const Scene& a, const Scene& b) {
  MotionDifference d;
  const MotionClip& ca = a.clips.at(0);
  const MotionClip& cb = b.clips.at(0);
  EXPECT_EQ(ca.num_frames, cb.num_frames);
  for (int j = 0; j < a.skeleton.num_joints(); ++j) {
    const auto k = b.skeleton.Find(a.skeleton.name(j));
    EXPECT_TRUE(k.has_value()) << a.skeleton.name(j);
    if (!k) continue;
    for (int f = 0; f < std::min(ca.num_frames, cb.num_frames); ++f) {
      d.rotation_deg = std::max(d.rotation_deg, GeodesicAngle(ca.rotation(f, j), cb.rotation(f, *k)) * kDegPerRad);
      d.translation_m = std::max(d.translation_m, (ca.translation(f, j) - cb.translation(f, *k)).cwiseAbs().maxCoeff());
    }
  }
  return d;
}

void ExpectSameSkeleton(const Skeleton& a, const Skeleton& b, double tolerance_m) {
  ASSERT_EQ(a.num_joints(), b.num_joints());
  for (int j = 0; j < a.num_joints(); ++j) {
    const Joint& x = a.joint(j);
    const Joint& y = b.joint(j);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.parent, y.parent) << x.name;
    EXPECT_EQ(x.bvh_channels, y.bvh_channels) << x.name;
    EXPECT_LE((x.rest_translation - y.rest_translation).cwiseAbs().maxCoeff(), tolerance_m) << x.name;
    EXPECT_EQ(x.end_site.has_value(), y.end_site.has_value()) << x.name;
    if (x.end_site && y.end_site) {
      EXPECT_LE((*x.end_site - *y.end_site).cwiseAbs().maxCoeff(), tolerance_m) << x.name;
    }
    EXPECT_EQ(x.bvh_offset.has_value(), y.bvh_offset.has_value()) << x.name;
    if (x.bvh_offset && y.bvh_offset) {
      EXPECT_LE((*x.bvh_offset - *y.bvh_offset).cwiseAbs().maxCoeff(), tolerance_m) << x.name;
    }
  }
}

}  // namespace mocapfill::testing
