// Rasterize stage: visits every pixel whose centre the triangle covers, with its screen-space
// barycentric weights (λ0, λ1, λ2 for vertex[0..2]), row by row from the bottom. The pixels can be
// limited to a rectangle (a tile): the edge functions are exact integers, so a pixel is covered
// the same way whichever rectangle it is visited from.
#pragma once

#include "raster/coverage/triangle.h"

#include <algorithm>

namespace illum {

struct PixelRect {
  int minX, minY, maxX, maxY;  // inclusive
};

template <class FragmentFn>
void rasterizeTriangle(const TriangleSetup& t, const PixelRect& rect, FragmentFn&& fragment) {
  const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
  const int minY = std::max(t.minY, rect.minY), maxY = std::min(t.maxY, rect.maxY);
  if (minX > maxX || minY > maxY) return;
  const std::int64_t half = kSubpixelOne / 2;
  const Real invArea = t.invArea;
  for (int y = minY; y <= maxY; ++y) {
    const std::int64_t fy = std::int64_t(y) * kSubpixelOne + half;
    const std::int64_t fx0 = std::int64_t(minX) * kSubpixelOne + half;
    // Evaluate the edge functions at the row's first centre, then step one pixel at a time.
    std::int64_t e0 = t.edge[0].at(fx0, fy), e1 = t.edge[1].at(fx0, fy), e2 = t.edge[2].at(fx0, fy);
    const std::int64_t s0 = t.edge[0].a * kSubpixelOne, s1 = t.edge[1].a * kSubpixelOne,
                       s2 = t.edge[2].a * kSubpixelOne;
    for (int x = minX; x <= maxX; ++x, e0 += s0, e1 += s1, e2 += s2) {
      if (e0 + t.edge[0].bias < 0 || e1 + t.edge[1].bias < 0 || e2 + t.edge[2].bias < 0) continue;
      fragment(x, y, Real(e0) * invArea, Real(e1) * invArea, Real(e2) * invArea);
    }
  }
}

template <class FragmentFn>
void rasterizeTriangle(const TriangleSetup& t, FragmentFn&& fragment) {
  rasterizeTriangle(t, PixelRect{t.minX, t.minY, t.maxX, t.maxY}, std::forward<FragmentFn>(fragment));
}

}  // namespace illum
