// tile_memory.h, compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/tile/tile_memory.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/tile/multisample.h"
#include "raster/tile/tile_memory.h"

#include <cstring>


HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void FillTile(Real* depth, std::uint32_t* color, std::size_t n, std::uint32_t clear) {
  const hn::ScalableTag<Real> dr;
  const hn::ScalableTag<std::uint32_t> du;
  const auto one = hn::Set(dr, Real(1));
  const auto word = hn::Set(du, clear);
  std::size_t i = 0;
  for (; i + hn::Lanes(dr) <= n; i += hn::Lanes(dr)) hn::StoreU(one, dr, depth + i);
  for (; i < n; ++i) depth[i] = Real(1);
  for (i = 0; i + hn::Lanes(du) <= n; i += hn::Lanes(du)) hn::StoreU(word, du, color + i);
  for (; i < n; ++i) color[i] = clear;
}

// Pixels are moved as 32-bit words through unaligned loads and stores (an image's rows are only
// 4-byte aligned, and Highway's unaligned accesses have no alignment needs beyond the lane's).
std::size_t CopyPixels(const std::uint32_t* src, std::ptrdiff_t srcStride, std::uint8_t* dst, std::ptrdiff_t dstStride,
                       int count, int rows, std::uint32_t background) {
  const hn::ScalableTag<std::uint32_t> du;
  const int lanes = int(hn::Lanes(du));
  const auto back = hn::Set(du, background);
  std::size_t unlike = 0;
  for (int r = 0; r < rows; ++r) {
    const auto* from = reinterpret_cast<const std::uint32_t*>(reinterpret_cast<const std::uint8_t*>(src) + r * srcStride);
    auto* to = reinterpret_cast<std::uint32_t*>(dst + r * dstStride);
    int i = 0;
    for (; i + lanes <= count; i += lanes) {
      const auto v = hn::LoadU(du, from + i);
      hn::StoreU(v, du, to + i);
      unlike += hn::CountTrue(du, hn::Ne(v, back));
    }
    if (i < count) {
      const auto m = hn::FirstN(du, std::size_t(count - i));
      const auto v = hn::MaskedLoad(m, du, from + i);
      hn::BlendedStore(v, m, du, to + i);
      unlike += hn::CountTrue(du, hn::And(m, hn::Ne(v, back)));
    }
  }
  return unlike;
}

void FillPixels(std::uint8_t* dst, std::ptrdiff_t dstStride, int count, int rows, std::uint32_t value) {
  const hn::ScalableTag<std::uint32_t> du;
  const int lanes = int(hn::Lanes(du));
  const auto word = hn::Set(du, value);
  for (int r = 0; r < rows; ++r) {
    auto* to = reinterpret_cast<std::uint32_t*>(dst + r * dstStride);
    int i = 0;
    for (; i + lanes <= count; i += lanes) hn::StoreU(word, du, to + i);
    if (i < count) hn::BlendedStore(word, hn::FirstN(du, std::size_t(count - i)), du, to + i);
  }
}

// resolvePixels (multisample.h), a vector of samples at a time: each pixel whose samples agree is
// their word at once (compared with its first lane by lane), the others resolved one by one.
std::size_t ResolvePixels(const std::uint32_t* src, int samples, int srcRowPixels, std::uint8_t* dst,
                          std::ptrdiff_t dstStride, int count, int rows, std::uint32_t background) {
  const hn::ScalableTag<std::uint32_t> du;
  const int lanes = int(hn::Lanes(du));
  std::size_t unlike = 0;
  const auto put = [&](std::uint8_t* to, std::uint32_t word) {
    std::memcpy(to, &word, 4);
    unlike += word != background;
  };
  if (samples > lanes || lanes > 64) {
    for (int r = 0; r < rows; ++r)
      for (int x = 0; x < count; ++x)
        put(dst + r * dstStride + 4 * x, resolvePixel(src + (std::size_t(r) * std::size_t(srcRowPixels) + std::size_t(x)) * std::size_t(samples), samples));
    return unlike;
  }
  HWY_ALIGN std::uint32_t firstOf[hn::MaxLanes(du)];
  for (int k = 0; k < lanes; ++k) firstOf[k] = std::uint32_t(k & ~(samples - 1));
  const auto first = hn::SetTableIndices(du, firstOf);
  const std::uint64_t group = samples >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << samples) - 1;
  const int perVector = lanes / samples;
  // The lanes that are a pixel's first sample.
  const auto leads = hn::Eq(hn::And(hn::Iota(du, 0), hn::Set(du, std::uint32_t(samples - 1))), hn::Zero(du));
  const auto backgroundWord = hn::Set(du, background);
#if HWY_TARGET != HWY_SCALAR
  // Mixed pixels summed in the vector: 2, 4 or 8 samples (a vector holds whole pixels).
  const bool sumsInVector = samples >= 2 && samples <= 8 && lanes >= 4;
  const int shift = __builtin_ctz(unsigned(samples));
  const auto channel = hn::Set(du, 0xFFu), redAndBlue = hn::Set(du, 0x00FF00FFu);
  const auto half = hn::Set(du, std::uint32_t(samples / 2)), halves = hn::Set(du, std::uint32_t(samples / 2) * 0x10001u);
  // Opaque samples, some pixels mixed: each pixel's colour is (s + samples/2) / samples of its
  // channels' sums s (resolvePixel's shifts), all pixels of the vector at once, in every lane of
  // the pixel. Red and blue are summed together, 16 bits apart, green alone (each sum ≤ 8·255 <
  // 2^16), over a pixel's lanes: swapped neighbours, swapped pairs (inside a 128-bit block),
  // swapped blocks.
  const auto resolveOpaque = [&](auto w) {
    const auto sumOfPixel = [&](auto v) {
      v = hn::Add(v, hn::Shuffle2301(v));
      if (samples >= 4) v = hn::Add(v, hn::Shuffle1032(v));
      if (samples >= 8) v = hn::Add(v, hn::SwapAdjacentBlocks(v));
      return v;
    };
    const auto redBlue = sumOfPixel(hn::And(w, redAndBlue)), green = sumOfPixel(hn::And(hn::ShiftRight<8>(w), channel));
    return hn::Or(hn::Or(hn::Set(du, 0xFF000000u), hn::And(hn::ShiftRightSame(hn::Add(redBlue, halves), shift), redAndBlue)),
                  hn::ShiftLeft<8>(hn::ShiftRightSame(hn::Add(green, half), shift)));
  };
#endif
#if HWY_TARGET != HWY_SCALAR
  // A vector of pixels from `samples` vectors of samples, where every pixel's samples agree or all
  // are opaque: each vector's pixels' words (in their first lanes) brought together by halving
  // (ConcatEven keeps the even lanes of two vectors), and stored as one. False (nothing written)
  // where some pixel is neither.
  const auto wholeVector = [&](const std::uint32_t* from, std::uint8_t* to) {
    // Nothing drawn there, as in much of a model's tiles: the background, tested at once.
    auto drawn = hn::Zero(du);
    for (int k = 0; k < samples; ++k)
      drawn = hn::Or(drawn, hn::Xor(hn::LoadU(du, from + std::size_t(k) * std::size_t(lanes)), backgroundWord));
    if (hn::AllTrue(du, hn::Eq(drawn, hn::Zero(du)))) {
      hn::StoreU(backgroundWord, du, reinterpret_cast<std::uint32_t*>(to));
      return true;
    }
    hn::Vec<decltype(du)> v[kSamplesMax];
    for (int k = 0; k < samples; ++k) {
      const auto w = hn::LoadU(du, from + std::size_t(k) * std::size_t(lanes));
      if (hn::AllTrue(du, hn::Eq(w, hn::TableLookupLanes(w, first)))) {
        v[k] = w;
        continue;
      }
      if (!(sumsInVector && hn::AllTrue(du, hn::Eq(hn::ShiftRight<24>(w), channel)))) return false;
      v[k] = resolveOpaque(w);
    }
    for (int n = samples; n > 1; n /= 2)
      for (int k = 0; k < n / 2; ++k) v[k] = hn::ConcatEven(du, v[2 * k + 1], v[2 * k]);
    hn::StoreU(v[0], du, reinterpret_cast<std::uint32_t*>(to));
    unlike += hn::CountTrue(du, hn::Ne(v[0], backgroundWord));
    return true;
  };
#endif
  for (int r = 0; r < rows; ++r) {
    const std::uint32_t* row = src + std::size_t(r) * std::size_t(srcRowPixels) * std::size_t(samples);
    std::uint8_t* to = dst + r * dstStride;
    for (int x = 0; x < count; x += perVector) {
#if HWY_TARGET != HWY_SCALAR
      // (A vector's worth of pixels at a time where the row has them; its first pixel then starts
      // a group of `samples` vectors.)
      if (samples <= 8 && x % lanes == 0 && x + lanes <= count &&
          wholeVector(row + std::size_t(x) * std::size_t(samples), to + 4 * x)) {
        x += lanes - perVector;
        continue;
      }
#endif
      const auto w = hn::LoadU(du, row + std::size_t(x) * std::size_t(samples));
      const auto agree = hn::Eq(w, hn::TableLookupLanes(w, first));
      if (x + perVector <= count && hn::AllTrue(du, agree)) {  // each pixel's samples agree: its first
        // (Through a buffer: a masked store is emulated on some targets by a read and write of the
        // whole vector, which could reach a neighbouring tile that another thread is copying.)
        HWY_ALIGN std::uint32_t firsts[hn::MaxLanes(du)];
        hn::Store(hn::Compress(w, leads), du, firsts);
        std::memcpy(to + 4 * x, firsts, 4 * std::size_t(perVector));
        unlike += hn::CountTrue(du, hn::And(leads, hn::Ne(w, backgroundWord)));
        continue;
      }
#if HWY_TARGET != HWY_SCALAR
      if (sumsInVector && x + perVector <= count && hn::AllTrue(du, hn::Eq(hn::ShiftRight<24>(w), channel))) {
        const auto resolved = resolveOpaque(w);
        HWY_ALIGN std::uint32_t firsts[hn::MaxLanes(du)];
        hn::Store(hn::Compress(resolved, leads), du, firsts);
        std::memcpy(to + 4 * x, firsts, 4 * std::size_t(perVector));
        unlike += hn::CountTrue(du, hn::And(leads, hn::Ne(resolved, backgroundWord)));
        continue;
      }
#endif
      std::uint8_t bytes[8] = {};
      hn::StoreMaskBits(du, agree, bytes);
      std::uint64_t same = 0;
      std::memcpy(&same, bytes, sizeof same);
      for (int g = 0; g < perVector && x + g < count; ++g) {
        const std::uint32_t* pixel = row + std::size_t(x + g) * std::size_t(samples);
        put(to + 4 * (x + g), (same >> (g * samples) & group) == group ? pixel[0] : resolvePixel(pixel, samples));
      }
    }
  }
  return unlike;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(FillTile);
HWY_EXPORT(CopyPixels);
HWY_EXPORT(FillPixels);
HWY_EXPORT(ResolvePixels);

void fillTile(Real* depth, std::uint32_t* color, std::size_t n, std::uint32_t clear) {
  HWY_DYNAMIC_DISPATCH(FillTile)(depth, color, n, clear);
}

std::size_t copyPixels(const std::uint32_t* src, std::ptrdiff_t srcStride, std::uint8_t* dst, std::ptrdiff_t dstStride,
                       int count, int rows, std::uint32_t background) {
  return HWY_DYNAMIC_DISPATCH(CopyPixels)(src, srcStride, dst, dstStride, count, rows, background);
}

void fillPixels(std::uint8_t* dst, std::ptrdiff_t dstStride, int count, int rows, std::uint32_t value) {
  HWY_DYNAMIC_DISPATCH(FillPixels)(dst, dstStride, count, rows, value);
}

std::size_t resolvePixels(const std::uint32_t* src, int samples, int srcRowPixels, std::uint8_t* dst,
                          std::ptrdiff_t dstStride, int count, int rows, std::uint32_t background) {
  return HWY_DYNAMIC_DISPATCH(ResolvePixels)(src, samples, srcRowPixels, dst, dstStride, count, rows, background);
}

}  // namespace illum
#endif
