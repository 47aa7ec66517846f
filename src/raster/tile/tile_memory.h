// Filling and copying a tile's pixels a vector at a time (Highway, dispatched at run time): the
// framebuffer clears every tile it draws and copies it into the image, 8 MB each at 4K, which
// 16-byte stores make a noticeable share of a simple frame.
#pragma once

#include <illum/real.h>

#include <cstddef>
#include <cstdint>

namespace illum {

// depth[0, n) = 1 and color[0, n) = clear (an RGBA8 word).
void fillTile(Real* depth, std::uint32_t* color, std::size_t n, std::uint32_t clear);

// `rows` rows of `count` pixels: row r from src + r·srcStride to dst + r·dstStride (in bytes, which
// may be negative: an image's rows run the other way). Returns how many differ from `background`.
std::size_t copyPixels(const std::uint32_t* src, std::ptrdiff_t srcStride, std::uint8_t* dst, std::ptrdiff_t dstStride,
                       int count, int rows, std::uint32_t background);

// Each of `rows` rows of `count` pixels from dst + r·dstStride on set to `value`.
void fillPixels(std::uint8_t* dst, std::ptrdiff_t dstStride, int count, int rows, std::uint32_t value);

}  // namespace illum
