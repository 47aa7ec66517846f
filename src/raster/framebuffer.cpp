#include "raster/framebuffer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstring>

namespace illum {
namespace {

std::uint32_t packed(const Color4& c) {
  const std::uint8_t bytes[4] = {toUnorm8(c.r), toUnorm8(c.g), toUnorm8(c.b), toUnorm8(c.a)};
  std::uint32_t p;
  std::memcpy(&p, bytes, 4);
  return p;
}

}  // namespace

void Framebuffer::reset(int width, int height, const Color4& clearColor) {
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTileSize - 1) / kTileSize;
  const std::size_t tiles = std::size_t(tilesX_) * std::size_t((height + kTileSize - 1) / kTileSize);
  if (depth_.size() != tiles * kTileBlock) {
    depth_.resize(tiles * kTileBlock);
    color_.resize(tiles * kTileBlock * 4);
  }
  clear_ = packed(clearColor);
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

std::size_t Framebuffer::toImage(Image& image, const Color4& background) const {
  image.width = width_;
  image.height = height_;
  image.rgba.resize(std::size_t(width_) * std::size_t(height_) * 4);
  const std::uint32_t background8 = packed(background);
  std::atomic<std::size_t> unlike{0};
  tbb::parallel_for(0, (height_ + kTileSize - 1) / kTileSize, [&](int band) {
    std::size_t n = 0;
    for (int y = band * kTileSize; y < std::min(height_, (band + 1) * kTileSize); ++y)
      for (int x = 0; x < width_; x += kTileSize) {
        const int count = std::min(kTileSize, width_ - x);
        std::uint8_t* dst = image.pixel(x, height_ - 1 - y);
        if (!cleared_[tileOf(x, y)]) {  // never drawn: the clear colour
          for (int i = 0; i < count; ++i) std::memcpy(dst + 4 * i, &clear_, 4);
          continue;
        }
        const std::uint8_t* src = &color_[index(x, y) * 4];
        std::memcpy(dst, src, std::size_t(count) * 4);
        for (int i = 0; i < count; ++i) {
          std::uint32_t p;
          std::memcpy(&p, src + 4 * i, 4);
          n += p != background8;
        }
      }
    unlike += n;
  });
  return unlike;
}

}  // namespace illum
