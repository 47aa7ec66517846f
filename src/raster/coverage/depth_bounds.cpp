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

// The farthest of the depths of block (bx, by): its rows, each kBlock·samples depths side by side,
// in vectors of `d`.
template <class D>
HWY_INLINE Real FarthestIn(D d, const DepthBounds::State& s, int bx, int by) {
  constexpr int kRow = DepthBounds::kBlock;
  const std::size_t samples = std::size_t(s.samples);
  const Real* first = s.depth + (std::size_t(by) * kRow * kTileSize + std::size_t(bx) * kRow) * samples;
  const int n = kRow * s.samples, lanes = int(hn::Lanes(d));
  auto farthest = hn::LoadU(d, first);
  for (int y = 0; y < kRow; ++y) {
    const Real* row = first + std::size_t(y) * kTileSize * samples;
    for (int i = 0; i < n; i += lanes) farthest = hn::Max(farthest, hn::LoadU(d, row + i));
  }
  return hn::GetLane(hn::MaxOfLanes(d, farthest));
}

HWY_INLINE Real FarthestInBlock(const DepthBounds::State& s, int bx, int by) {
  // A block's row holds kBlock depths a sample: vectors of kBlock lanes, or of 4·kBlock with 4
  // samples or more.
  if (s.samples >= 4) return FarthestIn(hn::CappedTag<Real, 4 * DepthBounds::kBlock>(), s, bx, by);
  return FarthestIn(hn::CappedTag<Real, DepthBounds::kBlock>(), s, bx, by);
}

bool Hidden(DepthBounds::State& s, const TriangleSetup& t) {
  constexpr int kBlock = DepthBounds::kBlock, kBlocks = DepthBounds::kBlocks;
  const int minX = std::max(t.minX, s.tile.minX) - s.tile.minX, maxX = std::min(t.maxX, s.tile.maxX) - s.tile.minX;
  const int minY = std::max(t.minY, s.tile.minY) - s.tile.minY, maxY = std::min(t.maxY, s.tile.maxY) - s.tile.minY;
  if (minX > maxX || minY > maxY) {
    s.asked = {0, -1, 0};
    return true;
  }
  const int bx0 = minX / kBlock, bx1 = maxX / kBlock;
  const unsigned columns = ((2u << bx1) - 1) & ~((1u << bx0) - 1);
  s.asked = {minY / kBlock, maxY / kBlock, std::uint16_t(columns)};
  // An interpolated depth is a convex combination of the vertices' depths, computed with a few
  // roundings (edge value, 1/area, products, sums: well under 16 units in the last place of the
  // largest |z|); 64 of them keep the skip on the safe side.
  const Real nearest = std::min({t.z[0], t.z[1], t.z[2]});
  const Real largest = std::max({Real(1), std::abs(t.z[0]), std::abs(t.z[1]), std::abs(t.z[2])});
  const Real threshold = nearest - 64 * std::numeric_limits<Real>::epsilon() * largest;
  if (!(threshold >= 0)) return false;  // (no depth is nearer than 0; and NaN)
  // The blocks known first, a row of them at a time: a block that decides costs a look-up, one
  // worked out a pass over its depths.
  const hn::CappedTag<Real, kBlocks> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const int lanes = int(hn::Lanes(d));
  const auto far = hn::Set(d, threshold);
  const auto bit = hn::Shl(hn::Set(du, 1), hn::Iota(du, 0));  // lane i: 1 << i
  for (int by = s.asked.minY; by <= s.asked.maxY; ++by) {
    const unsigned known = columns & ~unsigned(s.stale[by]);
    for (int i = 0; i < kBlocks; i += lanes) {
      const auto mine = hn::RebindMask(d, hn::TestBit(hn::Set(du, known >> i), bit));
      if (!hn::AllFalse(d, hn::And(mine, hn::Gt(hn::Load(d, s.farthest[by] + i), far)))) return false;
    }
  }
  for (int by = s.asked.minY; by <= s.asked.maxY; ++by)
    for (unsigned stale = s.stale[by] & columns; stale != 0; stale &= stale - 1) {
      const int bx = __builtin_ctz(stale);
      s.farthest[by][bx] = FarthestInBlock(s, bx, by);
      s.stale[by] &= std::uint16_t(~(1u << bx));
      if (s.farthest[by][bx] > threshold) return false;
    }
  return true;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(Hidden);

bool DepthBounds::hidden(const TriangleSetup& t) { return HWY_DYNAMIC_DISPATCH(Hidden)(s_, t); }

}  // namespace illum
#endif
