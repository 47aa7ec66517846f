#include "raster/lines/overlay.h"

#include "raster/lines/wide_segment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace illum {
namespace {

constexpr Real kLineBias = Real(2e-5);  // window depth a line may lie behind the surface it is on

// 1, 2 or 5 times a power of ten, the nearest at or above x.
Real roundSpacing(Real x) {
  const Real p = std::pow(Real(10), std::floor(std::log10(x)));
  for (Real m : {Real(1), Real(2), Real(5), Real(10)})
    if (m * p >= x) return m * p;
  return 10 * p;
}

void addEdges(const Object& o, std::vector<OverlayLine>& out) {
  const Color3 ink(0.04f, 0.04f, 0.05f);
  const auto& idx = o.mesh->indices;
  std::unordered_set<std::uint64_t> seen;
  seen.reserve(idx.size());
  for (std::size_t t = 0; t + 2 < idx.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = idx[t + std::size_t(k)], b = idx[t + std::size_t((k + 1) % 3)];
      // Vertices split for normals or uvs share positions: an edge is its two positions.
      const Vec3 pa = o.mesh->positions[a], pb = o.mesh->positions[b];
      if (pa == pb) continue;
      if (b < a) std::swap(a, b);
      if (!seen.insert(std::uint64_t(a) << 32 | b).second) continue;
      out.push_back({Vec3(o.worldFromObject * Vec4(pa, 1)), Vec3(o.worldFromObject * Vec4(pb, 1)), ink});
    }
}

void addGrid(const Scene& scene, std::vector<OverlayLine>& out) {
  const Vec3 up = glm::normalize(scene.camera.up);
  // Two directions across the up axis.
  const Vec3 u = glm::normalize(std::abs(up.x) < Real(0.9) ? glm::cross(up, Vec3(1, 0, 0)) : glm::cross(up, Vec3(0, 0, 1)));
  const Vec3 v = glm::cross(up, u);
  Real lowest = std::numeric_limits<Real>::max();
  Vec2 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
  for (const Object& o : scene.objects)
    for (const Vec3& p : o.mesh->positions) {
      const Vec3 w(o.worldFromObject * Vec4(p, 1));
      lowest = std::min(lowest, glm::dot(w, up));
      const Vec2 q(glm::dot(w, u), glm::dot(w, v));
      lo = glm::min(lo, q), hi = glm::max(hi, q);
    }
  if (!(lowest < std::numeric_limits<Real>::max())) return;
  // Half as wide again as the scene on every side, in about 20 cells.
  const Vec2 centre = (lo + hi) * Real(0.5);
  const Real half = std::max(Real(1e-3), std::max(hi.x - lo.x, hi.y - lo.y)) * Real(1.25);
  const Real spacing = roundSpacing(2 * half / 20);
  const int n = int(std::ceil(half / spacing));
  const Vec2 origin(std::round(centre.x / spacing) * spacing, std::round(centre.y / spacing) * spacing);
  const Color3 grey(0.45f, 0.46f, 0.48f);
  const auto at = [&](Real a, Real b) { return a * u + b * v + lowest * up; };
  for (int i = -n; i <= n; ++i) {
    const Real a = origin.x + Real(i) * spacing, b = origin.y + Real(i) * spacing;
    out.push_back({at(a, origin.y - Real(n) * spacing), at(a, origin.y + Real(n) * spacing), grey});
    out.push_back({at(origin.x - Real(n) * spacing, b), at(origin.x + Real(n) * spacing, b), grey});
  }
}

}  // namespace

std::vector<OverlayLine> overlayLines(const Scene& scene) {
  std::vector<OverlayLine> lines;
  if (scene.overlays.grid) addGrid(scene, lines);
  if (scene.overlays.edges)
    for (const Object& o : scene.objects) addEdges(o, lines);
  return lines;
}

void drawOverlayLines(Framebuffer& fb, const FrameContext& frame, std::span<const OverlayLine> lines, Real width,
                      int sample) {
  const Mat4 clipFromWorld = frame.clipFromView * frame.viewFromWorld;
  for (const OverlayLine& line : lines) {
    const auto segment = windowSegment(frame, clipFromWorld * Vec4(line.a, 1), clipFromWorld * Vec4(line.b, 1));
    if (!segment) continue;
    forEachSegmentPixel(frame, *segment, width, [&](int x, int y, Real t) {
      fb.clearTile(x, y);  // a tile no triangle touched is cleared now
      const Real z = segment->a.z + t * (segment->b.z - segment->a.z);
      if (z < 0 || z > 1 || z > fb.depth(x, y, sample) + kLineBias) return;
      fb.writeColor(x, y, Color4(line.color, 1), sample);
    });
  }
}

}  // namespace illum
