#include "raster/bin.h"

#include <algorithm>

namespace illum {

void TileBins::reset(int width, int height) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  tilesY_ = (height + kTileSize - 1) / kTileSize;
  bins_.resize(std::size_t(tilesX_) * std::size_t(tilesY_));
  clear();
}

PixelRect TileBins::tileRect(int tile) const {
  const int tx = tile % tilesX_, ty = tile / tilesX_;
  return {tx * kTileSize, ty * kTileSize, std::min(width_, (tx + 1) * kTileSize) - 1,
          std::min(height_, (ty + 1) * kTileSize) - 1};
}

void TileBins::bin(const RecordArena& records) {
  for (std::size_t i = 0; i < records.size(); ++i) {
    const DrawRecord& r = records[i];
    const TriangleSetup& t = r.setup;
    for (int ty = t.minY / kTileSize; ty <= t.maxY / kTileSize; ++ty)
      for (int tx = t.minX / kTileSize; tx <= t.maxX / kTileSize; ++tx)
        bins_[std::size_t(ty * tilesX_ + tx)].push_back(&r);
  }
}

void TileBins::clear() {
  for (auto& b : bins_) b.clear();
}

}  // namespace illum
