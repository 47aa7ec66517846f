#include "raster/setup/bin.h"

#include <algorithm>

namespace illum {

void TileBins::reset(int width, int height) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  tilesY_ = (height + kTileSize - 1) / kTileSize;
  // Only the tiles counted since the last reset need zeroing: a chunk touches few of them.
  if (recordCount_.size() != std::size_t(tileCount())) recordCount_.assign(std::size_t(tileCount()), 0);
  else
    for (const auto& [tile, record] : recordTiles_) recordCount_[tile] = 0;
  recordSpan_ = {};
  recordTiles_.clear();
  fragments.clear();
  surfaces.clear();
}

PixelRect TileBins::tileRect(int tile) const {
  const int tx = tile % tilesX_, ty = tile / tilesX_;
  return {tx * kTileSize, ty * kTileSize, std::min(width_, (tx + 1) * kTileSize) - 1,
          std::min(height_, (ty + 1) * kTileSize) - 1};
}

namespace {

// Whether a triangle may cover a sample of pixels minX..maxX × minY..maxY: at the corner of their
// squares where each edge function is largest (samples lie inside their pixel's square), none is
// negative. A triangle that spans tiles often misses some of its bounds' tiles (a thin diagonal
// one most of them), and each tile it is sent to tests its samples for nothing.
bool mayCover(const TriangleSetup& t, int minX, int maxX, int minY, int maxY) {
  const std::int64_t x0 = minX * kSubpixelOne, x1 = (maxX + 1) * kSubpixelOne;
  const std::int64_t y0 = minY * kSubpixelOne, y1 = (maxY + 1) * kSubpixelOne;
  for (const EdgeFunction& e : t.edge)
    if (e.at(e.a > 0 ? x1 : x0, e.b > 0 ? y1 : y0) < 0) return false;
  return true;
}

}  // namespace

void TileBins::addRecord(const TriangleSetup& t, std::uint32_t index) {
  const int tx0 = t.minX / kTileSize, tx1 = t.maxX / kTileSize, ty0 = t.minY / kTileSize, ty1 = t.maxY / kTileSize;
  const bool one = tx0 == tx1 && ty0 == ty1;
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) {
      if (!one && !mayCover(t, std::max(t.minX, tx * kTileSize), std::min(t.maxX, tx * kTileSize + kTileSize - 1),
                            std::max(t.minY, ty * kTileSize), std::min(t.maxY, ty * kTileSize + kTileSize - 1)))
        continue;
      const auto tile = std::uint32_t(ty * tilesX_ + tx);
      recordTiles_.emplace_back(tile, index);
      ++recordCount_[tile];
    }
}

void TileBins::finish() {
  using Entry = std::pair<std::uint32_t, std::uint32_t>;
  recordSpan_ = sortByTile(recordTiles_, [](const Entry& e) { return e.first; }, [](const Entry& e) { return e.second; },
                           recordStart_, sortedRecords_);
  fragments.finish();
  surfaces.finish();
}

}  // namespace illum
