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
  fragmentCount_ = 0;
  runs_.clear();
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

void TileBins::growFragments(std::size_t least) {
  const std::size_t capacity = std::max(least, 2 * fragmentCapacity_);
  std::unique_ptr<TinyFragment[]> grown(new TinyFragment[capacity]);
  std::copy(fragments_.get(), fragments_.get() + fragmentCount_, grown.get());
  fragments_ = std::move(grown);
  fragmentCapacity_ = capacity;
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
  // Runs of fragments: counted, then placed the same way.
  runStart_.assign(tiles + 1, 0);
  for (const Run& r : runs_) ++runStart_[r.tile + 1];
  for (std::size_t t = 0; t < tiles; ++t) runStart_[t + 1] += runStart_[t];
  sortedRuns_.resize(runs_.size());
  for (const Run& r : runs_) sortedRuns_[runStart_[r.tile]++] = r;
  // Each start was moved to its end: shift back by one tile.
  for (std::size_t t = tiles; t > 0; --t) runStart_[t] = runStart_[t - 1];
  runStart_[0] = 0;
}

}  // namespace illum
