// What the two drivers of the pipeline share (pipeline.cpp, binned and parallel; reference/, in
// submission order on one thread): drawing one record's fragments (rasterize → fragment →
// framebuffer), the drawing order and the finished frame. Records come from draw_record.h.
#pragma once

#include <illum/render.h>

#include "raster/draw_record.h"
#include "raster/fragment.h"
#include "raster/frame_context.h"
#include "raster/framebuffer.h"
#include "raster/rasterize.h"
#include "raster/setup.h"
#include "raster/vertex.h"
#include "shading/shade_points.h"

#include <cstdint>
#include <vector>

namespace illum {

// Multisampling shades a pixel at its centre, so every pass that finds the same triangle piece
// in a pixel computes the same colour: the first pass to shade it keeps it here for the others.
// Tile by tile in the framebuffer's layout (a tile's thread owns its block); reset before pass 0.
class ShadedPixelCache {
 public:
  static constexpr std::uint64_t kNone = ~std::uint64_t(0);
  void reset(int width, int height) {
    tilesX_ = (width + kTileSize - 1) / kTileSize;
    const std::size_t size = std::size_t(tilesX_) * std::size_t((height + kTileSize - 1) / kTileSize) * kTileBlock;
    key_.assign(size, kNone);
    color_.resize(size);
  }
  static std::uint64_t keyOf(const DrawRecord& r) {
    return std::uint64_t(r.object) << 35 | std::uint64_t(r.triangle) << 3 | r.piece;
  }
  // The slot of pixel `index` (tile-local) of the tile whose rectangle is `rect`.
  std::size_t slot(const PixelRect& rect, int index) const {
    return (std::size_t(rect.minY / kTileSize) * std::size_t(tilesX_) + std::size_t(rect.minX / kTileSize)) * kTileBlock +
           std::size_t(index);
  }
  std::uint64_t& key(std::size_t slot) { return key_[slot]; }
  std::uint32_t& color(std::size_t slot) { return color_[slot]; }

 private:
  int tilesX_ = 0;
  std::vector<std::uint64_t> key_;
  std::vector<std::uint32_t> color_;  // RGBA8, as the framebuffer stores it
};

// What every triangle of a frame draws into.
struct DrawTarget {
  const FrameContext& frame;
  const Scene& scene;
  Framebuffer& fb;
  PixelProbe* probe;  // null unless a pixel is watched
  std::vector<AttributeLayout> layouts;  // per object: what its records carry
  // Phong shading lit from the tile's visible surface in SIMD (shade_tile.h): float channels, no
  // texture or map in the scene and no watched pixel. Then, per object, its lighting and vertex colours.
  bool litFromSurface = false;
  std::vector<ShadeSetup> setups;
  std::vector<std::uint8_t> colored;
  // Per object: the object whose setup and colouring light it alike (itself or an earlier one),
  // the owner its pixels name in the visible surface, so that a vector of pixels of several such
  // objects is lit in one pass (shadeOwnedPoints lights lanes of one owner at a time).
  std::vector<std::uint32_t> shadeOwner;
  // Per object: blending on and the object translucent (material, texture or vertex alpha below 1).
  // An opaque object is drawn as without blending even when it is on: its alpha of 1 would blend
  // to the fragment itself, and so its interpolated alpha, a few ulps from 1, cannot blend at all.
  std::vector<std::uint8_t> translucent;
  ShadedPixelCache* shadedPixels = nullptr;  // multisampling: colours of earlier passes (Phong)
  // Flat and Gouraud pixels coloured in the depth pass itself (tile_raster.h): float channels, one
  // sample, no watched pixel.
  bool colorsInDepthPass = false;
  // Per object: its tiny triangles worked out at setup, without records (tile_raster.h): coloured
  // when colorsInDepthPass (opaque, untextured objects), or as visible surface when litFromSurface
  // (opaque objects without vertex colours).
  std::vector<std::uint8_t> tiny;

  DrawTarget(const FrameContext& frame, const Scene& scene, Framebuffer& fb, PixelProbe* probe);
  const AttributeLayout& layout(const DrawRecord& r) const { return layouts[r.object]; }
  bool blends(const DrawRecord& r) const { return translucent[r.object] != 0; }
};

// Draws the record's pixels inside `rect`; adds the fragments that passed the depth test.
void drawRecord(const DrawTarget& target, const DrawRecord& record, const PixelRect& rect, std::size_t& fragments);

// Records the fragment at the watched pixel: where it was lit (weights w), the lit colour, the
// texel that modulated it or, with texelIsBaseColor, tinted its base colour (null without a
// texture) and what was written; with `mapped`, the material and normal glTF's maps gave the pixel.
void recordProbe(const DrawTarget& target, const DrawRecord& record, const std::array<Real, 3>& w, const Color4& lit,
                 const Vec4* texel, const Color4& written, bool texelIsBaseColor = false,
                 const MappedSurface* mapped = nullptr);

// Scene order, or with blending the opaque objects first and then the translucent ones from the
// farthest to the nearest. Ties keep scene order.
std::vector<const Object*> drawingOrder(const Scene& scene, const FrameContext& frame);

// The pixels of a finished picture unlike the background (as the framebuffer converts it).
std::size_t pixelsUnlike(const Image& image, const Color4& background);

}  // namespace illum
