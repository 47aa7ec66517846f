#include "raster/framebuffer.h"

#include <algorithm>
#include <cstring>

namespace illum {

Framebuffer::Framebuffer(int width, int height, const Color4& clearColor)
    : width_(width), height_(height), tilesX_((width + kTileSize - 1) / kTileSize),
      color_(std::size_t(tilesX_) * std::size_t((height + kTileSize - 1) / kTileSize) * kTileBlock * 4),
      depth_(color_.size() / 4, Real(1)) {
  // glClearColor + glClearDepth(1) + glClear.
  const std::uint8_t clear[4] = {toUnorm8(clearColor.r), toUnorm8(clearColor.g), toUnorm8(clearColor.b),
                                 toUnorm8(clearColor.a)};
  for (std::size_t i = 0; i < color_.size(); i += 4) std::memcpy(&color_[i], clear, 4);
}

Image Framebuffer::toImage() const {
  Image img(width_, height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; x += kTileSize)
      std::memcpy(img.pixel(x, height_ - 1 - y), &color_[index(x, y) * 4], std::size_t(std::min(kTileSize, width_ - x)) * 4);
  return img;
}

}  // namespace illum
