// tile_memory.h, compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/tile_memory.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/tile_memory.h"


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

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(FillTile);
HWY_EXPORT(CopyPixels);
HWY_EXPORT(FillPixels);

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

}  // namespace illum
#endif
