// fragment.h's perspective-correct weights, Gouraud colour and Phong's renormalized normal over
// lanes, written once for the rasterizer's vectors (one triangle, its values broadcast) and for
// batches of tiny triangles (tiny_batch.h: each lane its own triangle's values). Float channels.
// Included once per target (Highway's -inl.h convention).

#if defined(ILLUM_RASTER_INTERPOLATE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_RASTER_INTERPOLATE_INL_H_
#undef ILLUM_RASTER_INTERPOLATE_INL_H_
#else
#define ILLUM_RASTER_INTERPOLATE_INL_H_
#endif

#include <hwy/highway.h>

#include "math/unorm8-inl.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// perspectiveWeights (fragment.h): p_i = λ_i/w_i / Σ λ_j/w_j, lane by lane.
template <class V>
HWY_INLINE void PerspectiveWeights(V l0, V l1, V l2, V invW0, V invW1, V invW2, V (&p)[3]) {
  const hn::DFromV<V> d;
  const V q0 = l0 * invW0, q1 = l1 * invW1, q2 = l2 * invW2;
  const V inv = hn::Set(d, 1.0f) / (q0 + q1 + q2);
  p[0] = q0 * inv, p[1] = q1 * inv, p[2] = q2 * inv;
}

// Σ p_i · a_i in gouraudColor's and phongSurface's order.
template <class V>
HWY_INLINE V Blend(const V (&p)[3], V a0, V a1, V a2) {
  return p[0] * a0 + p[1] * a1 + p[2] * a2;
}

// phongSurface's renormalized normal from the interpolated one n: n / |n|, or (0, 0, 1) where
// |n| = 0; negated in the lanes of `negate` (the back of a triangle under two-sided lighting).
template <class V, class M>
HWY_INLINE void UnitNormal(const V (&n)[3], M negate, V (&out)[3]) {
  const hn::DFromV<V> d;
  const V len = hn::Sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const auto positive = len > hn::Zero(d);
  const V inverse = hn::Set(d, 1.0f) / len;
  for (int c = 0; c < 3; ++c) {
    out[c] = hn::IfThenElse(positive, n[c] * inverse, hn::Set(d, c == 2 ? 1.0f : 0.0f));
    out[c] = hn::IfThenElse(negate, hn::Neg(out[c]), out[c]);
  }
}

// Colours as RGBA8 pixels. Three alphas of exactly 1 (`opaque`) blend to within a few ulps of 1,
// which converts to 255 every time.
template <class D, class V>
HWY_INLINE auto PackColors(D d, bool opaque, const V (&c)[4]) {
  return opaque ? PackUnorm8(d, c[0], c[1], c[2], 255u) : PackUnorm8(d, c[0], c[1], c[2], c[3]);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_RASTER_INTERPOLATE_INL_H_
