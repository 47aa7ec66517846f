// Bin stage: what touches which 64×64 tile, in submission order, so that each tile can be drawn
// by one thread at a time (llvmpipe's scheme): no locks on the framebuffer, and every pixel sees
// its fragments in the order GL would draw them. A tile's list holds its records (by index in
// their chunk's arena, draw_record.h) and, apart, the fragments of tiny triangles coloured at
// setup, each knowing how many of the tile's records came before it (tiny_fragment.h).
#pragma once

#include "raster/framebuffer.h"
#include "raster/rasterize.h"
#include "raster/tiny_fragment.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace illum {

// Fragments in one growable block that can hand out room for a few before they are counted (a
// tiny triangle's fragments are stored whole vectors at a time).
class FragmentList {
 public:
  void clear() { size_ = 0; }
  std::size_t size() const { return size_; }
  const TinyFragment* begin() const { return data_.get(); }
  const TinyFragment* end() const { return data_.get() + size_; }
  // Room for `n` fragments after the last; commit(k) then counts the first k of them.
  TinyFragment* room(std::size_t n) {
    if (size_ + n > capacity_) grow(size_ + n);
    return data_.get() + size_;
  }
  void commit(std::size_t k) { size_ += k; }

 private:
  void grow(std::size_t least);
  std::unique_ptr<TinyFragment[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

class TileBins {
 public:
  struct Tile {
    std::vector<std::uint32_t> records;  // indices into the chunk's arena
    FragmentList fragments;
  };

  TileBins() = default;
  // Tiles for a width × height viewport, all empty (their memory kept).
  void reset(int width, int height);

  int tileCount() const { return tilesX_ * tilesY_; }
  PixelRect tileRect(int tile) const;
  // Appends record `index` (whose triangle is `t`) to every tile its pixel bounding box overlaps.
  void addRecord(const TriangleSetup& t, std::uint32_t index);
  // The tile that holds the pixel (x, y).
  Tile& tileAt(int x, int y) { return tiles_[std::size_t((y / kTileSize) * tilesX_ + x / kTileSize)]; }
  const Tile& tile(int index) const { return tiles_[std::size_t(index)]; }
  void clear();

 private:
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::vector<Tile> tiles_;
};

}  // namespace illum
