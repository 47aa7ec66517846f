#include "raster/setup/object_reach.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace illum {
namespace {

// Window pixels of margin around the projected box: the vertex stage works in Real (float) from
// the same matrices, so its window positions differ from these, computed in double, by far less.
constexpr double kMarginPixels = 8;

// The box of `positions`: a flat pass over their coordinates, 16 points (48 values, every
// coordinate at the same place in each group) at a time, which the compiler makes vector
// minima and maxima; a million-triangle scene's half a million points take a fraction of a
// millisecond. (Not-a-number coordinates are passed over, as the comparisons fail.)
void boxOf(std::span<const Vec3> positions, Vec3& lo, Vec3& hi) {
  constexpr std::size_t kGroup = 48;
  static_assert(sizeof(Vec3) == 3 * sizeof(Real));
  const Real* values = &positions[0].x;
  const std::size_t count = positions.size() * 3;
  Real low[kGroup], high[kGroup];
  for (std::size_t k = 0; k < kGroup; ++k) low[k] = HUGE_VAL, high[k] = -HUGE_VAL;
  std::size_t i = 0;
  for (; i + kGroup <= count; i += kGroup)
    for (std::size_t k = 0; k < kGroup; ++k) {
      const Real v = values[i + k];
      low[k] = v < low[k] ? v : low[k];
      high[k] = v > high[k] ? v : high[k];
    }
  for (std::size_t k = 0; i + k < count; ++k) {  // the last points, fewer than 16
    const Real v = values[i + k];
    low[k] = v < low[k] ? v : low[k];
    high[k] = v > high[k] ? v : high[k];
  }
  lo = Vec3(HUGE_VAL), hi = Vec3(-HUGE_VAL);
  for (std::size_t k = 0; k < kGroup; ++k) lo[int(k % 3)] = std::min(lo[int(k % 3)], low[k]), hi[int(k % 3)] = std::max(hi[int(k % 3)], high[k]);
}

}  // namespace

PixelRect objectReach(const FrameContext& frame, const Object& object) {
  const PixelRect whole{0, 0, frame.width - 1, frame.height - 1};
  const Mesh& mesh = *object.mesh;
  if (mesh.positions.empty()) return whole;
  Vec3 lo, hi;
  boxOf(mesh.positions, lo, hi);
  if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) return whole;  // (no number among them)
  const glm::dmat4 clipFromObject =
      glm::dmat4(frame.clipFromView) * glm::dmat4(frame.viewFromWorld) * glm::dmat4(object.worldFromObject);
  double minX = HUGE_VAL, maxX = -HUGE_VAL, minY = HUGE_VAL, maxY = -HUGE_VAL;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec4 p(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z, 1);
    const glm::dvec4 clip = clipFromObject * p;
    if (!(clip.w > 0) || !std::isfinite(clip.x) || !std::isfinite(clip.y) || !std::isfinite(clip.w)) return whole;
    const double x = (clip.x / clip.w + 1) * 0.5 * frame.width, y = (clip.y / clip.w + 1) * 0.5 * frame.height;
    minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
  }
  // (Compared before converting: a box far off to one side converts to nothing out of range.)
  const auto clampX = [&](double v) { return int(std::clamp(std::floor(v), -1.0, double(frame.width))); };
  const auto clampY = [&](double v) { return int(std::clamp(std::floor(v), -1.0, double(frame.height))); };
  PixelRect r{clampX(minX - kMarginPixels), clampY(minY - kMarginPixels), clampX(maxX + kMarginPixels),
              clampY(maxY + kMarginPixels)};
  r.minX = std::max(r.minX, 0), r.minY = std::max(r.minY, 0);
  r.maxX = std::min(r.maxX, frame.width - 1), r.maxY = std::min(r.maxY, frame.height - 1);
  return r;
}

bool TileReach::find(const FrameContext& frame, std::span<const Object* const> order) {
  const int tilesX = (frame.width + kTileSize - 1) / kTileSize, tilesY = (frame.height + kTileSize - 1) / kTileSize;
  last_.assign(std::size_t(tilesX) * std::size_t(tilesY), 0);
  std::vector<std::uint32_t> drawn;
  for (std::size_t k = 0; k < order.size(); ++k)
    if (order[k]->mesh->triangleCount() > 0) drawn.push_back(std::uint32_t(k));
  if (drawn.size() < 2) return false;
  std::vector<PixelRect> reach(drawn.size());
  tbb::parallel_for(std::size_t(0), drawn.size(), [&](std::size_t i) { reach[i] = objectReach(frame, *order[drawn[i]]); });
  for (std::size_t i = 0; i < drawn.size(); ++i) {  // (in order: the last one to reach a tile stays)
    const PixelRect& r = reach[i];
    for (int ty = r.minY / kTileSize; r.minX <= r.maxX && ty <= r.maxY / kTileSize; ++ty)
      for (int tx = r.minX / kTileSize; tx <= r.maxX / kTileSize; ++tx)
        last_[std::size_t(ty) * std::size_t(tilesX) + std::size_t(tx)] = drawn[i] + 1;
  }
  return true;
}

}  // namespace illum
