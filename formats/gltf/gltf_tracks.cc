#include "formats/gltf/gltf_tracks.h"

#include "formats/fast_convert/cpu_avx2.h"

#if MOCAPFILL_AVX2_VARIANTS
#include <immintrin.h>
#endif

namespace mocapfill {

Status PackFrameTimes(const std::string& clip_name, size_t frames, double rate_hz, float* times) {
  for (size_t f = 0; f < frames; ++f) {
    times[f] = static_cast<float>(static_cast<double>(f) / rate_hz);
    if (f > 0 && times[f] <= times[f - 1])
      return Unsupported("clip '" + clip_name + "': frame times " + std::to_string(f - 1) + " and " +
                         std::to_string(f) + " are equal in float32; the clip is too long for its frame rate");
  }
  return OkStatus();
}

Status PackExplicitFrameTimes(const std::string& clip_name, const double* times_s, size_t frames, float* times) {
  for (size_t f = 0; f < frames; ++f) {
    times[f] = static_cast<float>(times_s[f]);
    if (f > 0 && times[f] <= times[f - 1])
      return Unsupported("clip '" + clip_name + "': frame times " + std::to_string(f - 1) + " and " +
                         std::to_string(f) + " (" + std::to_string(times_s[f - 1]) + " s and " +
                         std::to_string(times_s[f]) + " s) are equal in float32");
  }
  return OkStatus();
}

#if MOCAPFILL_AVX2_VARIANTS
namespace {

// (a0 + a2) + (a1 + a3) in every lane.
__attribute__((target("avx2"))) inline __m256d SumOfLanes(__m256d a) {
  const __m256d pairs = _mm256_add_pd(a, _mm256_permute2f128_pd(a, a, 0x01));  // (a0 + a2, a1 + a3, ...)
  return _mm256_add_pd(pairs, _mm256_permute_pd(pairs, 0x5));                   // + swapped within each half
}

// One joint's PackRotation in the four lanes of a register (x, y, z, w).
__attribute__((target("avx2"))) inline void PackOneAvx2(const Eigen::Quaterniond& q, Eigen::Vector4d& previous,
                                                      float* out) {
  __m256d v = _mm256_loadu_pd(q.coeffs().data());  // x, y, z, w
  const __m256d n2 = SumOfLanes(_mm256_mul_pd(v, v));
  if (const double length2 = _mm256_cvtsd_f64(n2); length2 > 0.0 && std::abs(length2 - 1.0) > kRotationUnitTolerance)
    v = _mm256_div_pd(v, _mm256_sqrt_pd(n2));
  const __m256d dot = SumOfLanes(_mm256_mul_pd(v, _mm256_loadu_pd(previous.data())));
  if (_mm256_cvtsd_f64(dot) < 0) v = _mm256_xor_pd(v, _mm256_set1_pd(-0.0));  // negation, zeros included
  _mm256_storeu_pd(previous.data(), v);
  _mm_storeu_ps(out, _mm256_cvtpd_ps(v));
}

// Joint i of the loop is joint_of(i).
template <class JointOf>
__attribute__((target("avx2"))) inline void PackRotationsAvx2(const Eigen::Quaterniond* q, size_t count, JointOf joint_of,
                                                            Eigen::Vector4d* previous, float* out, size_t stride) {
  for (size_t i = 0; i < count; ++i) {
    const size_t j = joint_of(i);
    PackOneAvx2(q[j], previous[j], out + j * stride);
  }
}

__attribute__((target("avx2"))) void PackAllAvx2(const Eigen::Quaterniond* q, size_t count, Eigen::Vector4d* previous,
                                               float* out, size_t stride) {
  PackRotationsAvx2(q, count, [](size_t i) { return i; }, previous, out, stride);
}

__attribute__((target("avx2"))) void PackListedAvx2(const Eigen::Quaterniond* q, const uint32_t* joints, size_t count,
                                                  Eigen::Vector4d* previous, float* out, size_t stride) {
  PackRotationsAvx2(q, count, [joints](size_t i) { return static_cast<size_t>(joints[i]); }, previous, out, stride);
}

}  // namespace
#endif

void PackRotations(const Eigen::Quaterniond* q, size_t count, Eigen::Vector4d* previous, float* out, size_t stride) {
#if MOCAPFILL_AVX2_VARIANTS
  if (CpuHasAvx2()) return PackAllAvx2(q, count, previous, out, stride);
#endif
  for (size_t j = 0; j < count; ++j) PackRotation(q[j], previous[j], out + j * stride);
}

void PackListedRotations(const Eigen::Quaterniond* q, const uint32_t* joints, size_t count, Eigen::Vector4d* previous,
                         float* out, size_t stride) {
#if MOCAPFILL_AVX2_VARIANTS
  if (CpuHasAvx2()) return PackListedAvx2(q, joints, count, previous, out, stride);
#endif
  for (size_t i = 0; i < count; ++i) PackRotation(q[joints[i]], previous[joints[i]], out + joints[i] * stride);
}

}  // namespace mocapfill
