// A triangle as coverage reads it: fixed-point edge functions, depths, 1/w and pixel bounds on
// screen. Setup (setup/setup.h) fills it from three vertices; coverage, interpolation and the
// depth bounds only read it, so it lives here, below setup, as llvmpipe's rasterizer defines the
// triangle its setup fills.
#pragma once

#include <illum/real.h>

#include "raster/frame_context.h"

#include <array>
#include <cstdint>

namespace illum {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixelOne = 1 << kSubpixelBits;

// E(x, y) = a·x + b·y + c over fixed-point window coordinates; the inside is E > 0, or E = 0 on a
// top or left edge (the bias folds that rule in: inside ⇔ E + bias ≥ 0).
// a and b are coordinate differences, within ±2^24 inside the guard band (clip.h).
struct EdgeFunction {
  std::int32_t a, b;
  std::int64_t c;
  std::int32_t bias;
  std::int64_t at(std::int64_t x, std::int64_t y) const { return a * x + b * y + c; }
};

// A triangle's geometry on screen, counter-clockwise (setup swaps the last two vertices of a
// clockwise one and says so). Its attributes travel beside it (draw_record.h). Left uninitialized
// until setupTriangle fills it: records are written once, straight into their arena.
struct TriangleSetup {
  std::array<Real, 3> z;                        // window depth in [0,1]
  std::array<Real, 3> invW;                     // 1/w_clip, for perspective-correct attributes
  std::array<EdgeFunction, 3> edge;             // edge[i] is opposite vertex i
  std::int64_t area2;                           // twice the area, fixed-point², > 0
  Real invArea;                                 // Real(1) / Real(area2): λi = E_i · invArea
  bool frontFacing;                             // counter-clockwise as submitted (GL_CCW front)
  bool swapped;                                 // vertices 1 and 2 swapped to make it counter-clockwise
  bool floatExact;                              // every edge value in the bounds (at their pixels' samples
                                                // too, when multisampled) is an integer ≤ 2^24
  int minX, maxX, minY, maxY;                   // pixels to visit, inside the viewport
};

// The triangle as a pass at `sample` would have set it up (setupTriangle with that offset): the
// same edges moved by the offset, so that its pixel centres test coverage and depth at the
// sample, exactly; its bounds stay the (widened) ones of `t`.
inline TriangleSetup atSample(const TriangleSetup& t, SubpixelOffset sample) {
  TriangleSetup moved = t;
  for (EdgeFunction& e : moved.edge) e.c += std::int64_t(e.a) * sample.x + std::int64_t(e.b) * sample.y;
  moved.floatExact = false;  // its values at the bounds' centres were not bounded for the offset
  return moved;
}

}  // namespace illum
