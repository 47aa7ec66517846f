// depth_bounds.h; the blocks' farthest depths a vector at a time (Highway's foreach_target,
// dispatched at run time).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/coverage/depth_bounds.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/coverage/depth_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A block's rows, each kBlock·samples depths side by side, in vectors of `d`.
template <class D>
HWY_INLINE Real Farthest(D d, const Real* first, int samples) {
  const int n = DepthBounds::kBlock * samples, lanes = int(hn::Lanes(d));
  auto farthest = hn::LoadU(d, first);
  for (int y = 0; y < DepthBounds::kBlock; ++y) {
    const Real* row = first + std::size_t(y) * kTileSize * std::size_t(samples);
    for (int i = 0; i < n; i += lanes) farthest = hn::Max(farthest, hn::LoadU(d, row + i));
  }
  return hn::GetLane(hn::MaxOfLanes(d, farthest));
}

Real FarthestDepthInBlock(const Real* depth, int samples, int bx, int by) {
  constexpr int kRow = DepthBounds::kBlock;
  const Real* first =
      depth + (std::size_t(by) * kRow * kTileSize + std::size_t(bx) * kRow) * std::size_t(samples);
  // A row holds kBlock depths a sample: vectors of kBlock lanes, or of 4·kBlock with 4 or more samples.
  if (samples >= 4) return Farthest(hn::CappedTag<Real, 4 * kRow>(), first, samples);
  return Farthest(hn::CappedTag<Real, kRow>(), first, samples);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(FarthestDepthInBlock);

Real farthestDepthInBlock(const Real* depth, int samples, int bx, int by) {
  return HWY_DYNAMIC_DISPATCH(FarthestDepthInBlock)(depth, samples, bx, by);
}

DepthBounds::Blocks DepthBounds::blocksOf(const TriangleSetup& t) const {
  const int minX = std::max(t.minX, tile_.minX) - tile_.minX, maxX = std::min(t.maxX, tile_.maxX) - tile_.minX;
  const int minY = std::max(t.minY, tile_.minY) - tile_.minY, maxY = std::min(t.maxY, tile_.maxY) - tile_.minY;
  if (minX > maxX || minY > maxY) return {0, -1, 0};
  const int bx0 = minX / kBlock, bx1 = maxX / kBlock;
  return {minY / kBlock, maxY / kBlock, std::uint16_t(((2u << bx1) - 1) & ~((1u << bx0) - 1))};
}

bool DepthBounds::hidden(const TriangleSetup& t) {
  const Blocks blocks = blocksOf(t);
  if (blocks.columns == 0) return true;
  // An interpolated depth is a convex combination of the vertices' depths, computed with a few
  // roundings (edge value, 1/area, products, sums: well under 16 units in the last place of the
  // largest |z|); 64 of them keep the skip on the safe side.
  const Real nearest = std::min({t.z[0], t.z[1], t.z[2]});
  const Real largest = std::max({Real(1), std::abs(t.z[0]), std::abs(t.z[1]), std::abs(t.z[2])});
  const Real threshold = nearest - 64 * std::numeric_limits<Real>::epsilon() * largest;
  if (!(threshold >= 0)) return false;  // (no depth is nearer than 0; and NaN)
  // The blocks known first: a block that decides costs a look-up, one worked out a pass over it.
  for (int by = blocks.minY; by <= blocks.maxY; ++by)
    for (unsigned known = blocks.columns & ~unsigned(stale_[by]); known != 0; known &= known - 1)
      if (farthest_[by][__builtin_ctz(known)] > threshold) return false;
  for (int by = blocks.minY; by <= blocks.maxY; ++by)
    for (unsigned stale = stale_[by] & blocks.columns; stale != 0; stale &= stale - 1) {
      const int bx = __builtin_ctz(stale);
      farthest_[by][bx] = farthestDepthInBlock(depth_, samples_, bx, by);
      stale_[by] &= std::uint16_t(~(1u << bx));
      if (farthest_[by][bx] > threshold) return false;
    }
  return true;
}

}  // namespace illum
#endif
