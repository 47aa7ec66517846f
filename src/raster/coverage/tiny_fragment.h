// A pixel of a tiny triangle, worked out at setup (tile_raster.h) and kept in its tile's list
// (bin.h) with its place among the tile's records, so that the tile draws everything in
// submission order: for flat and Gouraud shading its colour, for Phong shading the visible
// surface there, to be lit with the tile's other pixels.
#pragma once

#include "raster/tile/framebuffer.h"

#include <illum/real.h>

#include <cstdint>

namespace illum {

// Where a tiny triangle's pixel goes, its tag: its pixel in the tile (multisampled: its sample,
// pixel · samples + sample, the tile's sample planes' index) and how many of the tile's records
// come before it (those of one setup chunk: at most 1024 triangles, each cut into at most 7
// pieces by the clipper, well below 2^16).
struct TinyTag {
  static constexpr int kPixelBits = 16;  // a 64×64 tile's samples, up to 16 per pixel
  static std::uint32_t of(std::uint32_t recordsBefore, std::uint32_t pixel) { return recordsBefore << kPixelBits | pixel; }
  static std::uint32_t pixel(std::uint32_t tag) { return tag & ((1u << kPixelBits) - 1); }
  static std::uint32_t recordsBefore(std::uint32_t tag) { return tag >> kPixelBits; }
};

// A tiny triangle's bounds hold at most kTinyPixels pixel centres (tile_raster.h: isTiny).
constexpr int kTinyPixels = 32;

// Lane k of a tiny triangle's bounds, w pixels wide: column k mod w, row k / w, and its offset in
// the tile from the bounds' first pixel.
struct TinyLanes {
  float column[kTinyPixels + 1][kTinyPixels], row[kTinyPixels + 1][kTinyPixels];
  std::uint32_t offset[kTinyPixels + 1][kTinyPixels];
};
constexpr TinyLanes makeTinyLanes() {
  TinyLanes lanes{};
  for (int w = 1; w <= kTinyPixels; ++w)
    for (int k = 0; k < kTinyPixels; ++k) {
      lanes.column[w][k] = float(k % w), lanes.row[w][k] = float(k / w);
      lanes.offset[w][k] = std::uint32_t((k / w) * kTileSize + k % w);
    }
  return lanes;
}
alignas(64) inline constexpr TinyLanes kTinyLanes = makeTinyLanes();

struct TinyFragment {
  std::uint32_t tag;
  Real z;
  std::uint32_t color;  // RGBA8, as the framebuffer stores it
};

// Phong: what rasterizeSurface keeps of a pixel (objects without vertex colours).
struct TinySurface {
  std::uint32_t tag;
  Real z;
  std::uint32_t owner;
  Real position[3], normal[3];
};

// A stretch of one tile's tiny pixels stored together (one chunk's), and how many of the tile's
// records (gathered from every chunk) come before that chunk's.
template <class Pixel>
struct TinyRun {
  const Pixel* first;
  std::uint32_t count;
  std::uint32_t recordsBefore;
};

}  // namespace illum
