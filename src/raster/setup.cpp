#include "raster/setup.h"

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

using WindowVertex = WindowPosition;

// std::llround without the call into libm: exact for |x| < 2^52, where x − trunc(x) is exact.
std::int64_t roundHalfAway(double x) {
  const std::int64_t t = std::int64_t(x);
  const double fraction = x - double(t);
  return t + (fraction >= 0.5) - (fraction <= -0.5);
}


// Edge from p to q, positive on its left (the inside of a counter-clockwise triangle, y up).
EdgeFunction makeEdge(const WindowVertex& p, const WindowVertex& q) {
  EdgeFunction e;
  e.a = -(q.y - p.y);
  e.b = q.x - p.x;
  e.c = -(e.a * p.x + e.b * p.y);
  // Top-left rule, y up: a left edge runs downwards; a top edge is horizontal and runs leftwards.
  const bool left = q.y < p.y;
  const bool top = q.y == p.y && q.x < p.x;
  e.bias = (left || top) ? 0 : -1;
  return e;
}

}  // namespace

WindowPosition toWindow(const Vec4& clip, int width, int height) {
  const Real invW = Real(1) / clip.w;
  const Real xw = (clip.x * invW + 1) * Real(0.5) * Real(width);
  const Real yw = (clip.y * invW + 1) * Real(0.5) * Real(height);
  const Real zw = (clip.z * invW + 1) * Real(0.5);
  return {roundHalfAway(double(xw) * kSubpixelOne), roundHalfAway(double(yw) * kSubpixelOne), zw, invW};
}

bool setupTriangle(const ShadedVertex& v0, const ShadedVertex& v1, const ShadedVertex& v2, int width, int height,
                   TriangleSetup& out, SubpixelOffset sample) {
  const auto windowOf = [&](const ShadedVertex& v) {
    WindowPosition p = v.hasWindow ? v.window : toWindow(v.clip, width, height);
    p.x -= sample.x;
    p.y -= sample.y;
    return p;
  };
  std::array<WindowVertex, 3> w = {windowOf(v0), windowOf(v1), windowOf(v2)};
  std::int64_t area2 = (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y);
  if (area2 == 0) return false;
  // Pixel centres (x + 0.5) inside the bounding box, limited to the viewport (the scissor).
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t minFx = std::min({w[0].x, w[1].x, w[2].x}), maxFx = std::max({w[0].x, w[1].x, w[2].x});
  const std::int64_t minFy = std::min({w[0].y, w[1].y, w[2].y}), maxFy = std::max({w[0].y, w[1].y, w[2].y});
  const auto firstCentre = [&](std::int64_t f) { return (f - half + kSubpixelOne - 1) >> kSubpixelBits; };
  const auto lastCentre = [&](std::int64_t f) { return (f - half) >> kSubpixelBits; };
  out.minX = int(std::max<std::int64_t>(0, firstCentre(minFx)));
  out.maxX = int(std::min<std::int64_t>(width - 1, lastCentre(maxFx)));
  out.minY = int(std::max<std::int64_t>(0, firstCentre(minFy)));
  out.maxY = int(std::min<std::int64_t>(height - 1, lastCentre(maxFy)));
  // Most of a dense mesh's triangles hold no pixel centre: they stop here, before any copying.
  if (out.minX > out.maxX || out.minY > out.maxY) return false;

  out.frontFacing = area2 > 0;
  out.swapped = area2 < 0;
  if (out.swapped) {
    // Make the triangle counter-clockwise; the caller moves the attributes along.
    std::swap(w[1], w[2]);
    area2 = -area2;
  }
  out.area2 = area2;
  out.invArea = Real(1) / Real(area2);
  for (int i = 0; i < 3; ++i) {
    out.z[std::size_t(i)] = w[std::size_t(i)].z;
    out.invW[std::size_t(i)] = w[std::size_t(i)].invW;
  }
  out.edge[0] = makeEdge(w[1], w[2]);
  out.edge[1] = makeEdge(w[2], w[0]);
  out.edge[2] = makeEdge(w[0], w[1]);
  // An edge's function vanishes on its own segment, which lies in the bounds, so anywhere in them
  // |E| ≤ |a|·width + |b|·height (sub-pixel units): small triangles can be rasterized in float.
  const std::int64_t spanX = maxFx - minFx, spanY = maxFy - minFy;
  out.floatExact = true;
  for (const EdgeFunction& e : out.edge)
    out.floatExact = out.floatExact && std::abs(std::int64_t(e.a)) * spanX + std::abs(std::int64_t(e.b)) * spanY <= (1 << 24);
  return true;
}

}  // namespace illum
