// How a GL material answers (OpenGL 2.1 §2.14.1), over lanes, and the one composition of the
// equation:
//   c = e_cm + a_cm·a_cs + Σ_i att_i · spot_i · [a_cm·a_cli + (n⊙VP)·d_cm·d_cli + f_i·(n⊙ĥ)^s·s_cm·s_cli]
// per channel in eye space. The material's colours a_cm, d_cm and s_cm are common factors of every
// light's bracket, so the lights are summed first and the material multiplies the sums once:
//   c = e_cm + a_cm·a_cs + a_cm·Σ_i att_i·spot_i·a_cli + d_cm·Σ_i att_i·spot_i·(n⊙VP)·d_cli
//         + s_cm·Σ_i att_i·spot_i·f_i·(n⊙ĥ)^s·s_cli
// (nine multiplications fewer per light). The vertex stage, the per-pixel kernels, the reference
// pipeline, `illum eval` and `--debug-pixel` all come here; the recorder (kRecord) writes every
// intermediate of lane 0 without changing what is computed.

#if defined(ILLUM_SHADING_GL_LIGHTING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_SHADING_GL_LIGHTING_INL_H_
#undef ILLUM_SHADING_GL_LIGHTING_INL_H_
#else
#define ILLUM_SHADING_GL_LIGHTING_INL_H_
#endif

#include <illum/lighting.h>

#include "math/tone_map-inl.h"
#include "shading/brdf-inl.h"
#include "shading/cook_torrance-inl.h"
#include "shading/image_light-inl.h"
#include "shading/light_sample-inl.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {

// The surface at each lane, in eye space: N the unit normal of the side being lit (already −N for
// a back face), V the unit vector towards the viewer.
template <class V>
struct SurfaceL {
  Vec3L<V> P, N, toViewer;
};

// The material colours that may vary per lane: GL_COLOR_MATERIAL(GL_AMBIENT_AND_DIFFUSE) puts the
// vertex colour in both. Specular, emission and shininess are the object's.
template <class V>
struct MaterialColorsL {
  Vec3L<V> ambient, diffuse;
  V alpha;  // the diffuse alpha, which the lit colour carries
};

template <class V>
struct TermsL {
  Vec3L<V> emission, ambient, diffuse, specular;
};

// The lights' colours as they reach the surface, summed over the lights before the material's
// colours multiply them: Σ att·spot·a_cli, Σ att·spot·(n⊙VP)·d_cli and Σ att·spot·f·(n⊙ĥ)^s·s_cli
// (the early models fill `diffuse` alone).
template <class V>
struct LightSumsL {
  Vec3L<V> ambient, diffuse, specular;
};

template <class D, class V = hn::VFromD<D>>
HWY_INLINE LightSumsL<V> NoLight(D d) {
  const Vec3L<V> zero = Broadcast(d, Vec3(0));
  return {zero, zero, zero};
}

// Terms of nothing yet: what a light's share or a sum of shares starts from.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE TermsL<V> NoTerms(D d) {
  const Vec3L<V> zero = Broadcast(d, Vec3(0));
  return {zero, zero, zero, zero};
}

// The material's colours times the lights' sums, added to `terms`.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void AddReflected(D d, TermsL<V>& terms, const LightSumsL<V>& sums, const Material& material,
                             const MaterialColorsL<V>& colors) {
  terms.ambient = terms.ambient + Mul(colors.ambient, sums.ambient);
  terms.diffuse = terms.diffuse + Mul(colors.diffuse, sums.diffuse);
  terms.specular = terms.specular + Mul(Broadcast(d, Vec3(material.specular)), sums.specular);
}

// The material's own colours at every lane: GL's ambient and diffuse, or for cook-torrance the
// base colour in both (which vertex colours replace as they replace GL's two). `physical` is
// physicalFor(m, model), which the caller asks for once rather than once a vector.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE MaterialColorsL<V> UniformColors(D d, const Material& m, const PhysicalMaterial& physical, LightingModel model) {
  if (model == LightingModel::CookTorrance) {
    const Vec3L<V> base = Broadcast(d, physical.baseColor);
    return {base, base, hn::Set(d, m.diffuse.a)};
  }
  return {Broadcast(d, Vec3(m.ambient)), Broadcast(d, Vec3(m.diffuse)), hn::Set(d, m.diffuse.a)};
}

// The direction to the viewer: (0,0,1) for GL's infinite viewer; with GL_LIGHT_MODEL_LOCAL_VIEWER
// towards the eye at the origin (a point at the eye itself takes the infinite viewer's).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> ToViewer(D d, const Vec3L<V>& P, bool localViewer) {
  const Vec3L<V> infinite = Broadcast(d, Vec3(0, 0, 1));
  if (!localViewer) return infinite;
  const V len = Length(P);
  const auto away = len > hn::Zero(d);
  return Select(away, -P / hn::IfThenElse(away, len, hn::Set(d, Real(1))), infinite);
}

// Emission and the light model's global ambient: the terms before any light (Wylie's 1967 model
// has no ambient light; seed 001's shader has the material's ambient alone, and no emission).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE TermsL<V> TermsWithoutLights(D d, const LightModel& lightModel, const Material& material,
                                        const MaterialColorsL<V>& colors, LightingModel model) {
  const Vec3L<V> zero = Broadcast(d, Vec3(0));
  if (follows(model, lightModel.convention) && lightModel.convention == Convention::NoteShader)
    return {zero, colors.ambient, zero, zero};
  const Vec3L<V> ambient = model == LightingModel::Wylie ? zero : Mul(Broadcast(d, lightModel.ambient), colors.ambient);
  return {Broadcast(d, Vec3(material.emission)), ambient, zero, zero};
}

// An environment's image-based light (image_light.h) at each lane. Under a classic model it takes
// the global ambient's place (GL's a_cs becomes the irradiance E/π about N); a physically based
// material takes its diffuse part, (1 − metallic)·base ⊙ E/π, as its ambient term, and the split
// sum's reflection of the map, prefiltered(R, roughness) ⊙ (f0·A + B), as specular.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void AddImageLight(D d, TermsL<V>& terms, const EyeImageLight& env, LightingModel model,
                              const MaterialColorsL<V>& colors, const PhysicalL<V>& physical, const SurfaceL<V>& s) {
  const bool physicallyBased = model == LightingModel::CookTorrance;
  if (model == LightingModel::Wylie || (!physicallyBased && !env.lightsClassic)) return;
  const ImageLight& light = *env.light;
  const Vec3L<V> scale = Broadcast(d, env.scale);
  const Vec3L<V> irradiance = Mul(scale, IrradianceOverPi(d, light, Rotated(d, env.mapFromEye, s.N)));
  if (!physicallyBased) {
    terms.ambient = Mul(colors.ambient, irradiance);
    return;
  }
  const V one = hn::Set(d, Real(1));
  const V metallic = physical.metallic, dielectric = one - metallic;
  terms.ambient = Mul(dielectric * colors.ambient, irradiance);
  // Interpolated normals can turn a little away from the viewer: N·V stays just above 0, as the lights' lobe keeps it.
  const V NoV = hn::Max(Dot(s.N, s.toViewer), hn::Set(d, Real(1e-4)));
  const Vec3L<V> R = (hn::Set(d, Real(2)) * NoV) * s.N - s.toViewer;
  const V roughness = hn::Sqrt(physical.alpha);  // the perceptual roughness MicrofacetAlpha squared
  V A, B;
  SplitSum(d, NoV, roughness, A, B);
  const Vec3L<V> f0 = dielectric * physical.f0 + metallic * colors.diffuse;
  const Vec3L<V> reflectance = A * f0 + Vec3L<V>{B, B, B};
  const Vec3L<V> reflected = Prefiltered(d, light, Rotated(d, env.mapFromEye, R), roughness);
  terms.specular = terms.specular + Mul(Mul(scale, reflected), reflectance);
}

// The two models before Gouraud's, one light at a time:
//   wylie (Wylie, Romney, Evans and Erdahl 1967): d_cm·d_cli / d, the intensity falling as the
//     inverse of the distance d from a positional light, with no angle (a directional light: d_cm·d_cli);
//   bouknight (Bouknight 1970): d_cm·d_cli·max(N·L, 0), Lambert's law from a light at infinity
//     (no attenuation, no spot, no light ambient); the ambient term is the light model's.
template <bool kRecord, class D, class L, class V = hn::VFromD<D>>
HWY_INLINE void AccumulateEarlyLight(D d, LightSumsL<V>& sums, const L& light, const MaterialColorsL<V>& colors,
                                     LightingModel model, const SurfaceL<V>& s, LightDetail* record) {
  const LightSample<V> ls = SampleLight(d, light, s.P, s.N);
  const V NoL = Dot(s.N, ls.L);
  if constexpr (kRecord) {
    RecordLightSample(record, light, ls, NoL);
    record->attenuation = 1;
    record->spot = 1;
  }
  V factor;
  if (model == LightingModel::Wylie) {
    const V one = hn::Set(d, Real(1));
    factor = light.isPositional() ? one / hn::Max(ls.distance, hn::Set(d, Real(1e-6))) : one;
    if constexpr (kRecord) record->attenuation = hn::GetLane(factor);
  } else {
    factor = Fd_LambertCosine(NoL);
  }
  const Vec3L<V> diffuse = factor * Broadcast(d, light.diffuse);
  if constexpr (kRecord) record->terms = {Vec3(0), Vec3(0), Lane0(Mul(colors.diffuse, diffuse)), Vec3(0)};
  sums.diffuse = sums.diffuse + diffuse;
}

// One light's bracket without the material's colours, attenuation and spot applied, added to
// `sums`; the recorder's terms are the light's share with the material's colours (`colors`). A
// note's `convention` changes the bracket as lighting.h says.
template <bool kRecord, class D, class L, class V = hn::VFromD<D>>
HWY_INLINE void AccumulateGlLight(D d, LightSumsL<V>& sums, const L& light, const Material& material,
                                  const MaterialColorsL<V>& colors, LightingModel model, Convention convention,
                                  const SurfaceL<V>& s, LightDetail* record) {
  // Where is the light.
  const LightSample<V> ls = SampleLight(d, light, s.P, s.N);
  const V scale = ls.attenuation * ls.spot;
  const V NoL = Dot(s.N, ls.L);
  if constexpr (kRecord) {
    RecordLightSample(record, light, ls, NoL);
  } else if (hn::AllTrue(d, scale == hn::Zero(d))) {
    return;  // out of every lane's cone, or attenuated to nothing
  }

  // How the surface answers: ambient, Lambert's diffuse and the model's specular lobe, the last
  // only where N·L > 0 (f_i = 0: no highlight without direct light).
  const bool noteShader = convention == Convention::NoteShader;
  const Vec3L<V> ambient = noteShader ? Broadcast(d, Vec3(0)) : scale * Broadcast(d, light.ambient);
  const V strength = scale * Fd_LambertCosine(NoL);  // the note's "light strength", Ld's factor
  const Vec3L<V> diffuse = strength * Broadcast(d, light.diffuse);
  const auto lit = NoL > hn::Zero(d);
  // The lobe where some lane is lit (and every time for the report). A light of no specular
  // colour (the preview rig's fill) adds (scale·lobe)·0: the lobe, always finite, is left at 0
  // without being computed, for the same bits (0, or NaN where scale is).
  const bool computed = kRecord || ((noteShader || light.hasSpecular()) && !hn::AllFalse(d, lit));
  V lobe = hn::Zero(d);
  if (model == LightingModel::BlinnPhong && convention == Convention::NoteHalfSum && computed) {
    const Vec3L<V> H = hn::Set(d, Real(0.5)) * (ls.L + s.toViewer);
    const V NoH = Dot(s.N, H);
    lobe = hn::IfThenElseZero(lit, Fs_BlinnPhong(d, NoH, material.shininess));
    if constexpr (kRecord) record->H = Lane0(H), record->NoH = hn::GetLane(NoH);
  } else if (model == LightingModel::BlinnPhong && computed) {
    const Vec3L<V> H = ls.L + s.toViewer;
    const V len = Length(H);
    // L = −V (up to rounding) leaves H undefined; illum takes N·H = 0 (so only 0^0 = 1 survives).
    const auto defined = len > hn::Set(d, Real(1e-6));
    const V safeLen = hn::IfThenElse(defined, len, hn::Set(d, Real(1)));
    const V NoH = hn::IfThenElseZero(defined, Dot(s.N, H) / safeLen);
    lobe = hn::IfThenElseZero(lit, Fs_BlinnPhong(d, NoH, material.shininess));
    if constexpr (kRecord) {
      record->H = hn::GetLane(len) > Real(1e-6) ? Lane0(H / safeLen) : Vec3(0);
      record->NoH = hn::GetLane(NoH);
    }
  } else if (model == LightingModel::Phong && computed) {
    const Vec3L<V> R = (hn::Set(d, Real(2)) * NoL) * s.N - ls.L;
    const V RoV = Dot(R, s.toViewer);
    lobe = hn::IfThenElseZero(lit, Fs_Phong(d, RoV, material.shininess));
    if constexpr (kRecord) record->R = Lane0(R), record->RoV = hn::GetLane(RoV);
  }
  // The note's shader: the highlight, too, is the light's strength (its diffuse colour times N·L).
  const Vec3L<V> specular =
      noteShader ? (strength * lobe) * Broadcast(d, light.diffuse) : (scale * lobe) * Broadcast(d, light.specular);
  if constexpr (kRecord) {
    record->lobe = hn::GetLane(lobe);
    if (hn::GetLane(scale) != 0) {
      TermsL<V> share = NoTerms(d);
      AddReflected(d, share, {ambient, diffuse, specular}, material, colors);
      record->terms = {Vec3(0), Lane0(share.ambient), Lane0(share.diffuse), Lane0(share.specular)};
    }
  }
  sums.ambient = sums.ambient + ambient;
  sums.diffuse = sums.diffuse + diffuse;
  sums.specular = sums.specular + specular;
}

// One light under the model: a GL material's answer added to `sums` (AddLightSums applies the
// material's colours), or a physically based one's, whose colours vary with the light (Fresnel's
// F), added to `terms` as it is (`physical` is physicalOf(material) over the lanes, made once by
// the caller).
template <bool kRecord, class D, class L, class V = hn::VFromD<D>>
HWY_INLINE void AccumulateLight(D d, TermsL<V>& terms, LightSumsL<V>& sums, const L& light,
                                const Material& material, const PhysicalL<V>& physical,
                                const MaterialColorsL<V>& colors, LightingModel model, Convention convention,
                                const SurfaceL<V>& s, LightDetail* record) {
  if (model == LightingModel::CookTorrance)
    AccumulateCookTorrance<kRecord>(d, terms.ambient, terms.diffuse, terms.specular, light, physical, colors.diffuse,
                                    s.P, s.N, s.toViewer, record);
  else if (model == LightingModel::Wylie || model == LightingModel::Bouknight)
    AccumulateEarlyLight<kRecord>(d, sums, light, colors, model, s, record);
  else
    AccumulateGlLight<kRecord>(d, sums, light, material, colors, model,
                               follows(model, convention) ? convention : Convention::GL, s, record);
}

// The lights' `sums` reflected by the material's colours into `terms` (AddReflected), under
// every model but Cook-Torrance, whose lights add to `terms` themselves (AccumulateLight).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void AddLightSums(D d, TermsL<V>& terms, const LightSumsL<V>& sums, const Material& material,
                             const MaterialColorsL<V>& colors, LightingModel model) {
  if (model != LightingModel::CookTorrance) AddReflected(d, terms, sums, material, colors);
}

// What glTF's maps make of the material at each lane (their texels applied as withMapTexels applies
// them): a physically based material's metallic and roughness, and the emission; null: the
// material's own.
template <class V>
struct MappedL {
  const V* metallic = nullptr;  // with roughness
  const V* roughness = nullptr;
  const Vec3L<V>* emission = nullptr;
};

// The whole equation at each lane: emission, global ambient, then every light in order
// (`physicalMaterial` is physicalFor(material, model); the lights EyeLights or PreparedLights).
template <class D, class L, class V = hn::VFromD<D>>
HWY_INLINE TermsL<V> ShadeEquation(D d, std::span<const L> lights, const LightModel& lightModel,
                                   const Material& material, const PhysicalMaterial& physicalMaterial,
                                   const MaterialColorsL<V>& colors, LightingModel model, const SurfaceL<V>& s,
                                   const MappedL<V>& mapped = {}) {
  TermsL<V> terms = TermsWithoutLights(d, lightModel, material, colors, model);
  const bool noteShader = follows(model, lightModel.convention) && lightModel.convention == Convention::NoteShader;
  if (mapped.emission && !noteShader) terms.emission = *mapped.emission;  // (the note's shader has no emission)
  const PhysicalL<V> physical = mapped.metallic ? LanePhysical(d, physicalMaterial, *mapped.metallic, *mapped.roughness)
                                                : UniformPhysical(d, physicalMaterial);
  if (lightModel.environment && !noteShader)
    AddImageLight(d, terms, *lightModel.environment, model, colors, physical, s);
  LightSumsL<V> sums = NoLight(d);
  for (const L& light : lights)
    AccumulateLight<false>(d, terms, sums, light, material, physical, colors, model, lightModel.convention, s,
                           nullptr);
  if (!lights.empty()) AddLightSums(d, terms, sums, material, colors, model);
  return terms;
}

// The colour GL writes: each channel of the sum clamped to [0,1], alpha the diffuse alpha's; under
// a tone map (LightModel::toneMap), the sum tone mapped first by ToneMappedLanes (the one formula
// the ray tracers' pixels take too, through display.h's toneMapped).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void ClampedColor(D d, const TermsL<V>& t, V alpha, ToneMap toneMap, V& r, V& g, V& b, V& a) {
  const V zero = hn::Zero(d), one = hn::Set(d, Real(1));
  Vec3L<V> sum = t.emission + t.ambient + t.diffuse + t.specular;
  if (toneMap != ToneMap::None)
    for (V* c : {&sum.x, &sum.y, &sum.z}) *c = ToneMappedLanes(d, *c, toneMap);
  r = hn::Min(hn::Max(sum.x, zero), one);
  g = hn::Min(hn::Max(sum.y, zero), one);
  b = hn::Min(hn::Max(sum.z, zero), one);
  a = hn::Min(hn::Max(alpha, zero), one);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_GL_LIGHTING_INL_H_
