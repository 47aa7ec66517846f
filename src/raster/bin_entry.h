// One entry of a tile's list (bin.h), in submission order: a draw record, by its index in its
// chunk's arena, or one fragment of a tiny triangle coloured at setup (tile_raster.h).
#pragma once

#include <illum/real.h>

#include <cstdint>

namespace illum {

struct BinEntry {
  std::uint32_t tag;    // index << 1 for a record; pixel << 1 | 1 for a fragment (tile-local pixel)
  Real z;               // a fragment's depth
  std::uint32_t color;  // a fragment's RGBA8 colour

  bool isFragment() const { return tag & 1; }
  std::uint32_t index() const { return tag >> 1; }  // the record's, or the fragment's pixel
  static BinEntry record(std::uint32_t index) { return {index << 1, 0, 0}; }
  static BinEntry fragment(std::uint32_t pixel, Real z, std::uint32_t color) { return {pixel << 1 | 1, z, color}; }
};

}  // namespace illum
