// Framebuffer stage: an RGBA8 colour buffer and a float depth buffer in GL window coordinates
// (row 0 at the bottom), the depth test GL_LESS, and 8-bit conversion round(clamp(c)·255).
// Stored tile by tile (64×64 pixels, row-major inside a tile, edge tiles padded to full size), so
// that the thread drawing a tile owns one contiguous block and full SIMD rows never leave it.
#pragma once

#include <illum/image.h>
#include <illum/lighting.h>

#include "math/unorm8.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace illum {

constexpr int kTileSize = 64;
// Pixels after each tile's block that belong to no pixel: a vector that starts on the tile's last
// row may run past it (its lanes outside the triangle masked) without touching the next tile.
constexpr int kTilePadding = 16;
constexpr std::size_t kTileBlock = std::size_t(kTileSize) * kTileSize + kTilePadding;

// One tile's depths and RGBA8 pixels held apart from the framebuffer (Framebuffer::lendTile), for
// `samples` samples per pixel, laid out as the framebuffer lays out each of its own.
struct TileMemory {
  std::vector<Real> depth;
  std::vector<std::uint32_t> color;
  void reserve(int samples) {
    const std::size_t n = kTileBlock * std::size_t(samples);
    if (depth.size() < n) depth.resize(n), color.resize(n);
  }
};

// The framebuffer keeps `samples` samples per pixel (multisampling), side by side: sample s of
// the tile's pixel i is at i·samples + s, so that a vector holds whole pixels' samples and a
// pixel's samples lie together for the resolve. One sample is the plain layout.
// Source-over blending of `c` onto the RGBA8 pixel `p`: RGB by (SRC_ALPHA, ONE_MINUS_SRC_ALPHA),
// alpha by (ONE, ONE_MINUS_SRC_ALPHA).
inline void blendOver(std::uint8_t* p, const Color4& c) {
  const Real a = std::clamp(c.a, Real(0), Real(1));
  for (int i = 0; i < 3; ++i) p[i] = toUnorm8(std::clamp(c[i], Real(0), Real(1)) * a + Real(p[i]) / 255 * (1 - a));
  p[3] = toUnorm8(a + Real(p[3]) / 255 * (1 - a));
}

class Framebuffer {
 public:
  Framebuffer() = default;
  // Cleared at once, every tile.
  Framebuffer(int width, int height, const Color4& clearColor, int samples = 1) {
    reset(width, height, clearColor, samples);
    clearAll();
  }

  // glClearColor + glClearDepth(1) + glClear at a new size, keeping the memory when it is big
  // enough (a renderer reuses one framebuffer from frame to frame). The clear is lazy: a tile is
  // cleared by clearTile when it is first drawn (by the thread that draws it, while it is hot in
  // its cache), and a tile never drawn is background in toImage without ever being touched.
  void reset(int width, int height, const Color4& clearColor, int samples = 1);
  void clearTile(int x0, int y0);
  void clearAll();  // every tile, for drawing that is not tile by tile

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

  // GL_LESS against the stored depth of a sample; on a pass the depth is written and true returned.
  bool depthTest(int x, int y, Real z, int sample = 0) {
    Real& stored = depthAt(x, y, sample);
    if (!(z < stored)) return false;
    stored = z;
    return true;
  }
  Real depth(int x, int y, int sample = 0) const { return depthAt(x, y, sample); }
  void writeColor(int x, int y, const Color4& c, int sample = 0) {
    std::uint8_t* p = colorAt(x, y, sample);
    for (int i = 0; i < 4; ++i) p[i] = toUnorm8(c[i]);
  }

  void blendColor(int x, int y, const Color4& c, int sample = 0) { blendOver(colorAt(x, y, sample), c); }

  // The picture as an image file stores it: row 0 at the top, each pixel its samples resolved.
  Image toImage() const;
  // The same into `image` (its memory reused), tiles in parallel; returns how many pixels differ
  // from `background` as toUnorm8 converts it.
  std::size_t toImage(Image& image, const Color4& background) const;
  // toImage a tile at a time, for a pipeline that hands each tile over once it is drawn, while it
  // is still in the drawing core's cache: imageOf sizes `image`, copyTile copies one tile (index
  // as tileRect numbers them: row by row from the bottom), its samples resolved (multisample.h),
  // and counts its pixels unlike `background8` (packUnorm8 of the background).
  void imageOf(Image& image) const;
  std::size_t copyTile(int tile, Image& image, std::uint32_t background8) const;
  int tileCount() const { return int(cleared_.size()); }

  // A tile drawn for the first and last time this frame, straight into the image, can live in
  // its thread's `memory`, hot in that core's cache, rather than in the framebuffer's own block,
  // which a 4K frame (67 MB of them) would clear and copy through main memory. lendTile points the
  // tile (not drawn since reset) at `memory` (reserved for the samples) until returnTile, which
  // forgets what was drawn there: the tile is undrawn again.
  bool drawn(int tile) const { return cleared_[std::size_t(tile)] != 0; }
  void lendTile(int tile, TileMemory& memory) {
    memory.reserve(samples_);
    block_[std::size_t(tile)] = {memory.depth.data(), memory.color.data()};
  }
  void returnTile(int tile) {
    block_[std::size_t(tile)] = {};
    cleared_[std::size_t(tile)] = 0;
  }
  // A tile finished before the frame is (nothing later reaches it), once copied into the image,
  // gives its block back for another tile to draw in: the memory the framebuffer holds is that of
  // the most tiles in progress at once, not of the frame. The tile is undrawn again.
  void releaseTile(int tile);
  // Blocks made so far (each a tile's samples), for the tests: what a frame held at most.
  std::size_t blocksMade() const { return pool_.size(); }

  // The tile whose bottom-left pixel is (x0, y0) (multiples of kTileSize): kTileSize² pixels' depths
  // and RGBA8 words (their samples side by side), row by row from the bottom, then kTilePadding
  // spare pixels.
  Real* depthTile(int x0, int y0) { return block_[tileOf(x0, y0)].depth; }
  std::uint32_t* colorTile(int x0, int y0) { return block_[tileOf(x0, y0)].color; }

 private:
  struct Block {
    Real* depth = nullptr;
    std::uint32_t* color = nullptr;
  };

  std::size_t at(int x, int y, int sample) const { return inTile(x, y) * std::size_t(samples_) + std::size_t(sample); }
  Real& depthAt(int x, int y, int sample) const { return block_[tileOf(x, y)].depth[at(x, y, sample)]; }
  std::uint8_t* colorAt(int x, int y, int sample) const {
    return reinterpret_cast<std::uint8_t*>(block_[tileOf(x, y)].color + at(x, y, sample));
  }
  static std::size_t inTile(int x, int y) {
    return std::size_t(y % kTileSize) * kTileSize + std::size_t(x % kTileSize);
  }
  std::size_t tileOf(int x, int y) const { return std::size_t(y / kTileSize) * std::size_t(tilesX_) + std::size_t(x / kTileSize); }
  std::size_t blockSize() const { return kTileBlock * std::size_t(samples_); }
  // A block of the pool for `tile` (thread-safe: tiles are cleared by the threads drawing them).
  Block acquire(std::size_t tile);

  int width_ = 0, height_ = 0, tilesX_ = 0, samples_ = 1;
  std::uint32_t clear_ = 0;            // the clear colour as an RGBA8 word
  std::vector<std::uint8_t> cleared_;  // per tile: cleared since reset
  std::vector<Block> block_;           // per tile: where its pixels are (a block of the pool, lent memory, or none)
  // The blocks tiles are drawn in, made when a tile is first cleared and no block is free, and
  // kept from frame to frame (their memory is touched once): a frame whose tiles are all drawn in
  // lent memory makes none.
  struct OwnBlock {
    std::unique_ptr<Real[]> depth;
    std::unique_ptr<std::uint32_t[]> color;
  };
  std::vector<OwnBlock> pool_;            // every block made, of blockSize() for blockSamples_
  int blockSamples_ = 0;
  std::vector<std::uint32_t> free_;       // those no tile holds
  std::vector<std::int32_t> held_;        // per tile: the index in pool_ of the block it holds, or −1
  std::unique_ptr<std::mutex> poolMutex_ = std::make_unique<std::mutex>();
};

}  // namespace illum
