// Wide line segments in window space, the one rule the overlays and GL_LINES share: a pixel is
// covered when its sample point (the centre plus the pass's multisample offset) lies within half
// the width of the segment (round ends, so that the segments of a polyline join without gaps).
#pragma once

#include "raster/frame_context.h"

#include <algorithm>
#include <cmath>
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

// Calls visit(x, y, t) for every pixel of the frame the segment `width` pixels wide covers, with t
// (0..1) where along the window-space segment the pixel's sample is nearest.
template <class Visit>
void forEachSegmentPixel(const FrameContext& frame, const WindowSegment& s, Real width, Visit&& visit) {
  const Vec2 sample(Real(frame.sample.x) / 256, Real(frame.sample.y) / 256);
  const Real radius = width / 2;
  const Real length = glm::length(Vec2(s.b - s.a));
  // In pieces of at most 16 pixels, each tested over its own small box.
  const int pieces = std::max(1, int(std::ceil(length / 16)));
  const Vec2 a(s.a), b(s.b);
  for (int k = 0; k < pieces; ++k) {
    const Real t0 = Real(k) / Real(pieces), t1 = Real(k + 1) / Real(pieces);
    const Vec2 pa = a + t0 * (b - a), pb = a + t1 * (b - a);
    const int x0 = std::max(0, int(std::floor(std::min(pa.x, pb.x) - radius - 1)));
    const int x1 = std::min(frame.width - 1, int(std::ceil(std::max(pa.x, pb.x) + radius + 1)));
    const int y0 = std::max(0, int(std::floor(std::min(pa.y, pb.y) - radius - 1)));
    const int y1 = std::min(frame.height - 1, int(std::ceil(std::max(pa.y, pb.y) + radius + 1)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2 p(Real(x) + Real(0.5) + sample.x, Real(y) + Real(0.5) + sample.y);
        const auto [d, t] = toSegment(p, a, b);
        // The boxes overlap: a pixel belongs to the piece its nearest point lies in, once.
        if (d > radius || (t < t0 && k > 0) || (t >= t1 && k + 1 < pieces)) continue;
        visit(x, y, t);
      }
  }
}

}  // namespace illum
