#include "raster/tile/framebuffer.h"

#include "raster/tile/multisample.h"
#include "raster/tile/tile_memory.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

namespace illum {

void Framebuffer::reset(int width, int height, const Color4& clearColor, int samples) {
  width_ = width;
  height_ = height;
  samples_ = samples;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  const std::size_t tiles = std::size_t(tilesX_) * std::size_t((height + kTileSize - 1) / kTileSize);
  // The blocks made are kept for tiles of the same size; every one is free again.
  if (samples != blockSamples_) pool_.clear(), blockSamples_ = samples;
  free_.resize(pool_.size());
  for (std::size_t b = 0; b < pool_.size(); ++b) free_[b] = std::uint32_t(pool_.size() - 1 - b);
  clear_ = packUnorm8(clearColor);
  cleared_.assign(tiles, 0);
  block_.assign(tiles, Block{});
  held_.assign(tiles, -1);
}

Framebuffer::Block Framebuffer::acquire(std::size_t tile) {
  const std::lock_guard<std::mutex> lock(*poolMutex_);
  if (free_.empty()) {
    free_.push_back(std::uint32_t(pool_.size()));
    pool_.push_back({std::unique_ptr<Real[]>(new Real[blockSize()]), std::unique_ptr<std::uint32_t[]>(new std::uint32_t[blockSize()])});
  }
  const std::uint32_t b = free_.back();
  free_.pop_back();
  held_[tile] = std::int32_t(b);
  return {pool_[b].depth.get(), pool_[b].color.get()};
}

void Framebuffer::releaseTile(int tile) {
  const auto t = std::size_t(tile);
  if (held_[t] >= 0) {
    const std::lock_guard<std::mutex> lock(*poolMutex_);
    free_.push_back(std::uint32_t(held_[t]));
  }
  held_[t] = -1;
  block_[t] = {};
  cleared_[t] = 0;
}

void Framebuffer::clearTile(int x0, int y0) {
  const std::size_t t = tileOf(x0, y0);
  if (cleared_[t]) return;
  if (!block_[t].depth) block_[t] = acquire(t);  // (a lent tile has its memory)
  fillTile(block_[t].depth, block_[t].color, blockSize(), clear_);
  cleared_[t] = 1;
}

void Framebuffer::clearAll() {
  tbb::parallel_for(0, int(cleared_.size()), [&](int t) {
    clearTile(t % tilesX_ * kTileSize, t / tilesX_ * kTileSize);
  });
}

Image Framebuffer::toImage() const {
  Image img;
  toImage(img, Color4(0));
  return img;
}

void Framebuffer::imageOf(Image& image) const {
  image.width = width_;
  image.height = height_;
  image.rgba.resize(std::size_t(width_) * std::size_t(height_) * 4);
}

std::size_t Framebuffer::copyTile(int tile, Image& image, std::uint32_t background8) const {
  const int x0 = tile % tilesX_ * kTileSize, y0 = tile / tilesX_ * kTileSize;
  const int count = std::min(kTileSize, width_ - x0), rows = std::min(kTileSize, height_ - y0);
  // The image's rows run from the top: the tile's bottom row is the lowest of its rows there.
  std::uint8_t* const dst = image.pixel(x0, height_ - 1 - y0);
  const std::ptrdiff_t imageStride = -std::ptrdiff_t(width_) * 4;
  if (!cleared_[std::size_t(tile)]) {  // never drawn: the clear colour
    fillPixels(dst, imageStride, count, rows, clear_);
    return std::size_t(clear_ != background8) * std::size_t(count) * std::size_t(rows);
  }
  const std::uint32_t* src = block_[std::size_t(tile)].color;
  if (samples_ > 1) return resolvePixels(src, samples_, kTileSize, dst, imageStride, count, rows, background8);
  return copyPixels(src, kTileSize * 4, dst, imageStride, count, rows, background8);
}

std::size_t Framebuffer::toImage(Image& image, const Color4& background) const {
  imageOf(image);
  const std::uint32_t background8 = packUnorm8(background);
  std::atomic<std::size_t> unlike{0};
  tbb::parallel_for(0, tileCount(), [&](int tile) { unlike += copyTile(tile, image, background8); });
  return unlike;
}

}  // namespace illum
