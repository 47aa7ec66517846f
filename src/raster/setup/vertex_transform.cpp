// transformVertices, compiled once per SIMD target (Highway's foreach_target), dispatched at run
// time. Each lane runs the scalar formulas' operations in their order (no fused multiply-add:
// -ffp-contract=off), so every target gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/setup/vertex_transform.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/setup/clip.h"
#include "raster/setup/setup.h"
#include "raster/setup/vertex_transform.h"

#include <algorithm>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DD = hn::ScalableTag<double>;  // window coordinates are rounded in double (toWindow)
using DR = hn::Rebind<Real, DD>;
using VR = hn::VFromD<DR>;

// glm's mat4 · vec4(p, 1): (m0·x + m1·y) + (m2·z + m3·1), and m3·1 is m3.
HWY_INLINE VR Affine(DR d, const Mat4& m, int row, VR x, VR y, VR z) {
  return (hn::Set(d, m[0][row]) * x + hn::Set(d, m[1][row]) * y) + (hn::Set(d, m[2][row]) * z + hn::Set(d, m[3][row]));
}

// setup.h's roundHalfAway of double(v)·256, as 64-bit integers (lanes inside the guard band).
template <class V>
HWY_INLINE hn::VFromD<hn::Rebind<std::int64_t, DD>> FixedPoint(V v) {
  const DD dd;
  const hn::Rebind<std::int64_t, DD> di;
  hn::VFromD<DD> x;
  if constexpr (sizeof(Real) == 4) x = hn::PromoteTo(dd, v) * hn::Set(dd, double(kSubpixelOne));
  else x = v * hn::Set(dd, double(kSubpixelOne));
  const auto t = hn::ConvertTo(di, x);  // toward zero
  const auto fraction = x - hn::ConvertTo(dd, t);
  const auto one = hn::Set(di, 1);
  return t + hn::IfThenElseZero(hn::RebindMask(di, fraction >= hn::Set(dd, 0.5)), one) -
         hn::IfThenElseZero(hn::RebindMask(di, fraction <= hn::Set(dd, -0.5)), one);
}

void TransformVertices(const VertexTransform& t, const Vec3* positions, const Vec3* normals, std::size_t n,
                       TransformedVertices& out) {
  const DR d;
  const std::size_t lanes = hn::Lanes(d);
  const Vec2 guard = guardBandScale(t.width, t.height);
  const VR gx = hn::Set(d, guard.x), gy = hn::Set(d, guard.y), zero = hn::Zero(d), one = hn::Set(d, Real(1));
  const VR half = hn::Set(d, Real(0.5)), width = hn::Set(d, Real(t.width)), height = hn::Set(d, Real(t.height));
  for (std::size_t i = 0; i < n; i += lanes) {
    // The last vectors read from a copy padded with zeros.
    HWY_ALIGN Real padded[2][3 * hn::MaxLanes(DR())] = {};
    const Real* p = &positions[i].x;
    const Real* nrm = &normals[i].x;
    if (i + lanes > n) {
      std::memcpy(padded[0], p, (n - i) * sizeof(Vec3));
      std::memcpy(padded[1], nrm, (n - i) * sizeof(Vec3));
      p = padded[0], nrm = padded[1];
    }
    VR x, y, z, nx, ny, nz;
    hn::LoadInterleaved3(d, p, x, y, z);
    hn::LoadInterleaved3(d, nrm, nx, ny, nz);

    VR clip[4];
    for (int r = 0; r < 4; ++r) hn::StoreU(clip[r] = Affine(d, t.clipFromObject, r, x, y, z), d, out.clip[r] + i);
    for (int r = 0; r < 3; ++r) hn::StoreU(Affine(d, t.viewFromObject, r, x, y, z), d, out.eye[r] + i);

    // glm's mat3 · vec3, length and division (GL_NORMALIZE).
    const Mat3& m = t.normalFromObject;
    VR normal[3];
    for (int r = 0; r < 3; ++r)
      normal[r] = hn::Set(d, m[0][r]) * nx + hn::Set(d, m[1][r]) * ny + hn::Set(d, m[2][r]) * nz;
    const VR len = hn::Sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    const auto positive = len > zero;
    for (int r = 0; r < 3; ++r) hn::StoreU(hn::IfThenElse(positive, normal[r] / len, normal[r]), d, out.normal[r] + i);

    // clipOutcode: each plane's dot product reduces to these sums (the zero terms only change the
    // sign of a zero, which no comparison with 0 sees).
    const VR& cx = clip[0];
    const VR& cy = clip[1];
    const VR& cz = clip[2];
    const VR& cw = clip[3];
    const auto finite = hn::And(hn::And(hn::IsFinite(cx), hn::IsFinite(cy)), hn::And(hn::IsFinite(cz), hn::IsFinite(cw)));
    // Each plane's bit as a Real (distinct powers of two add exactly), whatever the lane width.
    const auto bit = [&](auto beyond, unsigned b) { return hn::IfThenElseZero(beyond, hn::Set(d, Real(b))); };
    const VR gxw = gx * cw, gyw = gy * cw;
    const VR code = ((bit(cz + cw < zero, 1u) + bit(hn::Neg(cz) + cw < zero, 2u)) +
                     (bit(cx + gxw < zero, 4u) + bit(hn::Neg(cx) + gxw < zero, 8u))) +
                    (bit(cy + gyw < zero, 16u) + bit(hn::Neg(cy) + gyw < zero, 32u));
    HWY_ALIGN Real codes[hn::MaxLanes(DR())];
    hn::Store(hn::IfThenElse(finite, code, hn::Set(d, Real(kNotFinite))), d, codes);
    for (std::size_t k = 0; k < lanes; ++k) out.outcode[i + k] = std::uint32_t(codes[k]);

    // toWindow.
    const VR invW = one / cw;
    hn::StoreU(invW, d, out.invW + i);
    hn::StoreU((cz * invW + one) * half, d, out.windowZ + i);
    const hn::Rebind<std::int64_t, DD> di;
    hn::StoreU(FixedPoint((cx * invW + one) * half * width), di, out.windowX + i);
    hn::StoreU(FixedPoint((cy * invW + one) * half * height), di, out.windowY + i);
  }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(TransformVertices);

void transformVertices(const VertexTransform& t, const Vec3* positions, const Vec3* normals, std::size_t n,
                       TransformedVertices& out) {
  HWY_DYNAMIC_DISPATCH(TransformVertices)(t, positions, normals, n, out);
}

}  // namespace illum
#endif  // HWY_ONCE
