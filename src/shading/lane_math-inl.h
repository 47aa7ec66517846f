// Arithmetic over lanes (Highway vectors of Real; one lane for the scalar paths): 3-vectors and
// the power function of the lobes. Included once per SIMD target (Highway's -inl.h convention).
//
// Every lane gives the same bits on every target and at every width: only IEEE-exact operations
// (+, −, ×, ÷, √, rounding to integers, bit moves) are used, never a fused multiply-add or an
// approximate reciprocal, and the build turns floating-point contraction off (-ffp-contract=off).
// That is what lets the scalar reports (eval, --debug-pixel) and the reference pipeline reproduce
// the SIMD renderer's values exactly, on an SSE4 machine as on an AVX-512 one.
//
// Lane vectors live in small structs (Vec3L). Highway allows that on x86 and Arm NEON, the
// machines illum targets; SVE and RVV's sizeless vectors could not be struct members.

#if defined(ILLUM_SHADING_LANE_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_SHADING_LANE_MATH_INL_H_
#undef ILLUM_SHADING_LANE_MATH_INL_H_
#else
#define ILLUM_SHADING_LANE_MATH_INL_H_
#endif

#include <illum/real.h>

#include <hwy/highway.h>

#include <cmath>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class V>
struct Vec3L {
  V x, y, z;
};

template <class D>
HWY_INLINE Vec3L<hn::VFromD<D>> Broadcast(D d, const Vec3& v) {
  return {hn::Set(d, v.x), hn::Set(d, v.y), hn::Set(d, v.z)};
}
template <class V>
HWY_INLINE Vec3L<V> operator+(const Vec3L<V>& a, const Vec3L<V>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class V>
HWY_INLINE Vec3L<V> operator-(const Vec3L<V>& a, const Vec3L<V>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class V>
HWY_INLINE Vec3L<V> operator*(V s, const Vec3L<V>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class V>
HWY_INLINE Vec3L<V> operator/(const Vec3L<V>& a, V s) { return {a.x / s, a.y / s, a.z / s}; }
template <class V>
HWY_INLINE Vec3L<V> operator-(const Vec3L<V>& a) { return {hn::Neg(a.x), hn::Neg(a.y), hn::Neg(a.z)}; }
// Componentwise product (colour × colour).
template <class V>
HWY_INLINE Vec3L<V> Mul(const Vec3L<V>& a, const Vec3L<V>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
template <class V>
HWY_INLINE V Dot(const Vec3L<V>& a, const Vec3L<V>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class V>
HWY_INLINE V Length(const Vec3L<V>& a) { return hn::Sqrt(Dot(a, a)); }
template <class M, class V>
HWY_INLINE Vec3L<V> Select(M m, const Vec3L<V>& yes, const Vec3L<V>& no) {
  return {hn::IfThenElse(m, yes.x, no.x), hn::IfThenElse(m, yes.y, no.y), hn::IfThenElse(m, yes.z, no.z)};
}
template <class V>
HWY_INLINE Vec3 Lane0(const Vec3L<V>& a) { return {hn::GetLane(a.x), hn::GetLane(a.y), hn::GetLane(a.z)}; }

// log2(x) for positive, finite x (float): x = m·2^e with m in [√½, √2), then
// ln m = 2·atanh(t), t = (m − 1)/(m + 1), |t| ≤ 0.172, by its series to t⁹ (error < 4e-10).
template <class D>
HWY_INLINE hn::VFromD<D> Log2Positive(D d, hn::VFromD<D> x) {
  const hn::RebindToSigned<D> di;
  using V = hn::VFromD<D>;
  const auto denormal = x < hn::Set(d, 1.17549435e-38f);  // FLT_MIN
  x = hn::IfThenElse(denormal, x * hn::Set(d, 8388608.0f), x);  // × 2^23
  const auto bits = hn::BitCast(di, x);
  const auto exponent = hn::ShiftRight<23>(bits) - hn::Set(di, 127);
  V m = hn::BitCast(d, hn::Or(hn::And(bits, hn::Set(di, 0x7FFFFF)), hn::Set(di, 0x3F800000)));
  const auto above = m > hn::Set(d, 1.41421356f);
  m = hn::IfThenElse(above, m * hn::Set(d, 0.5f), m);
  const V e = hn::ConvertTo(d, exponent) + hn::IfThenElseZero(above, hn::Set(d, 1.0f)) -
              hn::IfThenElseZero(denormal, hn::Set(d, 23.0f));
  const V one = hn::Set(d, 1.0f);
  const V t = (m - one) / (m + one);
  const V t2 = t * t;
  const V series =
      one + t2 * (hn::Set(d, 1.0f / 3) + t2 * (hn::Set(d, 1.0f / 5) + t2 * (hn::Set(d, 1.0f / 7) + t2 * hn::Set(d, 1.0f / 9))));
  return e + ((t + t) * series) * hn::Set(d, 1.44269504f);  // ln m / ln 2
}

// 2^y (float): y = i + f with i = round(y), |f| ≤ ½; 2^f = e^(f·ln 2) by its series to z⁷
// (error < 6e-9); 2^i built from exponent bits in two halves so that results down to the
// denormals and up to infinity come out as IEEE arithmetic would round them.
template <class D>
HWY_INLINE hn::VFromD<D> Exp2(D d, hn::VFromD<D> y) {
  const hn::RebindToSigned<D> di;
  using V = hn::VFromD<D>;
  y = hn::Min(hn::Max(y, hn::Set(d, -252.0f)), hn::Set(d, 254.0f));
  const V i = hn::Round(y);
  const V z = (y - i) * hn::Set(d, 0.693147181f);
  const V one = hn::Set(d, 1.0f);
  V p = hn::Set(d, 1.0f / 5040);
  p = hn::Set(d, 1.0f / 720) + z * p;
  p = hn::Set(d, 1.0f / 120) + z * p;
  p = hn::Set(d, 1.0f / 24) + z * p;
  p = hn::Set(d, 1.0f / 6) + z * p;
  p = hn::Set(d, 0.5f) + z * p;
  p = one + z * p;
  p = one + z * p;
  const auto n = hn::ConvertTo(di, i);
  const auto n1 = hn::ShiftRight<1>(n), n2 = n - n1;  // each in [−126, 127]
  const V s1 = hn::BitCast(d, hn::ShiftLeft<23>(n1 + hn::Set(di, 127)));
  const V s2 = hn::BitCast(d, hn::ShiftLeft<23>(n2 + hn::Set(di, 127)));
  return (p * s1) * s2;
}

// e^x: 2^(x·log2 e) through Exp2 in float lanes; std::exp lane by lane in double lanes.
template <class D>
HWY_INLINE hn::VFromD<D> Exp(D d, hn::VFromD<D> x) {
  if constexpr (sizeof(hn::TFromD<D>) == 4) {
    return Exp2(d, x * hn::Set(d, 1.44269504f));
  } else {
    HWY_ALIGN hn::TFromD<D> lanes[hn::MaxLanes(d)];
    hn::Store(x, d, lanes);
    for (std::size_t i = 0; i < hn::Lanes(d); ++i) lanes[i] = std::exp(lanes[i]);
    return hn::Load(d, lanes);
  }
}

// x^n for x > 0. A whole exponent up to 4096 (GL shininess and spot exponents mostly are) by
// binary powering: a multiplication or two per bit of n, relative error below n·2^-23. Other
// float exponents by log2/exp2 above (relative error about 1e-7·max(1, |n·log2 x|)); double
// lanes (-DILLUM_DOUBLE=ON) call std::pow lane by lane.
template <class D>
HWY_INLINE hn::VFromD<D> PowPositive(D d, hn::VFromD<D> x, Real n) {
  if constexpr (sizeof(hn::TFromD<D>) == 4) {
    if (n >= 1 && n <= 4096 && n == std::floor(n)) {
      unsigned k = unsigned(n);
      hn::VFromD<D> result = hn::Set(d, 1.0f), base = x;
      for (;;) {
        if (k & 1) result = result * base;
        k >>= 1;
        if (k == 0) return result;
        base = base * base;
      }
    }
    return Exp2(d, hn::Set(d, n) * Log2Positive(d, x));
  } else {
    HWY_ALIGN hn::TFromD<D> lanes[hn::MaxLanes(d)];
    hn::Store(x, d, lanes);
    for (std::size_t i = 0; i < hn::Lanes(d); ++i) lanes[i] = std::pow(lanes[i], n);
    return hn::Load(d, lanes);
  }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_LANE_MATH_INL_H_
