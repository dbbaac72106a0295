// The float32 packing of rotations (gltf_tracks.h): PackRotation is Eigen's normalized() and
// dot() written out, bit for bit, and PackRotations (four lanes at a time with AVX2) gives
// PackRotation's bits, hemisphere flips and signed zeros included.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>
#include <random>
#include <vector>

#include "formats/gltf/gltf_tracks.h"

namespace mocapfill {
namespace {

// The reference PackRotation must match bit for bit: Eigen's own expressions.
void PackWithEigen(const Eigen::Quaterniond& q, Eigen::Vector4d& previous, float* out) {
  Eigen::Vector4d v(q.x(), q.y(), q.z(), q.w());
  if (std::abs(v.squaredNorm() - 1.0) > kRotationUnitTolerance) v.normalize();
  if (v.dot(previous) < 0) v = -v;
  previous = v;
  const Eigen::Vector4f rounded = v.cast<float>();
  for (int c = 0; c < 4; ++c) out[c] = rounded[c];
}

std::vector<Eigen::Quaterniond> Samples() {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  std::vector<Eigen::Quaterniond> q;
  for (int n = 0; n < 200000; ++n) {
    Eigen::Quaterniond r;
    for (int c = 0; c < 4; ++c) r.coeffs()[c] = normal(rng);  // in order: argument order is the compiler's
    if (n % 3 == 0) r.coeffs() *= scale(rng);  // not unit: fills and imports may give these
    if (n % 5 == 1) r.normalize();              // unit to an ulp or two, as composed rotations are
    if (n % 35 == 11) r.coeffs() *= n % 2 != 0 ? 1.0 + 1e-13 : 1.0 + 1e-11;  // just inside, just outside the tolerance
    if (n % 17 == 0) r.coeffs()[n % 4] = 0.0;
    if (n % 19 == 0) r.coeffs()[(n + 1) % 4] = -0.0;
    q.push_back(r);
  }
  q.emplace_back(1.0, 0.0, 0.0, 0.0);
  q.emplace_back(0.0, 0.0, 0.0, 0.0);  // left as it is, as Eigen leaves it
  return q;
}

TEST(GltfTracks, PackRotationIsEigensExpressionsBitForBit) {
  const std::vector<Eigen::Quaterniond> q = Samples();
  Eigen::Vector4d previous_a = Eigen::Vector4d::Zero(), previous_b = Eigen::Vector4d::Zero();
  for (const Eigen::Quaterniond& r : q) {
    float a[4], b[4];
    PackRotation(r, previous_a, a);
    PackWithEigen(r, previous_b, b);
    ASSERT_EQ(std::memcmp(a, b, sizeof(a)), 0) << r.coeffs().transpose();
    ASSERT_EQ(std::memcmp(previous_a.data(), previous_b.data(), 4 * sizeof(double)), 0);
  }
}

TEST(GltfTracks, PackRotationsIsPackRotationJointByJoint) {
  const std::vector<Eigen::Quaterniond> q = Samples();
  for (size_t joints : {size_t{1}, size_t{3}, size_t{22}, size_t{31}}) {
    const size_t frames = q.size() / joints, stride = 4 * frames;
    std::vector<float> batch(stride * joints), single(stride * joints);
    std::vector<Eigen::Vector4d> previous_batch(joints, Eigen::Vector4d::Zero()), previous_single = previous_batch;
    for (size_t f = 0; f < frames; ++f) {
      PackRotations(&q[f * joints], joints, previous_batch.data(), batch.data() + 4 * f, stride);
      for (size_t j = 0; j < joints; ++j) PackRotation(q[f * joints + j], previous_single[j], single.data() + j * stride + 4 * f);
    }
    EXPECT_EQ(std::memcmp(batch.data(), single.data(), batch.size() * sizeof(float)), 0) << joints;
    EXPECT_EQ(std::memcmp(previous_batch.data(), previous_single.data(), joints * sizeof(Eigen::Vector4d)), 0) << joints;
  }
}

// PackListedRotations packs exactly the listed joints, as PackRotation would, and leaves the
// others' floats and previous values alone; zero quaternions are among the packed ones.
TEST(GltfTracks, PackListedRotationsPacksOnlyTheListedJoints) {
  std::vector<Eigen::Quaterniond> q = Samples();
  const size_t joints = 31, frames = q.size() / joints, stride = 4 * frames;
  for (size_t f = 0; f < frames; f += 7) q[f * joints + f % joints].coeffs().setZero();
  std::vector<float> listed(stride * joints, -7.0f), single(stride * joints, -7.0f);
  std::vector<Eigen::Vector4d> previous_listed(joints, Eigen::Vector4d::Zero()), previous_single = previous_listed;
  std::mt19937 rng(5);
  size_t packed = 0;
  for (size_t f = 0; f < frames; ++f) {
    std::vector<uint32_t> list;
    for (uint32_t j = 0; j < joints; ++j)
      if (f == 0 || rng() % 4 != 0) list.push_back(j);  // a quarter of the joints left out
    PackListedRotations(&q[f * joints], list.data(), list.size(), previous_listed.data(), listed.data() + 4 * f, stride);
    for (const uint32_t j : list) PackRotation(q[f * joints + j], previous_single[j], single.data() + j * stride + 4 * f);
    packed += list.size();
  }
  EXPECT_LT(packed, joints * frames * 9 / 10);
  EXPECT_EQ(std::memcmp(listed.data(), single.data(), listed.size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(previous_listed.data(), previous_single.data(), joints * sizeof(Eigen::Vector4d)), 0);
}

}  // namespace
}  // namespace mocapfill
