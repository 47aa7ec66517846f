// How a physically based material answers, over lanes: Cook and Torrance's microfacet model with
// the terms of brdf-inl.h, one light at a time, under the same lights as the classic models.
//
// A light's colour c is the radiance it reflects off a white Lambertian surface facing it, so its
// irradiance is E = π·c·att·spot·(N·L), and a GL scene and a physically based scene of the same
// lights compare: the diffuse term is exactly GL's for a dielectric of base colour = diffuse.
//   c = e + a_global ⊙ base + Σ_i att·spot·[ a_li ⊙ base
//         + (N·L) (1 − F)(1 − metallic) base ⊙ d_li            (π · Fd_Lambert = 1)
//         + (N·L) π D V F ⊙ s_li ]                              (V = G / (4 N·L N·V))
// with F = F_Schlick(V·H, mix(f0, base, metallic)), α = roughness² (at least 0.045²). The ambient
// terms stay the classic stand-in for the light arriving from everywhere else.
// Included once per target (Highway's -inl.h convention).

#if defined(ILLUM_SHADING_COOK_TORRANCE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_SHADING_COOK_TORRANCE_INL_H_
#undef ILLUM_SHADING_COOK_TORRANCE_INL_H_
#else
#define ILLUM_SHADING_COOK_TORRANCE_INL_H_
#endif

#include <illum/lighting.h>

#include "shading/brdf-inl.h"
#include "shading/light_sample-inl.h"

#include <algorithm>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {

// The distribution's α for a perceptual roughness, kept off the mirror limit where D has no value.
inline Real MicrofacetAlpha(Real roughness) {
  const Real r = std::clamp(roughness, Real(0.045), Real(1));
  return r * r;
}

// A physically based material over lanes: metallic and α per lane (glTF's metallic-roughness map
// varies them across a surface), f0 and the distribution shared.
template <class V>
struct PhysicalL {
  V metallic, alpha;
  Vec3L<V> f0;
  Microfacet distribution = Microfacet::GGX;
};

// The same material in every lane.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE PhysicalL<V> UniformPhysical(D d, const PhysicalMaterial& m) {
  return {hn::Set(d, m.metallic), hn::Set(d, MicrofacetAlpha(m.roughness)), Broadcast(d, m.f0), m.distribution};
}

// Each lane's metallic and perceptual roughness (α as MicrofacetAlpha makes it), the rest m's.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE PhysicalL<V> LanePhysical(D d, const PhysicalMaterial& m, V metallic, V roughness) {
  const V r = hn::Min(hn::Max(roughness, hn::Set(d, Real(0.045))), hn::Set(d, Real(1)));
  return {metallic, r * r, Broadcast(d, m.f0), m.distribution};
}

// One light's terms for a physically based material; `base` and its ambient stand-in per lane
// (vertex colours replace the base colour). N and V are unit vectors on the lit side.
template <bool kRecord, class D, class L, class V = hn::VFromD<D>>
HWY_INLINE void AccumulateCookTorrance(D d, Vec3L<V>& ambientOut, Vec3L<V>& diffuseOut, Vec3L<V>& specularOut,
                                       const L& light, const PhysicalL<V>& m, const Vec3L<V>& base,
                                       const Vec3L<V>& P, const Vec3L<V>& N, const Vec3L<V>& toViewer,
                                       LightDetail* record) {
  // Where is the light.
  const LightSample<V> ls = SampleLight(d, light, P, N);
  const V scale = ls.attenuation * ls.spot;
  const V NoL = Dot(N, ls.L);
  const V zero = hn::Zero(d), one = hn::Set(d, Real(1));
  const Vec3L<V> ambient = Mul(scale * base, Broadcast(d, light.ambient));
  ambientOut = ambientOut + ambient;
  const auto lit = NoL > zero;
  if constexpr (kRecord) {
    RecordLightSample(record, light, ls, NoL);
    if (hn::GetLane(scale) != 0) record->terms.ambient = Lane0(ambient);
  } else if (hn::AllFalse(d, hn::And(lit, scale > zero))) {
    return;  // no lane sees this light
  }
  // How the surface answers.
  const V alpha = m.alpha;
  const Vec3L<V> H = ls.L + toViewer;
  const V len = Length(H);
  const auto defined = len > hn::Set(d, Real(1e-6));
  const V safeLen = hn::IfThenElse(defined, len, one);
  const V NoH = hn::IfThenElseZero(defined, hn::ZeroIfNegative(Dot(N, H) / safeLen));
  const V VoH = hn::IfThenElseZero(defined, hn::ZeroIfNegative(Dot(toViewer, H) / safeLen));
  // Interpolated normals can turn a little away from the viewer: N·V stays just above 0.
  const V NoV = hn::Max(Dot(N, toViewer), hn::Set(d, Real(1e-4)));
  const V NoLlit = hn::ZeroIfNegative(NoL);
  // A light of no specular colour (the preview rig's fill) multiplies the lobe by 0: D and Vis,
  // always finite, are left at 0 without being computed, for the same bits.
  const bool highlight = kRecord || light.hasSpecular();
  const V Dist = !highlight ? zero
                 : m.distribution == Microfacet::GGX ? D_GGX(d, NoH, alpha)
                                                      : D_Beckmann(d, NoH, alpha);
  const V Vis = highlight ? V_SmithGGXCorrelated(d, NoV, NoLlit, alpha) : zero;
  const V metallic = m.metallic, dielectric = one - metallic;
  const Vec3L<V> f0 = dielectric * m.f0 + metallic * base;
  const Vec3L<V> F = F_Schlick(d, VoH, f0);
  const Vec3L<V> ones{one, one, one};
  const V weight = hn::IfThenElseZero(lit, scale * NoLlit);
  const Vec3L<V> diffuse = Mul(Mul((weight * dielectric) * (ones - F), base), Broadcast(d, light.diffuse));
  const Vec3L<V> specular = Mul((weight * hn::Set(d, kPi) * Dist * Vis) * F, Broadcast(d, light.specular));
  diffuseOut = diffuseOut + diffuse;
  specularOut = specularOut + specular;
  if constexpr (kRecord) {
    record->H = hn::GetLane(len) > Real(1e-6) ? Lane0(H / safeLen) : Vec3(0);
    record->NoH = hn::GetLane(NoH);
    record->NoV = hn::GetLane(NoV);
    record->VoH = hn::GetLane(VoH);
    record->D = hn::GetLane(Dist);
    record->visibility = hn::GetLane(Vis);
    record->F = Lane0(F);
    if (hn::GetLane(scale) != 0) record->terms.diffuse = Lane0(diffuse), record->terms.specular = Lane0(specular);
  }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_COOK_TORRANCE_INL_H_
