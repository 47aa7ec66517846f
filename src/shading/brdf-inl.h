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

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_BRDF_INL_H_
