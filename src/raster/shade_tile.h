// Fragment stage of the binned pipeline, for opaque drawing: a tile's records go through the
// depth pass first (tile_raster.h), which leaves in every pixel the one record it shows; then each
// visible pixel is coloured once: flat and Gouraud from the record's colours, Phong lit in
// batches of pixels by the SIMD equation (shade_points.h). The colours are those the one-pixel
// path (draw.h) computes, fragment by fragment, with the same formulas.
#pragma once

#include "raster/draw.h"
#include "raster/tile_raster.h"

#include <array>
#include <cstdint>
#include <span>

namespace illum {

// One thread's working memory for a tile, reused from tile to tile.
struct TileScratch {
  static constexpr std::size_t kBatch = 256;  // Phong pixels lit together
  std::array<std::uint32_t, kTileBlock> winners;  // the tile's layout, padding included
  // Phong batch, structure of arrays: eye position, normal, vertex colour, texel, lit colour.
  Real soa[18][kBatch];
  std::uint16_t pixel[kBatch];  // index inside the tile
  std::uint32_t slot[kBatch];   // which record
  TileScratch() { winners.fill(kNoWinner); }
};

// Draws `records` (the tile's, in submission order) into the tile `rect` without blending.
// Returns the fragments that passed the depth test.
std::size_t drawOpaqueTile(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                           TileScratch& scratch);

}  // namespace illum
