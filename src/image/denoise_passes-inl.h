// The À-trous passes over SIMD lanes (denoise.h), included once per Highway target by
// denoise.cpp alone: the exponential and luminance every kernel shares, one pass over rows, and the
// first pass's luminance plane.
#if defined(ILLUM_IMAGE_DENOISE_PASSES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_IMAGE_DENOISE_PASSES_INL_H_
#undef ILLUM_IMAGE_DENOISE_PASSES_INL_H_
#else
#define ILLUM_IMAGE_DENOISE_PASSES_INL_H_
#endif

#include <hwy/highway.h>

#include "image/denoise_planes.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using namespace illum::denoising;

// e^x for x ≤ 0 (below −87: 0), of multiplications and additions only (no fused
// multiply-add), so that every SIMD target gives the same bits: x = k·ln 2 + r, |r| ≤ ln 2 / 2,
// e^r by its Taylor polynomial to r⁵/120 (relative error below 2e-6: weights), times 2^k from the bits.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE V ExpNegative(D d, V x) {
  const hn::RebindToSigned<D> di;
  const auto underflows = hn::Lt(x, hn::Set(d, -87.0f));  // e^x below 2^−126: 0
  x = hn::Max(x, hn::Set(d, -87.0f));
  const V k = hn::Round(hn::Mul(x, hn::Set(d, 1.44269504088896341f)));
  // ln 2 in two parts, the first with few enough bits that k·ln2Hi is exact (Cody and Waite).
  const V r = hn::Sub(hn::Sub(x, hn::Mul(k, hn::Set(d, 0.693145751953125f))), hn::Mul(k, hn::Set(d, 1.42860682030941723e-6f)));
  V p = hn::Set(d, 1.0f / 120);
  for (const float c : {1.0f / 24, 1.0f / 6, 0.5f, 1.0f, 1.0f}) p = hn::Add(hn::Mul(p, r), hn::Set(d, c));
  const auto scale = hn::BitCast(d, hn::ShiftLeft<23>(hn::Add(hn::ConvertTo(di, k), hn::Set(di, 127))));
  return hn::IfThenZeroElse(underflows, hn::Mul(p, scale));
}

// Rec. 709 luminance of three colour vectors.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE V LuminanceOf(D d, const V (&c)[3]) {
  return hn::Add(hn::Add(hn::Mul(hn::Set(d, 0.2126f), c[0]), hn::Mul(hn::Set(d, 0.7152f), c[1])), hn::Mul(hn::Set(d, 0.0722f), c[2]));
}

// One pass over rows [y0, y1): `in` filtered into `out` (colour and variance planes), taps `step`
// pixels apart (the output's luminance written beside its colour, for the next pass); the depth
// compared where the guides have one.
void FilterRows(const Layout& layout, const Guides& guides, bool depths, const Planes& in, Planes& out, int step, int y0,
                int y1) {
  const hn::ScalableTag<float> d;
  using V = hn::VFromD<decltype(d)>;
  const int lanes = int(hn::Lanes(d));
  constexpr float kKernel[3] = {1.0f / 4, 1.0f / 2, 1.0f / 4};  // (1 2 1)/4 along each axis
  const V sigmaColor2 = hn::Set(d, kSigmaColor * kSigmaColor), epsilon = hn::Set(d, 1e-8f);
  const auto squared = [](V a, V b) {
    const V t = hn::Sub(a, b);
    return hn::Mul(t, t);
  };
  const std::ptrdiff_t stride = layout.stride;
  const V centreWeight = hn::Set(d, kKernel[1] * kKernel[1]);
  const V depthScale = hn::Set(d, 1.0f / float(step * step));  // depths differ with the taps' distance
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < layout.width; x += lanes) {  // the last vector's rest lands in the padding
      const std::size_t p = layout.at(x, y);
      V c[3], n[3], a[3];
      for (int k = 0; k < 3; ++k) {
        c[k] = hn::LoadU(d, in.color[k].data() + p);
        n[k] = hn::LoadU(d, guides.normal[k].data() + p);
        a[k] = hn::LoadU(d, guides.albedo[k].data() + p);
      }
      const V l = hn::LoadU(d, in.luminance.data() + p);
      const V z = hn::LoadU(d, guides.depth.data() + p);
      const V invColor2 = hn::Div(hn::Set(d, 1.0f), hn::Add(hn::Mul(sigmaColor2, hn::LoadU(d, in.variance.data() + p)), epsilon));
      V sumW = hn::Zero(d), sumV = hn::Zero(d), sum[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) {
            // The centre tap: every difference is 0, e^0 = 1 exactly, so its weight is the kernel's.
            sumW = hn::Add(sumW, centreWeight);
            for (int k = 0; k < 3; ++k) sum[k] = hn::Add(sum[k], hn::Mul(centreWeight, c[k]));
            sumV = hn::Add(sumV, hn::Mul(hn::Mul(centreWeight, centreWeight), hn::LoadU(d, in.variance.data() + p)));
            continue;
          }
          const std::size_t q = std::size_t(std::ptrdiff_t(p) + std::ptrdiff_t(dy * step) * stride + dx * step);
          V qc[3], dg = hn::Zero(d);
          for (int k = 0; k < 3; ++k) {
            qc[k] = hn::LoadU(d, in.color[k].data() + q);
            dg = hn::Add(dg, squared(n[k], hn::LoadU(d, guides.normal[k].data() + q)));
            dg = hn::Add(dg, squared(a[k], hn::LoadU(d, guides.albedo[k].data() + q)));
          }
          if (depths) dg = hn::Add(dg, hn::Mul(squared(z, hn::LoadU(d, guides.depth.data() + q)), depthScale));
          const V dc = squared(l, hn::LoadU(d, in.luminance.data() + q));
          const V e = hn::Add(hn::Mul(dc, invColor2), dg);
          const V w = hn::Mul(hn::Set(d, kKernel[dy + 1] * kKernel[dx + 1]), ExpNegative(d, hn::Neg(e)));
          sumW = hn::Add(sumW, w);
          for (int k = 0; k < 3; ++k) sum[k] = hn::Add(sum[k], hn::Mul(w, qc[k]));
          sumV = hn::Add(sumV, hn::Mul(hn::Mul(w, w), hn::LoadU(d, in.variance.data() + q)));
        }
      // The centre tap always counts (e = 0): sumW > 0.
      const V inv = hn::Div(hn::Set(d, 1.0f), sumW);
      V filtered[3];
      for (int k = 0; k < 3; ++k) {
        filtered[k] = hn::Mul(sum[k], inv);
        hn::StoreU(filtered[k], d, out.color[k].data() + p);
      }
      hn::StoreU(LuminanceOf(d, filtered), d, out.luminance.data() + p);
      hn::StoreU(hn::Mul(sumV, hn::Mul(inv, inv)), d, out.variance.data() + p);
    }
}

// Rows [y0, y1) of the outliers' scales (denoise.cpp's outlierScales says which pixels): a
// pixel's kind is a miss (normal 0), a hit, or the padding around the picture (kFarNormal, never a
// pixel's neighbour of its kind); its luminance is compared with the brightest of its 8 neighbours
// of its kind. The same bits as one pixel at a time: maxima, comparisons, a division and a square
// root, all exact.
void OutlierRows(const Layout& layout, const Planes& first, const Guides& guides, float* scale, int y0, int y1) {
  const hn::ScalableTag<float> d;
  using V = hn::VFromD<decltype(d)>;
  const int lanes = int(hn::Lanes(d));
  const std::ptrdiff_t stride = layout.stride;
  const auto kind = [&](std::size_t at) {  // 0: a miss, 1: a hit, 2: the padding
    V n2 = hn::Zero(d);
    for (int k = 0; k < 3; ++k) {
      const V n = hn::LoadU(d, guides.normal[k].data() + at);
      n2 = hn::Add(n2, hn::Mul(n, n));
    }
    return hn::Add(hn::IfThenElseZero(hn::Gt(n2, hn::Zero(d)), hn::Set(d, 1.0f)),
                   hn::IfThenElseZero(hn::Gt(n2, hn::Set(d, 1e19f)), hn::Set(d, 1.0f)));
  };
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < layout.width; x += lanes) {  // the last vector's rest lands in the padding
      const std::size_t p = layout.at(x, y);
      const V own = kind(p);
      V brightest = hn::Zero(d);
      auto compared = hn::FirstN(d, 0);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) continue;
          const std::size_t q = std::size_t(std::ptrdiff_t(p) + dy * stride + dx);
          const auto same = hn::Eq(kind(q), own);
          brightest = hn::IfThenElse(same, hn::Max(brightest, hn::LoadU(d, first.luminance.data() + q)), brightest);
          compared = hn::Or(compared, same);
        }
      const V l = hn::LoadU(d, first.luminance.data() + p);
      const V deviation = hn::Sqrt(hn::LoadU(d, first.variance.data() + p));
      const auto dims = hn::And(hn::And(compared, hn::Gt(l, brightest)),
                                hn::Lt(hn::Sub(l, brightest), hn::Mul(hn::Set(d, kOutlierDeviations), deviation)));
      hn::StoreU(hn::IfThenElse(dims, hn::Div(brightest, l), hn::Set(d, 1.0f)), d, scale + p);
    }
}

// The luminance plane of the first pass's input, rows [y0, y1), as FilterRows writes the others'.
void LuminanceRows(const Layout& layout, Planes& planes, int y0, int y1) {
  const hn::ScalableTag<float> d;
  const int lanes = int(hn::Lanes(d));
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < layout.width; x += lanes) {
      const std::size_t p = layout.at(x, y);
      const hn::VFromD<decltype(d)> c[3] = {hn::LoadU(d, planes.color[0].data() + p), hn::LoadU(d, planes.color[1].data() + p),
                                            hn::LoadU(d, planes.color[2].data() + p)};
      hn::StoreU(LuminanceOf(d, c), d, planes.luminance.data() + p);
    }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_IMAGE_DENOISE_PASSES_INL_H_
