// Fragment stage of the binned pipeline, for opaque drawing. Flat and Gouraud colour their pixels
// in the SIMD depth pass (tile_raster.h). Phong keeps the tile's visible surface (position,
// normal, colour per pixel) from its depth pass and lights each visible pixel once, 16 at a time
// (shade_points.h). With a texture or a watched pixel, the depth pass leaves in each pixel the
// record it shows, and the visible pixels are coloured afterwards one by one (Phong lit in
// batches). The colours are those the one-pixel path (draw.h) computes, fragment by fragment,
// with the same formulas.
#pragma once

#include "raster/shade/draw.h"
#include "raster/shade/shade_visible.h"
#include "raster/coverage/tile_raster.h"
#include "raster/coverage/tiny_fragment.h"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace illum {

// Where a tile's pixels are kept (the framebuffer's layout): depth and RGBA8 words of each pixel's
// `count` samples, side by side (framebuffer.h).
struct SampleTiles {
  int count = 1;
  Real* depth;
  std::uint32_t* color;
};

// One thread's working memory for a tile, reused from tile to tile.

struct TileScratch {
  // The record each sample shows (the framebuffer's layout, padding included), kNoWinner between tiles.
  std::vector<std::uint32_t> winners = std::vector<std::uint32_t>(kTileBlock, kNoWinner);
  // Phong's visible surface (tile_raster.h): position, normal, colour planes and owners.
  Real surface[10][kTileBlock];
  std::array<std::uint32_t, kTileBlock> owner;
  TileMemory pixels;  // a tile drawn straight into the image (Framebuffer::lendTile)
  TileScratch();
  ~TileScratch();
  // The deferred colours' batch and lists (shade_visible.h).
  VisibleBatch& visible() { return *visible_; }
  ShownLists shown;
  // Room for `samples` samples per pixel.
  void reserveSamples(int samples) {
    if (winners.size() < std::size_t(samples) * kTileBlock) winners.resize(std::size_t(samples) * kTileBlock, kNoWinner);
  }

 private:
  std::unique_ptr<VisibleBatch> visible_;
};

// A tile's pixels of tiny triangles (tile_raster.h), each where its count of records before it
// puts it: coloured, or surfaces for Phong shading.
struct TinyPixels {
  std::span<const TinyRun<TinyFragment>> fragments;
  std::span<const TinyRun<TinySurface>> surfaces;
  bool empty() const { return fragments.empty() && surfaces.empty(); }
};

// Draws `records` (the tile's, in submission order) and `tiny` into the tile `rect` without
// blending, kept in `tiles`. Returns the fragments (samples, when multisampled) that passed the
// depth test.
std::size_t drawOpaqueTile(const DrawTarget& target, std::span<const DrawRecord* const> records, const TinyPixels& tiny,
                           const PixelRect& rect, TileScratch& scratch, const SampleTiles& tiles);

// Draws the translucent `records` (the tile's, after the opaque ones, farthest first) into the
// tile, blending: each record's coverage and depth test (writing depth) at every sample, then its
// pixels' colours in SIMD lanes as the deferred ones are found (shade_visible.h), blended over the
// samples it covers (source-over), record after record. Returns the fragments (samples) that passed.
std::size_t drawBlendedTile(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                            TileScratch& scratch, const SampleTiles& tiles);

}  // namespace illum
