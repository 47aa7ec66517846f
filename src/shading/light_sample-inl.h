// Where is the light, seen from a surface point (OpenGL 2.1 §2.14.1): the unit vector L towards
// it, its distance, the distance attenuation and the spot factor. Over lanes (lane_math-inl.h);
// what the local models, the ray tracers' shadow rays and the physically based models share.

#if defined(ILLUM_SHADING_LIGHT_SAMPLE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_SHADING_LIGHT_SAMPLE_INL_H_
#undef ILLUM_SHADING_LIGHT_SAMPLE_INL_H_
#else
#define ILLUM_SHADING_LIGHT_SAMPLE_INL_H_
#endif

#include <illum/lighting.h>

#include "shading/brdf-inl.h"
#include "shading/prepared_light.h"

#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {

template <class V>
struct LightSample {
  Vec3L<V> L;     // unit vector towards the light
  V distance;     // to a positional light; 0 for a directional one
  V attenuation;  // 1 / (k_c + k_l·d + k_q·d²); 1 for a directional light
  V spot;         // the spot factor; 1 without a cone
};

// Distance attenuation 1 / (k_c + k_l·d + k_q·d²) for positional lights. With k = (0,0,1) it is
// the inverse-square law I/r².
template <class D>
HWY_INLINE hn::VFromD<D> DistanceAttenuation(D d, const Vec3& k, hn::VFromD<D> dist) {
  return hn::Set(d, Real(1)) / (hn::Set(d, k.x) + hn::Set(d, k.y) * dist + hn::Set(d, k.z) * dist * dist);
}

// Spotlight factor: max(−L·S, 0)^e inside the cone, 0 outside. A cutoff of 180 (cos ≤ −1) is no spot.
template <class D>
HWY_INLINE hn::VFromD<D> SpotFactor(D d, hn::VFromD<D> minusLoS, Real cosCutoff, Real exponent) {
  return hn::IfThenZeroElse(minusLoS < hn::Set(d, cosCutoff), PowLobe(d, minusLoS, exponent));
}

// The light (an EyeLight, or a PreparedLight) as seen from points P with unit normals N.
template <class D, class L, class V = hn::VFromD<D>>
HWY_INLINE LightSample<V> SampleLight(D d, const L& light, const Vec3L<V>& P, const Vec3L<V>& N) {
  LightSample<V> s;
  s.distance = hn::Zero(d);
  s.attenuation = hn::Set(d, Real(1));
  if (light.isPositional()) {
    const Vec3L<V> toLight = Broadcast(d, Vec3(light.position) / light.position.w) - P;
    s.distance = Length(toLight);
    // A light exactly at the point shines along the normal.
    const auto away = s.distance > hn::Zero(d);
    const V inverse = hn::Set(d, Real(1)) / hn::IfThenElse(away, s.distance, hn::Set(d, Real(1)));
    s.L = Select(away, inverse * toLight, N);
    s.attenuation = DistanceAttenuation(d, light.attenuation, s.distance);
  } else {
    if constexpr (std::is_same_v<L, PreparedLight>) s.L = Broadcast(d, light.towards);
    else s.L = Broadcast(d, unitTowards(light));
  }
  // The spot factor applies to directional lights too, as GL specifies.
  s.spot = light.isSpot() ? SpotFactor(d, hn::Neg(Dot(s.L, Broadcast(d, light.spotDirection))), light.spotCosCutoff,
                                       light.spotExponent)
                          : hn::Set(d, Real(1));
  return s;
}

// Records lane 0's light geometry for the reports (LightDetail), as every model does first.
template <class V>
HWY_INLINE void RecordLightSample(LightDetail* record, const EyeLight& light, const LightSample<V>& ls, V NoL) {
  record->positional = light.isPositional();
  record->L = Lane0(ls.L);
  record->distance = hn::GetLane(ls.distance);
  record->attenuation = hn::GetLane(ls.attenuation);
  record->spot = hn::GetLane(ls.spot);
  record->NoL = hn::GetLane(NoL);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_LIGHT_SAMPLE_INL_H_
