// The pixels of a row that a triangle may cover (a sample of them, when multisampled), from its
// edge functions: what the multisampled coverage kernel and the deferred colours visit of a
// triangle's bounds.
#pragma once

#include "raster/setup/setup.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace illum {

// Which pixels of a row may have a sample inside the triangle: for each edge, where its value at
// the pixel centre plus the largest of its samples' offsets keeps E + bias ≥ 0. E moves by
// A = 256·a a pixel, so the bound is a quotient: taken in double through 1/A, then checked and
// moved by a pixel in exact integers.
struct RowSpans {
  std::int64_t need[3];  // −(reach + bias): E at the centre must be at least this
  double inverse[3];     // 1/A, 0 where A = 0
  // `samples`: where a pixel's samples lie from its centre (none: the centre alone).
  RowSpans(const TriangleSetup& t, std::span<const SubpixelOffset> samples) {
    for (int i = 0; i < 3; ++i) {
      std::int64_t reach = samples.empty() ? 0 : std::numeric_limits<std::int64_t>::min();
      for (const SubpixelOffset& o : samples)
        reach = std::max(reach, std::int64_t(t.edge[i].a) * o.x + std::int64_t(t.edge[i].b) * o.y);
      need[i] = -(reach + t.edge[i].bias);
      const std::int64_t A = std::int64_t(t.edge[i].a) * kSubpixelOne;
      inverse[i] = A != 0 ? 1.0 / double(A) : 0.0;
    }
  }
  // Narrows [minX, maxX] (pixel centres at fy); false when no pixel is left.
  bool narrow(const TriangleSetup& t, std::int64_t fy, int& minX, int& maxX) const {
    const int x0 = minX;
    const std::int64_t fx = std::int64_t(x0) * kSubpixelOne + kSubpixelOne / 2;
    for (int i = 0; i < 3; ++i) {
      const std::int64_t short_ = need[i] - t.edge[i].at(fx, fy);  // what k·A must reach, k pixels on
      if (t.edge[i].a == 0) {
        if (short_ > 0) return false;
        continue;
      }
      // The least k with k·A ≥ short for A > 0, the largest for A < 0.
      const std::int64_t A = std::int64_t(t.edge[i].a) * kSubpixelOne;
      const double q = double(short_) * inverse[i];
      if (!(q > -32768 && q < 32768)) {  // the whole row, or none of it
        if (t.edge[i].a > 0 ? q >= 32768 : q <= -32768) return false;
        continue;
      }
      if (A > 0) {
        std::int64_t k = std::int64_t(std::ceil(q));
        if (k * A < short_) ++k;
        else if ((k - 1) * A >= short_) --k;
        minX = int(std::max<std::int64_t>(minX, x0 + k));
      } else {
        std::int64_t k = std::int64_t(std::floor(q));
        if (k * A < short_) --k;
        else if ((k + 1) * A >= short_) ++k;
        maxX = int(std::min<std::int64_t>(maxX, x0 + k));
      }
    }
    return minX <= maxX;
  }
};

}  // namespace illum
