#include "raster/bin.h"

#include <algorithm>

namespace illum {

void TileBins::reset(int width, int height) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  tilesY_ = (height + kTileSize - 1) / kTileSize;
  tiles_.resize(std::size_t(tilesX_) * std::size_t(tilesY_));
  clear();
}

PixelRect TileBins::tileRect(int tile) const {
  const int tx = tile % tilesX_, ty = tile / tilesX_;
  return {tx * kTileSize, ty * kTileSize, std::min(width_, (tx + 1) * kTileSize) - 1,
          std::min(height_, (ty + 1) * kTileSize) - 1};
}

void TileBins::addRecord(const TriangleSetup& t, std::uint32_t index) {
  for (int ty = t.minY / kTileSize; ty <= t.maxY / kTileSize; ++ty)
    for (int tx = t.minX / kTileSize; tx <= t.maxX / kTileSize; ++tx)
      tiles_[std::size_t(ty * tilesX_ + tx)].records.push_back(index);
}

void FragmentList::grow(std::size_t least) {
  const std::size_t capacity = std::max(least, 2 * capacity_);
  std::unique_ptr<TinyFragment[]> grown(new TinyFragment[capacity]);
  std::copy(begin(), end(), grown.get());
  data_ = std::move(grown);
  capacity_ = capacity;
}

void TileBins::clear() {
  for (Tile& t : tiles_) t.records.clear(), t.fragments.clear();
}

}  // namespace illum
