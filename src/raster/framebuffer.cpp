#include "raster/framebuffer.h"

#include <cstring>

namespace illum {

Framebuffer::Framebuffer(int width, int height, const Color4& clearColor)
    : width_(width), height_(height), color_(std::size_t(width) * std::size_t(height) * 4),
      depth_(std::size_t(width) * std::size_t(height), Real(1)) {
  // glClearColor + glClearDepth(1) + glClear.
  const std::uint8_t clear[4] = {toUnorm8(clearColor.r), toUnorm8(clearColor.g), toUnorm8(clearColor.b),
                                 toUnorm8(clearColor.a)};
  for (std::size_t i = 0; i < color_.size(); i += 4) std::memcpy(&color_[i], clear, 4);
}

Image Framebuffer::toImage() const {
  Image img(width_, height_);
  const std::size_t row = std::size_t(width_) * 4;
  for (int y = 0; y < height_; ++y)
    std::memcpy(img.pixel(0, height_ - 1 - y), &color_[std::size_t(y) * row], row);
  return img;
}

}  // namespace illum
