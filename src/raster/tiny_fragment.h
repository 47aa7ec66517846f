// A pixel of a tiny triangle, coloured at setup (tile_raster.h) and kept in its tile's list
// (bin.h) with its place among the tile's records, so that the tile draws everything in
// submission order.
#pragma once

#include <illum/real.h>

#include <cstdint>

namespace illum {

struct TinyFragment {
  static constexpr int kPixelBits = 12;  // a 64×64 tile's pixels
  std::uint32_t tag;    // recordsBefore << kPixelBits | pixel (tile-local)
  Real z;
  std::uint32_t color;  // RGBA8, as the framebuffer stores it

  std::uint32_t pixel() const { return tag & ((1u << kPixelBits) - 1); }
  // How many of the tile's records come before it.
  std::uint32_t recordsBefore() const { return tag >> kPixelBits; }
  static std::uint32_t tagOf(std::uint32_t recordsBefore, std::uint32_t pixel) {
    return recordsBefore << kPixelBits | pixel;
  }
};

}  // namespace illum
