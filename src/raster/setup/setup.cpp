#include "raster/setup/setup.h"

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

// std::llround without the call into libm: exact for |x| < 2^52, where x − trunc(x) is exact.
std::int64_t roundHalfAway(double x) {
  const std::int64_t t = std::int64_t(x);
  const double fraction = x - double(t);
  return t + (fraction >= 0.5) - (fraction <= -0.5);
}

// Edge from p to q, positive on its left (the inside of a counter-clockwise triangle, y up).
EdgeFunction makeEdge(std::int64_t px, std::int64_t py, std::int64_t qx, std::int64_t qy) {
  EdgeFunction e;
  e.a = std::int32_t(-(qy - py));
  e.b = std::int32_t(qx - px);
  e.c = -(e.a * px + e.b * py);
  // Top-left rule, y up: a left edge runs downwards; a top edge is horizontal and runs leftwards.
  const bool left = qy < py;
  const bool top = qy == py && qx < px;
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
                   TriangleSetup& out, SubpixelOffset sample, const FrameContext::SampleReach& reach) {
  // The coordinates as plain integers (copies of whole structs cost store-forwarding stalls in
  // this, the hottest function of a dense mesh).
  WindowPosition computed[3];
  const ShadedVertex* v[3] = {&v0, &v1, &v2};
  const WindowPosition* p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = v[k]->hasWindow ? &v[k]->window : &(computed[k] = toWindow(v[k]->clip, width, height));
  std::int64_t x[3], y[3];
  for (int k = 0; k < 3; ++k) x[k] = p[k]->x - sample.x, y[k] = p[k]->y - sample.y;
  std::int64_t area2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if (area2 == 0) return false;
  // Pixel centres (x + 0.5) inside the bounding box, limited to the viewport (the scissor).
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t minFx = std::min({x[0], x[1], x[2]}), maxFx = std::max({x[0], x[1], x[2]});
  const std::int64_t minFy = std::min({y[0], y[1], y[2]}), maxFy = std::max({y[0], y[1], y[2]});
  const auto firstCentre = [&](std::int64_t f) { return (f - half + kSubpixelOne - 1) >> kSubpixelBits; };
  const auto lastCentre = [&](std::int64_t f) { return (f - half) >> kSubpixelBits; };
  // (A sample at centre + o covers a point p when the centre is p − o.)
  out.minX = int(std::max<std::int64_t>(0, firstCentre(minFx - reach.maxX)));
  out.maxX = int(std::min<std::int64_t>(width - 1, lastCentre(maxFx - reach.minX)));
  out.minY = int(std::max<std::int64_t>(0, firstCentre(minFy - reach.maxY)));
  out.maxY = int(std::min<std::int64_t>(height - 1, lastCentre(maxFy - reach.minY)));
  // Most of a dense mesh's triangles hold no pixel centre: they stop here, before any copying.
  if (out.minX > out.maxX || out.minY > out.maxY) return false;

  out.frontFacing = area2 > 0;
  out.swapped = area2 < 0;
  {
    // Make the triangle counter-clockwise (the caller moves the attributes along), by selects:
    // front and back faces alternate through a mesh, and a branch would mispredict.
    const bool swap = out.swapped;
    const std::int64_t x1 = swap ? x[2] : x[1], x2 = swap ? x[1] : x[2];
    const std::int64_t y1 = swap ? y[2] : y[1], y2 = swap ? y[1] : y[2];
    const WindowPosition *p1 = swap ? p[2] : p[1], *p2 = swap ? p[1] : p[2];
    x[1] = x1, x[2] = x2, y[1] = y1, y[2] = y2, p[1] = p1, p[2] = p2;
    area2 = swap ? -area2 : area2;
  }
  out.area2 = area2;
  out.invArea = Real(1) / Real(area2);
  for (int i = 0; i < 3; ++i) {
    out.z[std::size_t(i)] = p[i]->z;
    out.invW[std::size_t(i)] = p[i]->invW;
  }
  out.edge[0] = makeEdge(x[1], y[1], x[2], y[2]);
  out.edge[1] = makeEdge(x[2], y[2], x[0], y[0]);
  out.edge[2] = makeEdge(x[0], y[0], x[1], y[1]);
  // An edge's function vanishes on its own segment, which lies in the bounds, so anywhere in them
  // |E| ≤ |a|·width + |b|·height (sub-pixel units): small triangles can be rasterized in float.
  // Multisampled, the bounds' centres lie up to the reach beyond the vertices' box, and their
  // samples as far again: floatExact then holds at every sample of the bounds' pixels.
  const std::int64_t spanX = maxFx - minFx + 2 * (reach.maxX - reach.minX);
  const std::int64_t spanY = maxFy - minFy + 2 * (reach.maxY - reach.minY);
  out.floatExact = true;
  for (const EdgeFunction& e : out.edge)
    out.floatExact = out.floatExact && std::abs(std::int64_t(e.a)) * spanX + std::abs(std::int64_t(e.b)) * spanY <= (1 << 24);
  return true;
}

}  // namespace illum
