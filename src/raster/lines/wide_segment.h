// Wide line segments in window space, the one rule the overlays and GL_LINES share: a pixel is
// covered when its sample point (the centre plus the pass's multisample offset) lies within half
// the width of the segment (round ends, so that the segments of a polyline join without gaps).
#pragma once

#include "raster/frame_context.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <optional>

namespace illum {

// A segment after near-plane clipping: its window endpoints (x, y in pixels, y up; z in [0,1]
// where visible), their clip w, and where they lie on the segment before clipping (0..1).
struct WindowSegment {
  Vec3 a{0}, b{0};
  Real wA = 1, wB = 1;
  Real tA = 0, tB = 1;
};

// The clip-space segment a→b clipped against the near plane (z ≥ −w) and put in window
// coordinates; nothing if it lies wholly in front of the near plane or is absurdly long.
inline std::optional<WindowSegment> windowSegment(const FrameContext& frame, Vec4 a, Vec4 b) {
  WindowSegment s;
  const Real da = a.z + a.w, db = b.z + b.w;
  if (da < 0 && db < 0) return std::nullopt;
  const Vec4 a0 = a, b0 = b;
  if (da < 0) s.tA = da / (da - db), a = a0 + s.tA * (b0 - a0);
  if (db < 0) s.tB = da / (da - db), b = a0 + s.tB * (b0 - a0);
  if (!(a.w > 0) || !(b.w > 0)) return std::nullopt;
  const auto window = [&](const Vec4& c) {
    return Vec3((c.x / c.w + 1) * Real(0.5) * Real(frame.width), (c.y / c.w + 1) * Real(0.5) * Real(frame.height),
                (c.z / c.w + 1) * Real(0.5));
  };
  s.a = window(a), s.b = window(b);
  s.wA = a.w, s.wB = b.w;
  const Real length = glm::length(Vec2(s.b - s.a));
  if (!std::isfinite(length) || length > Real(1e5)) return std::nullopt;
  return s;
}

// Distance from p to the segment ab, and where along it (0..1) the nearest point is.
inline std::pair<Real, Real> toSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const Real len2 = glm::dot(d, d);
  const Real t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, Real(0), Real(1)) : Real(0);
  return {glm::length(a + t * d - p), t};
}

// The x range, on the horizontal line at height py, of the points within `radius` of the segment ab
// (a capsule: the union of the discs at its ends and the band between them, one interval since it
// is convex); empty (lo > hi) when the line misses it.
inline std::pair<Real, Real> capsuleSpan(const Vec2& a, const Vec2& b, Real radius, Real py) {
  Real lo = std::numeric_limits<Real>::infinity(), hi = -lo;
  const auto disc = [&](const Vec2& c) {
    const Real dy = py - c.y, h2 = radius * radius - dy * dy;
    if (h2 < 0) return;
    const Real h = std::sqrt(h2);
    lo = std::min(lo, c.x - h), hi = std::max(hi, c.x + h);
  };
  disc(a);
  disc(b);
  const Vec2 d = b - a;
  const Real length = glm::length(d);
  if (length > 0) {
    // The band: |cross(p − a, u)| ≤ radius and 0 ≤ dot(p − a, u) ≤ length, with u = d / length.
    const Vec2 u = d / length;
    const Real dy = py - a.y;
    Real bandLo = -std::numeric_limits<Real>::infinity(), bandHi = -bandLo;
    const auto within = [&](Real coefficient, Real offset, Real min, Real max) {  // min ≤ coefficient·x + offset ≤ max
      if (coefficient == 0) {
        if (offset < min || offset > max) bandLo = 1, bandHi = 0;
        return;
      }
      Real x0 = (min - offset) / coefficient, x1 = (max - offset) / coefficient;
      if (x0 > x1) std::swap(x0, x1);
      bandLo = std::max(bandLo, x0), bandHi = std::min(bandHi, x1);
    };
    within(u.y, -dy * u.x, -radius, radius);  // (x − a.x)·u.y − dy·u.x, with x relative to a.x
    within(u.x, dy * u.y, 0, length);         // (x − a.x)·u.x + dy·u.y
    if (bandLo <= bandHi) lo = std::min(lo, a.x + bandLo), hi = std::max(hi, a.x + bandHi);
  }
  return {lo, hi};
}

// Calls visit(x, y, t) for every pixel of the frame the segment `width` pixels wide covers, with t
// (0..1) where along the window-space segment the pixel's sample is nearest. Row by row, over the
// span capsuleSpan finds (a pixel wider on each side, for rounding), each pixel tested exactly:
// the work follows the pixels covered, not the segment's bounding box.
// Only rows [rowBegin, rowEnd) are visited: bands of rows can be drawn by different threads.
template <class Visit>
void forEachSegmentPixel(const FrameContext& frame, const WindowSegment& s, Real width, Visit&& visit, int rowBegin = 0,
                         int rowEnd = std::numeric_limits<int>::max()) {
  const Vec2 sample(Real(frame.sample.x) / 256, Real(frame.sample.y) / 256);
  const Real radius = width / 2;
  const Vec2 a(s.a), b(s.b);
  const int y0 = std::max(rowBegin, int(std::floor(std::min(a.y, b.y) - radius - 1)));
  const int y1 = std::min(std::min(frame.height, rowEnd) - 1, int(std::ceil(std::max(a.y, b.y) + radius + 1)));
  for (int y = y0; y <= y1; ++y) {
    const Real py = Real(y) + Real(0.5) + sample.y;
    const auto [lo, hi] = capsuleSpan(a, b, radius, py);
    if (!(lo <= hi)) continue;
    const int x0 = std::max(0, int(std::floor(lo - Real(0.5) - sample.x)) - 1);
    const int x1 = std::min(frame.width - 1, int(std::ceil(hi - Real(0.5) - sample.x)) + 1);
    for (int x = x0; x <= x1; ++x) {
      const Vec2 p(Real(x) + Real(0.5) + sample.x, py);
      const auto [d, t] = toSegment(p, a, b);
      if (d <= radius) visit(x, y, t);
    }
  }
}

}  // namespace illum
