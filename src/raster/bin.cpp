#include "raster/bin.h"

#include <algorithm>

namespace illum {

void TileBins::reset(int width, int height) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  tilesY_ = (height + kTileSize - 1) / kTileSize;
  recordCount_.assign(std::size_t(tileCount()), 0);
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
  const std::size_t tiles = std::size_t(tileCount());
  // Records: the counts are known; starts by prefix sum, then each pair to its place.
  recordStart_.resize(tiles);
  std::uint32_t at = 0;
  for (std::size_t t = 0; t < tiles; ++t) recordStart_[t] = at, at += recordCount_[t];
  sortedRecords_.resize(recordTiles_.size());
  std::vector<std::uint32_t>& next = recordCount_;  // reused as cursors, then restored
  for (std::size_t t = 0; t < tiles; ++t) next[t] = recordStart_[t];
  for (const auto& [tile, index] : recordTiles_) sortedRecords_[next[tile]++] = index;
  for (std::size_t t = 0; t < tiles; ++t) next[t] -= recordStart_[t];
  fragments.finish(tiles);
  surfaces.finish(tiles);
}

}  // namespace illum
