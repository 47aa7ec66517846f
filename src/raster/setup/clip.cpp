#include "raster/setup/clip.h"

#include <algorithm>
#include <cmath>

namespace illum {
namespace {

// A clip plane as a dot product with (x, y, z, w): the inside is where it is ≥ 0.
using Plane = Vec4;

std::array<Plane, 6> clipPlanes(int width, int height) {
  const Vec2 g = guardBandScale(width, height);
  const Real gx = g.x, gy = g.y;
  return {{
      {0, 0, 1, 1},    // near: z ≥ −w
      {0, 0, -1, 1},   // far: z ≤ w
      {1, 0, 0, gx},   // x ≥ −gx·w
      {-1, 0, 0, gx},  // x ≤ gx·w
      {0, 1, 0, gy},   // y ≥ −gy·w
      {0, -1, 0, gy},  // y ≤ gy·w
  }};
}

}  // namespace

Vec2 guardBandScale(int width, int height) {
  return {1 + Real(2 * kGuardBandPixels) / Real(width), 1 + Real(2 * kGuardBandPixels) / Real(height)};
}

unsigned clipOutcode(const Vec4& clip, int width, int height) {
  // A vertex pushed to infinity (an overflowing transform) has no place on screen.
  if (!std::isfinite(clip.x) || !std::isfinite(clip.y) || !std::isfinite(clip.z) || !std::isfinite(clip.w))
    return kNotFinite;
  const auto planes = clipPlanes(width, height);
  unsigned code = 0;
  for (std::size_t p = 0; p < planes.size(); ++p)
    if (glm::dot(planes[p], clip) < 0) code |= 1u << p;
  return code;
}

ClipResult classifyTriangle(const ShadedVertex& a, const ShadedVertex& b, const ShadedVertex& c, int width, int height,
                            unsigned* outsidePlanes) {
  // Trivial accept and reject with per-vertex outcodes.
  unsigned orCodes = 0, andCodes = ~0u;
  for (const ShadedVertex* v : {&a, &b, &c}) {
    const unsigned code = v->outcode != kOutcodeUnknown ? v->outcode : clipOutcode(v->clip, width, height);
    if (code & kNotFinite) return ClipResult::Outside;
    orCodes |= code;
    andCodes &= code;
  }
  if (outsidePlanes) *outsidePlanes = orCodes;
  if (andCodes != 0) return ClipResult::Outside;
  return orCodes == 0 ? ClipResult::Inside : ClipResult::Clipped;
}

ClipResult clipTriangle(const std::array<ShadedVertex, 3>& tri, int width, int height, ClippedPolygon& polygon) {
  const auto planes = clipPlanes(width, height);
  unsigned orCodes = 0;
  polygon.size = 0;
  const ClipResult kind = classifyTriangle(tri[0], tri[1], tri[2], width, height, &orCodes);
  if (kind == ClipResult::Outside) return kind;
  std::copy(tri.begin(), tri.end(), polygon.vertex.begin());
  polygon.size = 3;
  if (kind == ClipResult::Inside) return ClipResult::Inside;

  // Each plane cuts `in` into `out`; the two swap roles, so nothing is allocated.
  ClippedPolygon other;
  ClippedPolygon* in = &polygon;
  ClippedPolygon* out = &other;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (!(orCodes & (1u << p))) continue;
    out->size = 0;
    for (std::size_t i = 0; i < in->size; ++i) {
      const ShadedVertex& a = in->vertex[i];
      const ShadedVertex& b = in->vertex[(i + 1) % in->size];
      const Real da = glm::dot(planes[p], a.clip), db = glm::dot(planes[p], b.clip);
      if (da >= 0) out->vertex[out->size++] = a;
      // Interpolate from the inside vertex so that a shared edge is cut at the same point
      // whichever triangle it belongs to.
      if ((da >= 0) != (db >= 0))
        out->vertex[out->size++] = da >= 0 ? lerp(a, b, da / (da - db)) : lerp(b, a, db / (db - da));
    }
    std::swap(in, out);
    if (in->size < 3) {
      polygon.size = 0;
      return ClipResult::Outside;
    }
  }
  if (in != &polygon) polygon = *in;
  return ClipResult::Clipped;
}

}  // namespace illum
