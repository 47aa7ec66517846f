// The À-trous denoiser (denoise.h), compiled once per SIMD target (Highway's foreach_target) and
// dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "image/denoise.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "image/denoise.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include <sys/mman.h>

#ifndef ILLUM_DENOISE_ONCE
#define ILLUM_DENOISE_ONCE
namespace illum {
namespace {

// The filter's constants, tuned on the Cornell box, the built-in scene and glTF models against
// 4096-sample references (bench/denoise.sh).
constexpr int kPasses = 5;
constexpr float kSigmaColor = 4.0f;    // in standard deviations of the pixel's noise
constexpr float kSigmaNormal = 0.1f;   // |n_p − n_q| of unit normals
constexpr float kSigmaAlbedo = 0.02f;  // |a_p − a_q|
// The first-order fit at pixels that hold two surfaces (FitRows): how far a pixel's mean normal
// falls short of a unit normal where it is wholly a mixture, the ridge on the fit's slopes (in
// unscaled normal and albedo units), and how many times the variance left in the passes' value
// the fit may differ from it by, squared, and still be taken (its weight e^(−d²/(k·var))).
constexpr float kMixedShortfall = 0.02f;
constexpr float kFitRidge = 1e-2f;
constexpr float kFitAgreement = 8.0f;
// Pixels around the picture, as far as the widest pass reaches (two taps of 2^(kPasses−1)), whose
// normal is so far from any unit normal that their weight is exactly 0.
constexpr int kPad = 2 << (kPasses - 1);
constexpr float kFarNormal = 1e10f;
// Floats after each padded row that belong to no pixel: a vector that starts at a row's last pixel
// and a tap kPad to its right still ends inside its own row (and inside the planes at the last).
constexpr int kVectorSlack = 64;

// A plane of floats padded by kPad on every side, left uninitialised until its rows are written
// (in parallel: the first touch of its pages is shared by the threads, and nothing is zeroed twice).
struct Plane {
  float* values = nullptr;
  float* data() { return values; }
  const float* data() const { return values; }
};

// One block for every plane (16 of them, 3 MiB each at 1000×600), asked to be backed by the
// kernel's transparent huge pages: first touching 4 KiB pages one by one cost the filter 10k page
// faults a call, about a fifth of its time.
class PlaneArena {
 public:
  PlaneArena(std::size_t planes, std::size_t floats) : planeFloats_(floats) {
    constexpr std::size_t kHugePage = std::size_t(2) << 20;
    const std::size_t bytes = (planes * floats * sizeof(float) + kHugePage - 1) / kHugePage * kHugePage;
    block_.reset(static_cast<float*>(std::aligned_alloc(kHugePage, bytes)));
    if (!block_) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(block_.get(), bytes, MADV_HUGEPAGE);  // a hint: without it the filter is slower, not wrong
#endif
  }
  float* plane(std::size_t i) { return block_.get() + i * planeFloats_; }

 private:
  struct Free {
    void operator()(float* p) const { std::free(p); }
  };
  std::unique_ptr<float, Free> block_;
  std::size_t planeFloats_;
};

struct Layout {
  int width, height, stride;
  std::size_t at(int x, int y) const { return std::size_t(y + kPad) * std::size_t(stride) + std::size_t(x + kPad); }
  std::size_t size() const { return std::size_t(stride) * std::size_t(height + 2 * kPad); }
};

// What a pass reads and writes: the colour, its luminance (what the colour term compares, computed
// once a pixel rather than once a tap) and its variance.
struct Planes {
  Plane color[3], luminance, variance;
};

// What guides every pass: the first hit's normal and albedo, each divided by its σ, so that a tap's
// squared distance in the six is its guides' share of the exponent.
struct Guides {
  Plane normal[3], albedo[3];
};

// The first-order fit's input (the radiance as it came, not divided by the albedo: a pixel that
// holds two surfaces is a mix of their radiances, weighed as its guides are) and its output: the
// fitted radiance and its weight against the passes' value (0: not a mixture, or no fit).
struct Fit {
  Plane radiance[3];            // in: the radiance as it came
  Plane fitted[3], weight;      // out
};

}  // namespace
}  // namespace illum
#endif

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
// pixels apart (the output's luminance written beside its colour, for the next pass).
void FilterRows(const Layout& layout, const Guides& guides, const Planes& in, Planes& out, int step, int y0, int y1) {
  const hn::ScalableTag<float> d;
  using V = hn::VFromD<decltype(d)>;
  const int lanes = int(hn::Lanes(d));
  constexpr float kB3[5] = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};
  const V sigmaColor2 = hn::Set(d, kSigmaColor * kSigmaColor), epsilon = hn::Set(d, 1e-8f);
  const auto squared = [](V a, V b) {
    const V t = hn::Sub(a, b);
    return hn::Mul(t, t);
  };
  const std::ptrdiff_t stride = layout.stride;
  const V centreWeight = hn::Set(d, kB3[2] * kB3[2]);
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
      const V invColor2 = hn::Div(hn::Set(d, 1.0f), hn::Add(hn::Mul(sigmaColor2, hn::LoadU(d, in.variance.data() + p)), epsilon));
      V sumW = hn::Zero(d), sumV = hn::Zero(d), sum[3] = {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
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
          const V dc = squared(l, hn::LoadU(d, in.luminance.data() + q));
          const V e = hn::Add(hn::Mul(dc, invColor2), dg);
          const V w = hn::Mul(hn::Set(d, kB3[dy + 2] * kB3[dx + 2]), ExpNegative(d, hn::Neg(e)));
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

// The first-order fit at pixels that hold two surfaces, rows [y0, y1). Where a pixel's samples
// saw two surfaces, its radiance, normal and albedo are the same mix of theirs: its guides match
// no neighbour's, so the passes leave it as noisy as it came (half the built-in scene's error lies
// in such pixels). A local first-order regression (as in Bitterli et al., "Nonlinearly Weighted
// First-order Regression for Denoising Monte Carlo Renderings", EGSR 2016) fits the radiance over
// the pixel and its 8 neighbours as an affine function of the guides,
//   c(q) ≈ β₀ + βᵀ(g(q) − g(p))   (g: normal and albedo; a ridge kFitRidge on β),
// and β₀ is the pixel's radiance as its mix of surfaces predicts it. It is taken in proportion to
// how far the pixel's mean normal falls short of a unit one, and only where it agrees with the
// passes' value within the noise left in that (where it does not, the radiance is not what the
// guides say: a shadow's edge, a reflection). Each lane solves its own 7×7 normal equations by
// Cholesky, the intercept last, so that it is the last forward substitution alone.
void FitRows(const Layout& layout, const Guides& guides, const Planes& filtered, Fit& fit, int y0, int y1) {
  const hn::ScalableTag<float> d;
  using V = hn::VFromD<decltype(d)>;
  const int lanes = int(hn::Lanes(d));
  constexpr int kTerms = 7;  // the normal's and the albedo's differences, then the intercept
  const std::ptrdiff_t stride = layout.stride;
  // The guides come divided by their σ: the ridge in their units.
  const float normalRidge = kFitRidge / (kSigmaNormal * kSigmaNormal), albedoRidge = kFitRidge / (kSigmaAlbedo * kSigmaAlbedo);
  const float ridge[kTerms] = {normalRidge, normalRidge, normalRidge, albedoRidge, albedoRidge, albedoRidge, 0.0f};
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0f);
  // A neighbour takes part if something was hit there (normal not 0) and it is in the picture
  // (the padding's normal is kFarNormal).
  const V unitScaled = hn::Set(d, 1.0f / (kSigmaNormal * kSigmaNormal)), farScaled = hn::Set(d, 4.0f / (kSigmaNormal * kSigmaNormal));
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < layout.width; x += lanes) {
      const std::size_t p = layout.at(x, y);
      V g[6];
      for (int k = 0; k < 3; ++k) {
        g[k] = hn::LoadU(d, guides.normal[k].data() + p);
        g[3 + k] = hn::LoadU(d, guides.albedo[k].data() + p);
      }
      // The mean normal's length (unscaled) and how much of a mixture that makes the pixel.
      const V n2 = hn::Add(hn::Add(hn::Mul(g[0], g[0]), hn::Mul(g[1], g[1])), hn::Mul(g[2], g[2]));
      const V length = hn::Sqrt(hn::Div(n2, unitScaled));
      V mixed = hn::Min(one, hn::Max(zero, hn::Div(hn::Sub(one, length), hn::Set(d, kMixedShortfall))));
      mixed = hn::IfThenElseZero(hn::Gt(n2, zero), mixed);
      if (hn::AllTrue(d, hn::Le(mixed, zero))) {
        hn::StoreU(zero, d, fit.weight.data() + p);
        continue;
      }
      // The normal equations AᵀA β = Aᵀc, lower triangle, with the ridge.
      V a[kTerms][kTerms], b[kTerms][3];
      for (int i = 0; i < kTerms; ++i) {
        for (int j = 0; j <= i; ++j) a[i][j] = zero;
        for (int k = 0; k < 3; ++k) b[i][k] = zero;
      }
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::size_t q = std::size_t(std::ptrdiff_t(p) + std::ptrdiff_t(dy) * stride + dx);
          V f[kTerms];
          for (int k = 0; k < 3; ++k) {
            f[k] = hn::LoadU(d, guides.normal[k].data() + q);
            f[3 + k] = hn::LoadU(d, guides.albedo[k].data() + q);
          }
          const V q2 = hn::Add(hn::Add(hn::Mul(f[0], f[0]), hn::Mul(f[1], f[1])), hn::Mul(f[2], f[2]));
          const auto takesPart = hn::And(hn::Gt(q2, zero), hn::Lt(q2, farScaled));
          for (int k = 0; k < 6; ++k) f[k] = hn::IfThenElseZero(takesPart, hn::Sub(f[k], g[k]));
          f[6] = hn::IfThenElseZero(takesPart, one);
          V c[3];
          for (int k = 0; k < 3; ++k) c[k] = hn::LoadU(d, fit.radiance[k].data() + q);
          for (int i = 0; i < kTerms; ++i) {
            for (int j = 0; j <= i; ++j) a[i][j] = hn::Add(a[i][j], hn::Mul(f[i], f[j]));
            for (int k = 0; k < 3; ++k) b[i][k] = hn::Add(b[i][k], hn::Mul(f[i], c[k]));
          }
        }
      for (int i = 0; i < kTerms; ++i) a[i][i] = hn::Add(a[i][i], hn::Set(d, ridge[i]));
      // Cholesky, A = LLᵀ in place; a lane whose pivot is not positive takes no fit.
      auto solvable = hn::Gt(mixed, zero);
      V inverseDiagonal[kTerms];
      for (int i = 0; i < kTerms; ++i)
        for (int j = 0; j <= i; ++j) {
          V sum = a[i][j];
          for (int k = 0; k < j; ++k) sum = hn::Sub(sum, hn::Mul(a[i][k], a[j][k]));
          if (i == j) {
            const auto positive = hn::Gt(sum, hn::Set(d, 1e-12f));
            solvable = hn::And(solvable, positive);
            a[i][i] = hn::Sqrt(hn::IfThenElse(positive, sum, one));
            inverseDiagonal[i] = hn::Div(one, a[i][i]);
          } else {
            a[i][j] = hn::Mul(sum, inverseDiagonal[j]);
          }
        }
      // Forward substitution Lz = Aᵀc; the intercept β₀ = z_last / L_last,last.
      V fitted[3];
      for (int k = 0; k < 3; ++k) {
        V z[kTerms];
        for (int i = 0; i < kTerms; ++i) {
          V sum = b[i][k];
          for (int j = 0; j < i; ++j) sum = hn::Sub(sum, hn::Mul(a[i][j], z[j]));
          z[i] = hn::Mul(sum, inverseDiagonal[i]);
        }
        fitted[k] = hn::Max(zero, hn::Mul(z[kTerms - 1], inverseDiagonal[kTerms - 1]));
        hn::StoreU(fitted[k], d, fit.fitted[k].data() + p);
      }
      // Agreement with the passes' value (both divided by the albedo, as the variance is).
      V difference[3];
      for (int k = 0; k < 3; ++k) {
        const V albedo = hn::Mul(g[3 + k], hn::Set(d, kSigmaAlbedo));
        const V demodulation = hn::IfThenElse(hn::Gt(albedo, hn::Set(d, kDenoiseMinAlbedo)), albedo, one);
        difference[k] = hn::Sub(hn::Div(fitted[k], demodulation), hn::LoadU(d, filtered.color[k].data() + p));
      }
      const V l = LuminanceOf(d, difference);
      const V noise = hn::Add(hn::Mul(hn::Set(d, kFitAgreement), hn::LoadU(d, filtered.variance.data() + p)), hn::Set(d, 1e-8f));
      const V agreement = ExpNegative(d, hn::Neg(hn::Div(hn::Mul(l, l), noise)));
      hn::StoreU(hn::IfThenElseZero(solvable, hn::Mul(mixed, agreement)), d, fit.weight.data() + p);
    }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(FilterRows);
HWY_EXPORT(LuminanceRows);
HWY_EXPORT(FitRows);

void denoise(const DenoiseInput& in, std::span<float> out) {
  const int w = in.width, h = in.height;
  const Layout layout{w, h, w + 2 * kPad + kVectorSlack};
  const std::size_t size = layout.size();
  Planes planes[2];
  Guides guides;
  Fit fit;
  PlaneArena arena(2 * 5 + 6 + 3, size);
  std::size_t next = 0;
  for (Planes& p : planes)
    for (Plane* plane : {&p.color[0], &p.color[1], &p.color[2], &p.luminance, &p.variance}) plane->values = arena.plane(next++);
  for (int k = 0; k < 3; ++k) guides.normal[k].values = arena.plane(next++), guides.albedo[k].values = arena.plane(next++);
  for (Plane* plane : {&fit.radiance[0], &fit.radiance[1], &fit.radiance[2]}) plane->values = arena.plane(next++);
  // The fit's output goes where the passes are done with: the planes the last pass read.
  const Planes& last = planes[kPasses % 2];
  Planes& spent = planes[(kPasses + 1) % 2];
  for (int k = 0; k < 3; ++k) fit.fitted[k].values = spent.color[k].values;
  fit.weight.values = spent.luminance.values;
  // Every padded row, in parallel: the padding's colour 0 and its normal so far from any unit
  // normal that a tap there weighs exactly 0; inside, the demodulated colour, the guides, and the
  // variance estimated from a pixel's own samples, which is noisy itself: blurred 3×3 (1 2 1)
  // within the picture. Inside a row only the padding is filled: the pixels are written below
  // (the first planes and the guides) or by the first pass (the second planes).
  tbb::parallel_for(tbb::blocked_range<int>(-kPad, h + kPad, 8), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const std::size_t row = std::size_t(y + kPad) * std::size_t(layout.stride);
      const bool inside = y >= 0 && y < h;
      const auto fill = [&](float* plane, float value) {
        if (!inside) {
          std::fill_n(plane + row, layout.stride, value);
          return;
        }
        std::fill_n(plane + row, kPad, value);
        std::fill(plane + row + std::size_t(kPad + w), plane + row + std::size_t(layout.stride), value);
      };
      for (Planes& p : planes)
        for (Plane* plane : {&p.color[0], &p.color[1], &p.color[2], &p.luminance, &p.variance}) fill(plane->data(), 0.0f);
      for (int k = 0; k < 3; ++k) {
        fill(guides.normal[k].data(), kFarNormal);
        fill(guides.albedo[k].data(), 0.0f);
        fill(fit.radiance[k].data(), 0.0f);
      }
      if (!inside) continue;
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x), at = layout.at(x, y);
        for (int k = 0; k < 3; ++k) {
          const float a = in.albedo[3 * i + std::size_t(k)];
          // The albedo divided out (1 where it is near black), multiplied back in at the end.
          planes[0].color[k].data()[at] = in.color[4 * i + std::size_t(k)] / demodulationOf(a);
          fit.radiance[k].data()[at] = in.color[4 * i + std::size_t(k)];
          guides.normal[k].data()[at] = in.normal[3 * i + std::size_t(k)] * (1 / kSigmaNormal);
          guides.albedo[k].data()[at] = a * (1 / kSigmaAlbedo);
        }
        float sum = 0, weight = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            const float k = float((2 - std::abs(dx)) * (2 - std::abs(dy)));
            sum += k * in.variance[std::size_t(qy) * std::size_t(w) + std::size_t(qx)];
            weight += k;
          }
        planes[0].variance.data()[at] = sum / weight;
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    HWY_DYNAMIC_DISPATCH(LuminanceRows)(layout, planes[0], rows.begin(), rows.end());
  });
  for (int pass = 0; pass < kPasses; ++pass) {
    const Planes& from = planes[pass % 2];
    Planes& to = planes[(pass + 1) % 2];
    tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
      HWY_DYNAMIC_DISPATCH(FilterRows)(layout, guides, from, to, 1 << pass, rows.begin(), rows.end());
    });
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& rows) {
    HWY_DYNAMIC_DISPATCH(FitRows)(layout, guides, last, fit, rows.begin(), rows.end());
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x), at = layout.at(x, y);
        const float weight = fit.weight.data()[at];
        for (int k = 0; k < 3; ++k) {
          float c = last.color[k].data()[at] * demodulationOf(in.albedo[3 * i + std::size_t(k)]);
          if (weight > 0) c = weight * fit.fitted[k].data()[at] + (1 - weight) * c;
          out[4 * i + std::size_t(k)] = c;
        }
        out[4 * i + 3] = in.color[4 * i + 3];
      }
  });
}

}  // namespace illum
#endif  // HWY_ONCE
