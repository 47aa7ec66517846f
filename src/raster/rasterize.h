// Rasterize stage: visits every pixel whose centre the triangle covers, with its screen-space
// barycentric weights (λ0, λ1, λ2 for vertex[0..2]).
#pragma once

#include "raster/setup.h"

namespace illum {

template <class FragmentFn>
void rasterizeTriangle(const TriangleSetup& t, FragmentFn&& fragment) {
  const std::int64_t half = kSubpixelOne / 2;
  const Real invArea = Real(1) / Real(t.area2);
  for (int y = t.minY; y <= t.maxY; ++y) {
    const std::int64_t fy = std::int64_t(y) * kSubpixelOne + half;
    const std::int64_t fx0 = std::int64_t(t.minX) * kSubpixelOne + half;
    // Evaluate the edge functions at the row's first centre, then step one pixel at a time.
    std::int64_t e0 = t.edge[0].at(fx0, fy), e1 = t.edge[1].at(fx0, fy), e2 = t.edge[2].at(fx0, fy);
    const std::int64_t s0 = t.edge[0].a * kSubpixelOne, s1 = t.edge[1].a * kSubpixelOne,
                       s2 = t.edge[2].a * kSubpixelOne;
    for (int x = t.minX; x <= t.maxX; ++x, e0 += s0, e1 += s1, e2 += s2) {
      if (e0 + t.edge[0].bias < 0 || e1 + t.edge[1].bias < 0 || e2 + t.edge[2].bias < 0) continue;
      fragment(x, y, Real(e0) * invArea, Real(e1) * invArea, Real(e2) * invArea);
    }
  }
}

}  // namespace illum
