#include "raster/framebuffer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstring>

namespace illum {

void Framebuffer::reset(int width, int height, const Color4& clearColor) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  const std::size_t tiles = std::size_t(tilesX_) * std::size_t((height + kTileSize - 1) / kTileSize);
  if (depth_.size() != tiles * kTileBlock) {
    depth_.resize(tiles * kTileBlock);
    color_.resize(tiles * kTileBlock * 4);
  }
  clear_ = packUnorm8(clearColor);
  cleared_.assign(tiles, 0);
}

void Framebuffer::clearTile(int x0, int y0) {
  const std::size_t t = tileOf(x0, y0);
  if (cleared_[t]) return;
  std::fill_n(&depth_[t * kTileBlock], kTileBlock, Real(1));
  std::uint8_t* c = &color_[t * kTileBlock * 4];
  for (std::size_t i = 0; i < kTileBlock; ++i) std::memcpy(c + 4 * i, &clear_, 4);
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
  const bool drawn = cleared_[std::size_t(tile)];  // else never drawn: the clear colour
  std::size_t unlike = 0;
  for (int y = y0; y < y0 + rows; ++y) {
    std::uint8_t* dst = image.pixel(x0, height_ - 1 - y);
    if (!drawn) {
      for (int i = 0; i < count; ++i) std::memcpy(dst + 4 * i, &clear_, 4);
      continue;
    }
    const std::uint8_t* src = &color_[index(x0, y) * 4];
    std::memcpy(dst, src, std::size_t(count) * 4);
    for (int i = 0; i < count; ++i) {
      std::uint32_t p;
      std::memcpy(&p, src + 4 * i, 4);
      unlike += p != background8;
    }
  }
  return drawn ? unlike : std::size_t(clear_ != background8) * std::size_t(count) * std::size_t(rows);
}

std::size_t Framebuffer::toImage(Image& image, const Color4& background) const {
  imageOf(image);
  const std::uint32_t background8 = packUnorm8(background);
  std::atomic<std::size_t> unlike{0};
  tbb::parallel_for(0, tileCount(), [&](int tile) { unlike += copyTile(tile, image, background8); });
  return unlike;
}

}  // namespace illum
