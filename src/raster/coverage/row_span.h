// The pixels of a row that a triangle may cover (a sample of them, when multisampled), from its
// edge functions: what the multisampled coverage kernel visits of a triangle's bounds.
#pragma once

#include "raster/coverage/triangle.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace illum {

// Which pixels of a row may have a sample inside the triangle: for each edge, where its value at
// the pixel centre plus the largest of its samples' offsets keeps E + bias ≥ 0. Along a row E moves
// by A = 256·a a pixel and from row to row by B = 256·b, so each edge's bound is a quotient that
// moves by −B/A a row, stepped in double. The span is only ever wider than the exact one: each
// bound is widened by a thousandth of a pixel, far more than double's error on quotients below
// 2^32 in magnitude, so a pixel is at worst tested needlessly (exactly, by the coverage kernel),
// never left out.
//
// The bounds of all the rows a triangle's bounds hold are worked out at once (narrowRows, a vector
// of rows at a time): row by row, each edge's three branches and scalar rounding cost more than
// the row's own tests at 4 samples.
struct RowSpans {
  int minX, minY;        // the bounds' first pixel, where the quotients are taken
  std::int64_t need[3];  // −(reach + bias) − E at (minX, minY): what A·dx + B·dy must reach
  std::int64_t B[3];     // 256·b: E's step a row
  double q0[3], dq[3];   // need / A and −B / A, where A ≠ 0
  bool rising[3];        // A > 0: the bound is the row's first pixel; A < 0: its last
  // `samples`: where a pixel's samples lie from its centre (none: the centre alone).
  RowSpans(const TriangleSetup& t, std::span<const SubpixelOffset> samples, int minX_, int minY_)
      : minX(minX_), minY(minY_) {
    const std::int64_t half = kSubpixelOne / 2;
    for (int i = 0; i < 3; ++i) {
      const EdgeFunction& e = t.edge[i];
      std::int64_t reach = samples.empty() ? 0 : std::numeric_limits<std::int64_t>::min();
      for (const SubpixelOffset& o : samples) reach = std::max(reach, std::int64_t(e.a) * o.x + std::int64_t(e.b) * o.y);
      need[i] = -(reach + e.bias) - e.at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half);
      B[i] = std::int64_t(e.b) * kSubpixelOne;
      // (Through 1/A: within a few units in the last place of the quotients, far inside the slack.)
      const double perA = e.a != 0 ? 1.0 / double(std::int64_t(e.a) * kSubpixelOne) : 0.0;
      q0[i] = double(need[i]) * perA;
      dq[i] = -double(B[i]) * perA;
      rising[i] = e.a > 0;
    }
  }
};

// Narrows [minX, maxX] for each of `count` rows from the spans' first (minY): row r's pixels
// first[r] .. last[r], first[r] > last[r] where none is left. first and last have room for
// kRowSpansRoom words past `count` (a vector's rows are stored whole). (tile_raster.cpp, SIMD.)
constexpr int kRowSpansRoom = 16;
void narrowRows(const RowSpans& spans, const TriangleSetup& t, int count, int maxX, std::int32_t* first,
                std::int32_t* last);

}  // namespace illum
