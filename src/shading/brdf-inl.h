// The reflection lobes of the classic models, one small named function each (Filament style),
// over lanes (lane_math-inl.h): the scalar reports, the vertex stage and the per-pixel kernels all
// evaluate these same lines. Each returns the factor that multiplies light colour × material colour.

#if defined(ILLUM_SHADING_BRDF_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_SHADING_BRDF_INL_H_
#undef ILLUM_SHADING_BRDF_INL_H_
#else
#define ILLUM_SHADING_BRDF_INL_H_
#endif

#include "shading/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {

// Lambert's cosine law: reflected intensity ∝ cos θ = N·L, never negative. (GL's factor, not
// Filament's Fd_Lambert = 1/π: the physically based models keep that name for the 1/π.)
// J. H. Lambert, Photometria (1760); OpenGL 2.1 §2.14.1, the term (n ⊙ VP_pli).
template <class V>
HWY_INLINE V Fd_LambertCosine(V NoL) {
  return hn::ZeroIfNegative(NoL);
}

// max(x, 0)^n, the lobes' common form, with pow's exact cases: 0^0 = 1, 0^n = 0, 1^n = 1.
template <class D>
HWY_INLINE hn::VFromD<D> PowLobe(D d, hn::VFromD<D> x, Real n) {
  const auto one = hn::Set(d, Real(1));
  if (n == 0) return one;
  const auto positive = x > hn::Zero(d);
  const auto safe = hn::IfThenElse(positive, x, one);  // keeps the log away from 0 and below
  return hn::IfThenElseZero(positive, hn::IfThenElse(x == one, one, PowPositive(d, safe, n)));
}

// Phong's specular lobe (R·V)^n with R = 2N(N·L) − L.
// B. T. Phong, "Illumination for computer generated pictures", CACM 18(6), 1975.
template <class D>
HWY_INLINE hn::VFromD<D> Fs_Phong(D d, hn::VFromD<D> RoV, Real shininess) {
  return PowLobe(d, RoV, shininess);
}

// Blinn's halfway-vector lobe (N·H)^n with H = normalize(L + V).
// J. F. Blinn, "Models of light reflection for computer synthesized pictures", SIGGRAPH 1977;
// OpenGL 2.1 §2.14.1, the term (n ⊙ ĥ_i)^s_rm.
template <class D>
HWY_INLINE hn::VFromD<D> Fs_BlinnPhong(D d, hn::VFromD<D> NoH, Real shininess) {
  return PowLobe(d, NoH, shininess);
}

// ---- Cook-Torrance's microfacet model: f = Fd + D·G·F / (4 N·L N·V) ----
// (R. L. Cook and K. E. Torrance, "A Reflectance Model for Computer Graphics", SIGGRAPH 1981 /
// ACM TOG 1(1), 1982), with the terms physically based renderers use today (Filament's names).

constexpr Real kPi = Real(3.14159265358979323846);

// Lambert's diffuse BRDF, albedo/π: the 1/π of an ideal diffuse reflector.
inline Real Fd_Lambert() { return 1 / kPi; }

// GGX / Trowbridge-Reitz normal distribution: α² / (π ((N·H)²(α² − 1) + 1)²).
// B. Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007, eq. 33.
// (α per lane: glTF's metallic-roughness map varies it across a surface.)
template <class D>
HWY_INLINE hn::VFromD<D> D_GGX(D d, hn::VFromD<D> NoH, hn::VFromD<D> alpha) {
  const auto a2 = alpha * alpha;
  const auto k = NoH * NoH * (a2 - hn::Set(d, Real(1))) + hn::Set(d, Real(1));
  return a2 / (hn::Set(d, kPi) * k * k);
}

// Beckmann's distribution, Cook and Torrance's choice: exp(−tan²θ/α²) / (π α² cos⁴θ), θ = ∠(N, H).
// Cook and Torrance 1982, eq. 5 (with m = α).
template <class D>
HWY_INLINE hn::VFromD<D> D_Beckmann(D d, hn::VFromD<D> NoH, hn::VFromD<D> alpha) {
  const auto c2 = NoH * NoH;
  const auto a2 = alpha * alpha;
  const auto positive = c2 > hn::Zero(d);
  const auto safe = hn::IfThenElse(positive, c2, hn::Set(d, Real(1)));
  // −tan²θ/α² = (c² − 1)/(c² α²) ≤ 0.
  const auto e = Exp(d, (safe - hn::Set(d, Real(1))) / (safe * a2));
  return hn::IfThenElseZero(positive, e / (hn::Set(d, kPi) * a2 * safe * safe));
}

// Smith's height-correlated masking-shadowing as a visibility term, V = G / (4 N·L N·V):
// 0.5 / (N·L √((N·V)²(1 − α²) + α²) + N·V √((N·L)²(1 − α²) + α²)).
// E. Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2),
// 2014, eq. 99; the form of Filament's V_SmithGGXCorrelated.
template <class D>
HWY_INLINE hn::VFromD<D> V_SmithGGXCorrelated(D d, hn::VFromD<D> NoV, hn::VFromD<D> NoL, hn::VFromD<D> alpha) {
  const auto a2 = alpha * alpha, one = hn::Set(d, Real(1));
  const auto ggxV = NoL * hn::Sqrt(NoV * NoV * (one - a2) + a2);
  const auto ggxL = NoV * hn::Sqrt(NoL * NoL * (one - a2) + a2);
  return hn::Set(d, Real(0.5)) / (ggxV + ggxL);
}

// Schlick's Fresnel approximation: F0 + (1 − F0)(1 − V·H)⁵.
// C. Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", CGF 13(3), 1994.
template <class D>
HWY_INLINE Vec3L<hn::VFromD<D>> F_Schlick(D d, hn::VFromD<D> VoH, const Vec3L<hn::VFromD<D>>& f0) {
  const auto one = hn::Set(d, Real(1));
  const auto m = hn::ZeroIfNegative(one - VoH);
  const auto m2 = m * m;
  const auto f = m2 * m2 * m;
  const Vec3L<hn::VFromD<D>> ones{one, one, one};
  return f0 + f * (ones - f0);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_BRDF_INL_H_
