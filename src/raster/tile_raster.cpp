// rasterizeDepth, compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/tile_raster.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/framebuffer.h"
#include "raster/tile_raster.h"

#include <algorithm>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

std::size_t RasterizeDepth(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t slot,
                           std::uint32_t* winners) {
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  if (minX > maxX || minY > maxY) return 0;
  const hn::ScalableTag<double> dd;   // edge functions, exact
  const hn::Rebind<Real, decltype(dd)> dr;  // barycentrics and depth, as the scalar path rounds them
  const hn::Rebind<std::uint32_t, decltype(dd)> du;
  const int lanes = int(hn::Lanes(dd));
  // Rows start on a multiple of the lane count inside the tile: a vector never leaves the tile.
  const int startX = tile.minX + (minX - tile.minX) / lanes * lanes;
  const auto iota = hn::Iota(dd, 0.0);
  const auto xIota = hn::Iota(dr, Real(startX - tile.minX));
  const auto lo = hn::Set(dr, Real(minX - tile.minX)), hi = hn::Set(dr, Real(maxX - tile.minX));
  const auto invArea = hn::Set(dr, Real(1) / Real(t.area2));
  const auto z0 = hn::Set(dr, t.z[0]), z1 = hn::Set(dr, t.z[1]), z2 = hn::Set(dr, t.z[2]);
  const auto slots = hn::Set(du, slot);
  std::int64_t step[3];
  hn::VFromD<decltype(dd)> laneStep[3];
  for (int i = 0; i < 3; ++i) {
    step[i] = t.edge[i].a * kSubpixelOne;
    laneStep[i] = iota * hn::Set(dd, double(step[i]));
  }
  const auto toReal = [&](hn::VFromD<decltype(dd)> v) {
    if constexpr (sizeof(Real) == 4) return hn::DemoteTo(dr, v);  // rounds as int64 → float does
    else return v;
  };
  const std::int64_t half = kSubpixelOne / 2;
  std::size_t passed = 0;
  for (int y = minY; y <= maxY; ++y) {
    const std::int64_t fy = std::int64_t(y) * kSubpixelOne + half;
    const std::int64_t fx = std::int64_t(startX) * kSubpixelOne + half;
    std::int64_t e[3] = {t.edge[0].at(fx, fy), t.edge[1].at(fx, fy), t.edge[2].at(fx, fy)};
    Real* depthRow = depth + (y - tile.minY) * kTileSize - tile.minX;
    std::uint32_t* winnerRow = winners + (y - tile.minY) * kTileSize - tile.minX;
    auto xs = xIota;
    for (int x = startX; x <= maxX; x += lanes, xs = xs + hn::Set(dr, Real(lanes))) {
      const auto E0 = hn::Set(dd, double(e[0])) + laneStep[0];
      const auto E1 = hn::Set(dd, double(e[1])) + laneStep[1];
      const auto E2 = hn::Set(dd, double(e[2])) + laneStep[2];
      for (int i = 0; i < 3; ++i) e[i] += lanes * step[i];
      // Inside ⇔ E + bias ≥ 0 (the top-left rule folded into the bias); converting to Real keeps
      // the sign and zero, so the test can run in the narrower lanes.
      const auto zero = hn::Zero(dr);
      const auto inside = hn::And(
          hn::And(hn::And(toReal(E0 + hn::Set(dd, double(t.edge[0].bias))) >= zero,
                          toReal(E1 + hn::Set(dd, double(t.edge[1].bias))) >= zero),
                  toReal(E2 + hn::Set(dd, double(t.edge[2].bias))) >= zero),
          hn::And(xs >= lo, xs <= hi));
      if (hn::AllFalse(dr, inside)) continue;
      const auto l0 = toReal(E0) * invArea, l1 = toReal(E1) * invArea, l2 = toReal(E2) * invArea;
      const auto z = l0 * z0 + l1 * z1 + l2 * z2;
      const auto stored = hn::LoadU(dr, depthRow + x);
      const auto pass = hn::And(inside, z < stored);
      hn::BlendedStore(z, pass, dr, depthRow + x);
      hn::BlendedStore(slots, hn::RebindMask(du, pass), du, winnerRow + x);
      passed += hn::CountTrue(dr, pass);
    }
  }
  return passed;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(RasterizeDepth);

std::size_t rasterizeDepth(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t slot,
                           std::uint32_t* winners) {
  return HWY_DYNAMIC_DISPATCH(RasterizeDepth)(t, tile, depth, slot, winners);
}

}  // namespace illum
#endif  // HWY_ONCE
