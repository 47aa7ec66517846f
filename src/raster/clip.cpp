#include "raster/clip.h"

#include <cmath>

namespace illum {
namespace {

// A clip plane as a dot product with (x, y, z, w): the inside is where it is ≥ 0.
using Plane = Vec4;

std::array<Plane, 6> clipPlanes(int width, int height) {
  const Real gx = 1 + Real(2 * kGuardBandPixels) / Real(width);
  const Real gy = 1 + Real(2 * kGuardBandPixels) / Real(height);
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

ClipResult clipTriangle(const std::array<ShadedVertex, 3>& tri, int width, int height,
                        std::vector<ShadedVertex>& polygon) {
  const auto planes = clipPlanes(width, height);
  // A vertex pushed to infinity (an overflowing transform) has no place on screen.
  for (const ShadedVertex& v : tri)
    if (!std::isfinite(v.clip.x) || !std::isfinite(v.clip.y) || !std::isfinite(v.clip.z) || !std::isfinite(v.clip.w))
      return ClipResult::Outside;
  // Trivial accept and reject with per-vertex outcodes.
  unsigned orCodes = 0, andCodes = ~0u;
  for (const ShadedVertex& v : tri) {
    unsigned code = 0;
    for (std::size_t p = 0; p < planes.size(); ++p)
      if (glm::dot(planes[p], v.clip) < 0) code |= 1u << p;
    orCodes |= code;
    andCodes &= code;
  }
  if (andCodes != 0) return ClipResult::Outside;
  if (orCodes == 0) {
    polygon.insert(polygon.end(), tri.begin(), tri.end());
    return ClipResult::Inside;
  }

  std::vector<ShadedVertex> in(tri.begin(), tri.end()), out;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (!(orCodes & (1u << p))) continue;
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i) {
      const ShadedVertex& a = in[i];
      const ShadedVertex& b = in[(i + 1) % in.size()];
      const Real da = glm::dot(planes[p], a.clip), db = glm::dot(planes[p], b.clip);
      if (da >= 0) out.push_back(a);
      // Interpolate from the inside vertex so that a shared edge is cut at the same point
      // whichever triangle it belongs to.
      if ((da >= 0) != (db >= 0)) out.push_back(da >= 0 ? lerp(a, b, da / (da - db)) : lerp(b, a, db / (db - da)));
    }
    in.swap(out);
    if (in.size() < 3) return ClipResult::Outside;
  }
  polygon.insert(polygon.end(), in.begin(), in.end());
  return ClipResult::Clipped;
}

}  // namespace illum
