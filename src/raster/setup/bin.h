// Bin stage: what touches which 64×64 tile, in submission order, so that each tile can be drawn
// by one thread at a time (llvmpipe's scheme): no locks on the framebuffer, and every pixel sees
// its fragments in the order GL would draw them. One chunk's bins hold, per tile, its records (by
// index in the chunk's arena, draw_record.h) and, apart, the pixels of tiny triangles worked out
// at setup, each knowing how many of the tile's records came before it (tiny_fragment.h).
// Everything is appended in submission order and sorted by tile once the chunk is set up (a
// stable counting sort; tiny pixels stay where they are, only their runs, one per stretch of
// consecutive pixels of one tile, are sorted), so a chunk's memory is its own content,
// whichever tiles it touched.
#pragma once

#include "raster/tile/framebuffer.h"
#include "raster/coverage/rasterize.h"
#include "raster/coverage/tiny_fragment.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace illum {

// The tiles a chunk touched: [first, last) in tile order. A chunk of a dense mesh touches a few
// of a 4K frame's two thousand tiles: its per-tile tables span only these.
struct TileSpan {
  std::uint32_t first = 0, last = 0;
  bool holds(std::uint32_t tile) const { return tile - first < last - first; }  // (unsigned: below first wraps)
  TileSpan joined(const TileSpan& other) const {
    if (first == last) return other;
    if (other.first == other.last) return *this;
    return {std::min(first, other.first), std::max(last, other.last)};
  }
};

// A stable counting sort by tile: value(item) of each of `items` into `sorted`, tile by tile,
// each tile's in the order appended; returns the tiles touched, and start[t − first] ..
// start[t − first + 1] are tile t's.
template <class Item, class Sorted, class TileOf, class Value>
TileSpan sortByTile(const std::vector<Item>& items, TileOf tileOf, Value value, std::vector<std::uint32_t>& start,
                    std::vector<Sorted>& sorted) {
  TileSpan span;
  if (items.empty()) {
    start.assign(1, 0);
    sorted.clear();
    return span;
  }
  span.first = ~std::uint32_t(0);
  for (const Item& item : items) {
    const std::uint32_t tile = tileOf(item);
    span.first = std::min(span.first, tile);
    span.last = std::max(span.last, tile + 1);
  }
  start.assign(span.last - span.first + 1, 0);
  for (const Item& item : items) ++start[tileOf(item) - span.first + 1];
  for (std::size_t t = 0; t + 1 < start.size(); ++t) start[t + 1] += start[t];
  sorted.resize(items.size());
  for (const Item& item : items) sorted[start[tileOf(item) - span.first]++] = value(item);
  // Each start was moved to its end: shift back by one tile.
  for (std::size_t t = start.size() - 1; t > 0; --t) start[t] = start[t - 1];
  start[0] = 0;
  return span;
}

// One chunk's tiny pixels of one kind, in runs of one tile.
template <class Pixel>
class TinyRuns {
 public:
  void clear() { count_ = 0, runs_.clear(); }
  // Room for `n` pixels after the last; commit(k, tile) then appends the first k of them to `tile`.
  Pixel* room(std::size_t n) {
    if (count_ + n > capacity_) grow(count_ + n);
    return pixels_.get() + count_;
  }
  void commit(std::size_t k, int tile) {
    if (k == 0) return;
    if (!runs_.empty() && runs_.back().tile == std::uint32_t(tile)) runs_.back().count += std::uint32_t(k);
    else runs_.push_back({std::uint32_t(tile), std::uint32_t(count_), std::uint32_t(k)});
    count_ += k;
  }
  TileSpan span() const { return span_; }
  // Sorts the runs by tile.
  void finish() {
    span_ = sortByTile(runs_, [](const Run& r) { return r.tile; }, [](const Run& r) { return r; }, start_, sorted_);
  }
  // f(first, count) for each run of the tile's pixels, in order.
  template <class F>
  void forEachRun(int tile, F&& f) const {
    if (!span_.holds(std::uint32_t(tile))) return;
    const std::size_t t = std::size_t(tile) - span_.first;
    for (std::uint32_t r = start_[t]; r < start_[t + 1]; ++r) f(pixels_.get() + sorted_[r].first, sorted_[r].count);
  }

 private:
  struct Run {
    std::uint32_t tile, first, count;
  };
  void grow(std::size_t least) {
    const std::size_t capacity = std::max(least, 2 * capacity_);
    std::unique_ptr<Pixel[]> grown(new Pixel[capacity]);
    std::copy(pixels_.get(), pixels_.get() + count_, grown.get());
    pixels_ = std::move(grown);
    capacity_ = capacity;
  }
  std::unique_ptr<Pixel[]> pixels_;
  std::size_t count_ = 0, capacity_ = 0;
  std::vector<Run> runs_, sorted_;
  TileSpan span_;                     // the tiles with runs
  std::vector<std::uint32_t> start_;  // per tile of span_, its first sorted run (and its end at tile + 1)
};

class TileBins {
 public:
  TileBins() = default;
  // Tiles for a width × height viewport, all empty (their memory kept).
  void reset(int width, int height);

  int tileCount() const { return tilesX_ * tilesY_; }
  PixelRect tileRect(int tile) const;
  int tileOf(int x, int y) const { return (y / kTileSize) * tilesX_ + x / kTileSize; }
  int tilesX() const { return tilesX_; }

  // Appends record `index` (whose triangle is `t`) to every tile its pixel bounding box overlaps.
  void addRecord(const TriangleSetup& t, std::uint32_t index);
  // How many records `tile` has so far.
  std::uint32_t recordsIn(int tile) const { return recordCount_[std::size_t(tile)]; }
  // Tiny triangles' pixels: coloured (flat, Gouraud) or surfaces (Phong).
  TinyRuns<TinyFragment> fragments;
  TinyRuns<TinySurface> surfaces;

  // Sorts what was appended by tile; then records(tile) and the tiny pixels' forEach hold it.
  void finish();
  // The tiles that have something, once finished.
  TileSpan span() const { return recordSpan_.joined(fragments.span()).joined(surfaces.span()); }
  std::span<const std::uint32_t> records(int tile) const {
    if (!recordSpan_.holds(std::uint32_t(tile))) return {};
    const std::size_t t = std::size_t(tile) - recordSpan_.first;
    return std::span(sortedRecords_).subspan(recordStart_[t], recordStart_[t + 1] - recordStart_[t]);
  }

 private:
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> recordTiles_;  // (tile, record), as appended
  std::vector<std::uint32_t> recordCount_;  // per tile, as appended
  // Sorted by tile: the record indices, and where each tile of recordSpan_ starts (and ends, at tile + 1).
  TileSpan recordSpan_;
  std::vector<std::uint32_t> recordStart_, sortedRecords_;
};

}  // namespace illum
