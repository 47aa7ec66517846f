// Bin stage: what touches which 64×64 tile, in submission order, so that each tile can be drawn
// by one thread at a time (llvmpipe's scheme): no locks on the framebuffer, and every pixel sees
// its fragments in the order GL would draw them. A tile's list holds records (draw_record.h) and,
// between them, the fragments of tiny triangles already coloured at setup (tile_raster.h).
#pragma once

#include "raster/bin_entry.h"
#include "raster/framebuffer.h"
#include "raster/rasterize.h"
#include "raster/tile_raster.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace illum {

// A tile's entries in one growable block that can hand out room for a few entries before they
// are counted (a tiny triangle's fragments are stored whole vectors at a time).
class EntryList {
 public:
  void clear() { size_ = 0; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const BinEntry* begin() const { return data_.get(); }
  const BinEntry* end() const { return data_.get() + size_; }
  void push_back(const BinEntry& e) { *room(1) = e, ++size_; }
  // Room for `n` entries after the last; commit(k) then counts the first k of them.
  BinEntry* room(std::size_t n) {
    if (size_ + n > capacity_) grow(size_ + n);
    return data_.get() + size_;
  }
  void commit(std::size_t k) { size_ += k; }

 private:
  void grow(std::size_t least);
  std::unique_ptr<BinEntry[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

class TileBins {
 public:
  TileBins() = default;
  // Tiles for a width × height viewport, all empty (their memory kept).
  void reset(int width, int height);

  int tileCount() const { return tilesX_ * tilesY_; }
  PixelRect tileRect(int tile) const;
  // Appends record `index` (whose triangle is `t`) to every tile its pixel bounding box overlaps.
  void addRecord(const TriangleSetup& t, std::uint32_t index);
  // The list of the tile that holds the pixel (x, y).
  EntryList& listAt(int x, int y) { return bins_[std::size_t((y / kTileSize) * tilesX_ + x / kTileSize)]; }
  const EntryList& entries(int tile) const { return bins_[std::size_t(tile)]; }
  void clear();

 private:
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::vector<EntryList> bins_;
};

}  // namespace illum
