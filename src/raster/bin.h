// Bin stage: what touches which 64×64 tile, in submission order, so that each tile can be drawn
// by one thread at a time (llvmpipe's scheme): no locks on the framebuffer, and every pixel sees
// its fragments in the order GL would draw them. One chunk's bins hold, per tile, its records (by
// index in the chunk's arena, draw_record.h) and, apart, the fragments of tiny triangles coloured
// at setup, each knowing how many of the tile's records came before it (tiny_fragment.h).
// Everything is appended in submission order and sorted by tile once the chunk is set up (a
// stable counting sort; fragments stay where they are, only their runs, one per stretch of
// consecutive fragments of one tile, are sorted), so a chunk's memory is its own content,
// whichever tiles it touched.
#pragma once

#include "raster/framebuffer.h"
#include "raster/rasterize.h"
#include "raster/tiny_fragment.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace illum {

class TileBins {
 public:
  TileBins() = default;
  // Tiles for a width × height viewport, all empty (their memory kept).
  void reset(int width, int height);

  int tileCount() const { return tilesX_ * tilesY_; }
  PixelRect tileRect(int tile) const;
  int tileOf(int x, int y) const { return (y / kTileSize) * tilesX_ + x / kTileSize; }

  // Appends record `index` (whose triangle is `t`) to every tile its pixel bounding box overlaps.
  void addRecord(const TriangleSetup& t, std::uint32_t index);
  // How many records `tile` has so far.
  std::uint32_t recordsIn(int tile) const { return recordCount_[std::size_t(tile)]; }
  // Room for `n` fragments after the last; commitFragments(k, tile) then appends the first k of
  // them to `tile`.
  TinyFragment* fragmentRoom(std::size_t n) {
    if (fragmentCount_ + n > fragmentCapacity_) growFragments(fragmentCount_ + n);
    return fragments_.get() + fragmentCount_;
  }
  void commitFragments(std::size_t k, int tile) {
    if (k == 0) return;
    if (!runs_.empty() && runs_.back().tile == std::uint32_t(tile)) runs_.back().count += std::uint32_t(k);
    else runs_.push_back({std::uint32_t(tile), std::uint32_t(fragmentCount_), std::uint32_t(k)});
    fragmentCount_ += k;
  }

  // Sorts what was appended by tile; then records(tile) and fragments(tile) hold it.
  void finish();
  std::span<const std::uint32_t> records(int tile) const {
    return std::span(sortedRecords_).subspan(recordStart_[std::size_t(tile)], recordCount_[std::size_t(tile)]);
  }
  // f(fragment) for each of the tile's fragments, in order.
  template <class F>
  void forEachFragment(int tile, F&& f) const {
    for (std::uint32_t r = runStart_[std::size_t(tile)]; r < runStart_[std::size_t(tile) + 1]; ++r) {
      const TinyFragment* first = fragments_.get() + sortedRuns_[r].first;
      for (std::uint32_t k = 0; k < sortedRuns_[r].count; ++k) f(first[k]);
    }
  }

 private:
  void growFragments(std::size_t least);

  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  // As appended: (tile, record) pairs, and fragments in runs of one tile.
  struct Run {
    std::uint32_t tile, first, count;
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> recordTiles_;
  std::unique_ptr<TinyFragment[]> fragments_;
  std::size_t fragmentCount_ = 0, fragmentCapacity_ = 0;
  std::vector<Run> runs_;
  // Sorted by tile: per tile, where its records start, and where its runs start (and end, at
  // tile + 1).
  std::vector<std::uint32_t> recordCount_, recordStart_, sortedRecords_;
  std::vector<std::uint32_t> runStart_;
  std::vector<Run> sortedRuns_;
};

}  // namespace illum
