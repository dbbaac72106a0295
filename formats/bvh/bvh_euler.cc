#include "formats/bvh/bvh_euler.h"

#include <cmath>
#include <cstdint>

#include "formats/fast_convert/cpu_avx2.h"

namespace mocapfill::bvh {

namespace {

// sin and cos of deg, for |deg| < 1e9: reduced exactly by multiples of 90 degrees, Taylor
// polynomials on [-45, 45] degrees, the quadrant picked with selects, which keeps it
// branch-free and lets the compiler vectorise a loop of it (SinCosDegreesBatch). Larger
// angles give something (their quadrant is taken as 0, so that no out-of-range conversion
// happens) that callers replace with libm's value.
[[gnu::always_inline]] inline void SinCosReduced(double deg, double& sine, double& cosine) {
  constexpr double kRoundingShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  const double quarter_turns = (deg * (1.0 / 90.0) + kRoundingShift) - kRoundingShift;
  const double x = (deg - 90.0 * quarter_turns) * kRadPerDeg;  // deg - 90 k is exact
  const double x2 = x * x;
  // Taylor series to x^15 / x^16: the next terms are below 1e-16 for |x| <= pi/4.
  const double s =
      x * (1.0 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880 + x2 * (-1.0 / 39916800 +
          x2 * (1.0 / 6227020800 + x2 * (-1.0 / 1307674368000))))))));
  const double c =
      1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 +
          x2 * (1.0 / 479001600 + x2 * (-1.0 / 87178291200 + x2 * (1.0 / 20922789888000))))))));
  // Quarter turn q maps (s, c) to (s, c), (c, -s), (-s, -c), (-c, s).
  const int q = static_cast<int>(std::abs(deg) < 1e9 ? quarter_turns : 0.0) & 3;
  const bool odd = (q & 1) != 0, sine_negative = (q & 2) != 0, cosine_negative = ((q + 1) & 2) != 0;
  sine = (odd ? c : s) * (sine_negative ? -1.0 : 1.0);
  cosine = (odd ? s : c) * (cosine_negative ? -1.0 : 1.0);
}

[[gnu::always_inline]] inline void SinCosDegreesInline(double deg, double& sine, double& cosine) {
  if (!(std::abs(deg) < 1e9)) {
    sine = std::sin(deg * kRadPerDeg);
    cosine = std::cos(deg * kRadPerDeg);
    return;
  }
  SinCosReduced(deg, sine, cosine);
}

// q * (c + s e_A) = (w c - s v_A,  c v + w s e_A + s (v x e_A)), written out for axis A.
template <int A>
inline void MultiplyByAxis(double& w, double (&v)[3], double c, double s) {
  constexpr int B = (A + 1) % 3, D = (A + 2) % 3;
  const double w0 = w, va = v[A], vb = v[B], vd = v[D];
  w = w0 * c - va * s;
  v[A] = va * c + w0 * s;
  v[B] = vb * c + vd * s;  // (v x e_A)_B = v_D
  v[D] = vd * c - vb * s;  // (v x e_A)_D = -v_B
}

// The rotation R_A0 R_A1 R_A2 from the sines and cosines of the three half angles.
template <int A0, int A1, int A2>
Eigen::Quaterniond ComposeHalfAngles(const double* s, const double* c) {
  double w = c[0], v[3] = {0.0, 0.0, 0.0};
  v[A0] = s[0];
  MultiplyByAxis<A1>(w, v, c[1], s[1]);
  MultiplyByAxis<A2>(w, v, c[2], s[2]);
  // Each factor has c^2 + s^2 = 1 to an ulp or two, so the product is unit to ~1e-15
  // and needs no normalising.
  return Eigen::Quaterniond(w, v[0], v[1], v[2]);
}

template <int A0, int A1, int A2>
Eigen::Quaterniond Compose(const std::array<double, 3>& angles_deg) {
  // Joints that never turn (CMU's fingers, a fifth of its values) skip the trigonometry;
  // the branch follows the joint, so it predicts well.
  if (angles_deg[0] == 0.0 && angles_deg[1] == 0.0 && angles_deg[2] == 0.0) return Eigen::Quaterniond::Identity();
  double s[3], c[3];
  for (int i = 0; i < 3; ++i) SinCosDegreesInline(0.5 * angles_deg[i], s[i], c[i]);
  return ComposeHalfAngles<A0, A1, A2>(s, c);
}

struct OrderFunctions {
  EulerComposer compose;
  HalfAngleComposer compose_half_angles;
};

template <int A0, int A1, int A2>
constexpr OrderFunctions kOrderFunctions{&Compose<A0, A1, A2>, &ComposeHalfAngles<A0, A1, A2>};

// The composers of one of the six Tait-Bryan orders (EulerOrder guarantees three distinct axes).
const OrderFunctions& FunctionsFor(const EulerOrder& order) {
  switch (order.axes[0] * 9 + order.axes[1] * 3 + order.axes[2]) {
    case 0 * 9 + 1 * 3 + 2: return kOrderFunctions<0, 1, 2>;
    case 0 * 9 + 2 * 3 + 1: return kOrderFunctions<0, 2, 1>;
    case 1 * 9 + 0 * 3 + 2: return kOrderFunctions<1, 0, 2>;
    case 1 * 9 + 2 * 3 + 0: return kOrderFunctions<1, 2, 0>;
    case 2 * 9 + 0 * 3 + 1: return kOrderFunctions<2, 0, 1>;
    default: return kOrderFunctions<2, 1, 0>;
  }
}

}  // namespace

void SinCosDegrees(double deg, double& sine, double& cosine) { SinCosDegreesInline(deg, sine, cosine); }

EulerComposer ComposerFor(const EulerOrder& order) { return FunctionsFor(order).compose; }

HalfAngleComposer HalfAngleComposerFor(const EulerOrder& order) { return FunctionsFor(order).compose_half_angles; }

namespace {

// SinCosDegrees of every angle, vectorised: SinCosReduced for all, then libm's value for
// the (rare) angles of 1e9 degrees and more, as SinCosDegrees gives them. Inlined into an
// AVX2 build and a plain x86-64 one, picked per call (cpu_avx2.h).
__attribute__((always_inline)) inline void SinCosDegreesLoop(const double* __restrict deg, size_t n,
                                                             double* __restrict sine, double* __restrict cosine) {
  // Whether any angle needs libm is found in the vectorised loop: a second scalar pass over
  // every angle would cost a large share of this function.
  uint64_t large = 0;
  for (size_t i = 0; i < n; ++i) {
    SinCosReduced(deg[i], sine[i], cosine[i]);
    large |= std::abs(deg[i]) < 1e9 ? 0 : 1;
  }
  if (large == 0) return;
  for (size_t i = 0; i < n; ++i)
    if (!(std::abs(deg[i]) < 1e9)) SinCosDegreesInline(deg[i], sine[i], cosine[i]);
}

#if MOCAPFILL_AVX2_VARIANTS
__attribute__((target("avx2"))) void SinCosDegreesAvx2(const double* __restrict deg, size_t n,
                                                       double* __restrict sine, double* __restrict cosine) {
  SinCosDegreesLoop(deg, n, sine, cosine);
}
#endif

void SinCosDegreesPlain(const double* __restrict deg, size_t n, double* __restrict sine,
                        double* __restrict cosine) {
  SinCosDegreesLoop(deg, n, sine, cosine);
}

}  // namespace

void SinCosDegreesBatch(const double* __restrict deg, size_t n, double* __restrict sine, double* __restrict cosine) {
#if MOCAPFILL_AVX2_VARIANTS
  if (CpuHasAvx2()) return SinCosDegreesAvx2(deg, n, sine, cosine);
#endif
  SinCosDegreesPlain(deg, n, sine, cosine);
}

Eigen::Quaterniond ComposeEulerDegrees(const std::array<double, 3>& angles_deg, const EulerOrder& order) {
  return ComposerFor(order)(angles_deg);
}

}  // namespace mocapfill::bvh
