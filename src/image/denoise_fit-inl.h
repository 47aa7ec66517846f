// The first-order fit at pixels that hold two surfaces over SIMD lanes (denoise.h), included once
// per Highway target by denoise.cpp alone, after denoise_passes-inl.h (whose ExpNegative and
// LuminanceOf it uses).
#if defined(ILLUM_IMAGE_DENOISE_FIT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_IMAGE_DENOISE_FIT_INL_H_
#undef ILLUM_IMAGE_DENOISE_FIT_INL_H_
#else
#define ILLUM_IMAGE_DENOISE_FIT_INL_H_
#endif

#include <hwy/highway.h>

#include "image/denoise.h"
#include "image/denoise_passes-inl.h"
#include "image/denoise_planes.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using namespace illum::denoising;

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

#endif  // ILLUM_IMAGE_DENOISE_FIT_INL_H_
