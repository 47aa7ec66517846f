// Bin stage: which draw records touch which 64×64 tile, in submission order, so that each tile
// can be drawn by one thread at a time (llvmpipe's scheme): no locks on the framebuffer, and every
// pixel sees its fragments in the order GL would draw them.
#pragma once

#include "raster/draw.h"

#include <cstdint>
#include <vector>

namespace illum {

class TileBins {
 public:
  TileBins() = default;
  // Tiles for a width × height viewport, all empty (their memory kept).
  void reset(int width, int height);

  int tileCount() const { return tilesX_ * tilesY_; }
  PixelRect tileRect(int tile) const;
  // Appends every record to the tiles its pixel bounding box overlaps. The records must stay where
  // they are until clear().
  void bin(const RecordArena& records);
  const std::vector<const DrawRecord*>& records(int tile) const { return bins_[std::size_t(tile)]; }
  void clear();

 private:
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::vector<std::vector<const DrawRecord*>> bins_;
};

}  // namespace illum
