// Occlusion by blocks (a hierarchical depth test, as in Greene, Kass and Miller's "Hierarchical
// Z-Buffer Visibility", 1993, one level deep): the farthest depth of each 4×4-pixel block of a
// tile, so that a triangle behind everything already drawn where its bounds lie is skipped
// without testing its samples. Most of a detailed model's triangles are such: 2CylinderEngine at
// 1280×720 and 4 samples has 47 % of its triangle-in-tile draws hidden by their bounds alone.
//
// A skip changes nothing a draw would have: it is taken only when the triangle's nearest vertex
// depth, less a margin for the rounding of interpolated depths, is not nearer than any depth of
// those blocks, so that GL_LESS fails at every sample the triangle could cover.
#pragma once

#include <illum/real.h>

#include "raster/coverage/triangle.h"
#include "raster/coverage/rasterize.h"
#include "raster/tile/framebuffer.h"

#include <algorithm>
#include <cstdint>

namespace illum {

class DepthBounds {
 public:
  static constexpr int kBlock = 4, kBlocks = kTileSize / kBlock;  // a tile is kBlocks × kBlocks blocks
  static_assert(kBlocks <= 16);

  // A tile's depth plane, just cleared or in any state: every block is worked out when asked.
  DepthBounds(const Real* depth, int samples, const PixelRect& tile) {
    s_.depth = depth, s_.samples = samples, s_.tile = tile;
    sampleShift_ = __builtin_ctz(unsigned(samples));
    std::fill_n(s_.stale, kBlocks, std::uint16_t(~0u));
  }

  // Whether every sample of `t`'s pixels in the tile keeps its depth under GL_LESS (then drawing
  // `t` there changes nothing).
  bool hidden(const TriangleSetup& t);
  // The triangle hidden() was last asked about changed depths in the tile (somewhere in its bounds).
  void drawn() {
    for (int by = s_.asked.minY; by <= s_.asked.maxY; ++by) s_.stale[by] |= s_.asked.columns;
  }
  // Tile-local sample `at` (pixel·samples + sample) changed its depth. (A shift, not a division:
  // this is asked for every tiny fragment that passes, and samples is a power of two.)
  void drawnAt(std::uint32_t at) {
    const std::uint32_t pixel = at >> sampleShift_;
    s_.stale[pixel / kTileSize / kBlock] |= std::uint16_t(1u << (pixel % kTileSize / kBlock));
  }

  // What the test works on (depth_bounds.cpp, a vector of blocks at a time).
  struct State {
    const Real* depth;
    int samples;
    PixelRect tile;
    std::uint16_t stale[kBlocks];  // per row of blocks, those whose farthest is not worked out
    // The blocks the last triangle asked about touches: rows minY..maxY, in each the columns
    // whose bits are set (none when its bounds miss the tile).
    struct {
      int minY = 0, maxY = -1;
      std::uint16_t columns = 0;
    } asked;
    alignas(64) Real farthest[kBlocks][kBlocks] = {};
  };

 private:
  State s_;
  int sampleShift_;  // log2 of the samples per pixel
};

}  // namespace illum
