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

void TileBins::addRecord(const TriangleSetup& t, std::uint32_t index) {
  for (int ty = t.minY / kTileSize; ty <= t.maxY / kTileSize; ++ty)
    for (int tx = t.minX / kTileSize; tx <= t.maxX / kTileSize; ++tx) {
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
