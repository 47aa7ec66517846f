// The tone maps over SIMD lanes (Highway, included once per target): the one formula of each,
// display.cpp's toneMapped being the one-lane instance, so the rasterizer's lanes (ClampedColor)
// and the tracers' pixels give the same bits. Plain multiplies, adds and a correctly rounded
// divide, in the same order on every target (the build keeps FMA contraction off).

#if defined(ILLUM_MATH_TONE_MAP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_MATH_TONE_MAP_INL_H_
#undef ILLUM_MATH_TONE_MAP_INL_H_
#else
#define ILLUM_MATH_TONE_MAP_INL_H_
#endif

#include <hwy/highway.h>

#include <illum/tone_map.h>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Radiance x to the tone map's value: negative and NaN are black; Reinhard x/(1+x); ACES the
// rational fit of Narkowicz (2015), "ACES Filmic Tone Mapping Curve", clamped to [0, 1] (a value
// whose square overflows stays NaN, as the clamp leaves it); an infinite x is 1 under both.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE V ToneMappedLanes(D d, V x, ToneMap toneMap) {
  using T = hn::TFromD<D>;
  const V zero = hn::Zero(d), one = hn::Set(d, T(1));
  const auto positive = x > zero;
  const auto infinite = x == hn::Inf(d);
  V y = x;
  switch (toneMap) {
    case ToneMap::None: break;
    case ToneMap::Reinhard: y = hn::IfThenElse(infinite, one, x / (one + x)); break;
    case ToneMap::Aces: {
      const V fit = (x * (hn::Set(d, T(2.51)) * x + hn::Set(d, T(0.03)))) /
                    (x * (hn::Set(d, T(2.43)) * x + hn::Set(d, T(0.59))) + hn::Set(d, T(0.14)));
      const V clamped = hn::IfThenElse(fit < zero, zero, hn::IfThenElse(one < fit, one, fit));
      y = hn::IfThenElse(infinite, one, clamped);
      break;
    }
  }
  return hn::IfThenElseZero(positive, y);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_MATH_TONE_MAP_INL_H_
