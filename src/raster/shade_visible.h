// The deferred draws' one shade hand-off: the (pixel, record) pairs a tile's pixels show (each
// record once per pixel, whichever of its samples show it), gathered object by object and
// coloured in SIMD lanes: the pixel centre's barycentrics → perspective-correct weights → the
// draw's colour (flat, Gouraud's interpolated one, or Phong's surface lit by shadePoints) → the
// texel (texture_lanes-inl.h) → GL_MODULATE → RGBA8, written to every sample that shows the
// record. The same bits as the one-pixel formulas of fragment.h; an object whose glTF maps are
// drawn is lit pixel by pixel through them.
#pragma once

#include "raster/draw.h"
#include "raster/tile_raster.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace illum {

// Where a tile's deferred colours go: its RGBA8 words and the record each sample shows, each
// pixel's `count` samples side by side (framebuffer.h).
struct VisibleSamples {
  int count = 1;
  std::uint32_t* color;
  const std::uint32_t* winners;

  // f(index, slot) once for each record that some sample of pixel `index` shows, in sample order.
  template <class F>
  void forEachShown(int index, F&& f) const {
    const std::uint32_t* shown = winners + std::size_t(index) * std::size_t(count);
    for (int s = 0; s < count; ++s) {
      const std::uint32_t slot = shown[s];
      if (slot == kNoWinner) continue;
      bool earlier = false;
      for (int e = 0; e < s && !earlier; ++e) earlier = shown[e] == slot;
      if (!earlier) f(index, slot);
    }
  }
  void write(int index, std::uint32_t slot, std::uint32_t rgba) const {
    const std::size_t at = std::size_t(index) * std::size_t(count);
    for (int s = 0; s < count; ++s)
      if (winners[at + std::size_t(s)] == slot) color[at + std::size_t(s)] = rgba;
  }
  // The watched pixel reports what its first sample shows.
  bool reported(int index, std::uint32_t slot) const { return winners[std::size_t(index) * std::size_t(count)] == slot; }
};

// A batch of pairs of one object, structure of arrays, and what the lanes make of them.
struct VisibleBatch {
  static constexpr std::size_t kSize = 256;
  static constexpr int kValues = 12;  // per vertex, at most: position 3, normal 3, colour 4, uv 2
  std::size_t count = 0;
  // Per pair: the pixel centre's screen-space barycentrics, 1/w at the vertices and, for the
  // texture's footprint, how the barycentrics move one pixel right (a·256/area) and up (b·…).
  alignas(64) Real l[3][kSize];
  alignas(64) Real invW[3][kSize];
  alignas(64) Real stepX[3][kSize];
  alignas(64) Real stepY[3][kSize];
  alignas(64) Real vertex[3][kValues][kSize];  // per vertex, the values the layout below names
  alignas(64) std::uint32_t negate[kSize];     // all ones: a back face under two-sided lighting
  // Results: the surface (Phong), the colour (flat: as gathered; Gouraud: interpolated; Phong: the
  // vertex colour, or the base colour tinted by the texel), the texel and the lit colour.
  alignas(64) Real position[3][kSize];
  alignas(64) Real normal[3][kSize];
  alignas(64) Real color[4][kSize];
  alignas(64) Real texel[4][kSize];
  alignas(64) Real lit[4][kSize];
  alignas(64) std::uint32_t rgba[kSize];
  std::uint16_t pixel[kSize];
  std::uint32_t slot[kSize];
};

// What a batch's lanes compute, the same for every pair of the batch (its object's).
struct VisibleLayout {
  Shading shading = Shading::Phong;
  int lit = -1, position = -1, normal = -1, color = -1, uv = -1;  // in VisibleBatch::vertex, −1: none
  const Texture* texture = nullptr;  // the object's drawn texture
  bool baseTexel = false;            // the texel tints the base colour before lighting
  Color4 baseColor{1};               // the material's base colour and alpha, for baseTexel without vertex colours
};

// The lanes' part (SIMD, dispatched): weights, colour or surface, texel; then, after lighting,
// GL_MODULATE and RGBA8.
void interpolateVisible(const VisibleLayout& layout, VisibleBatch& batch);
void finishVisible(const VisibleLayout& layout, VisibleBatch& batch);

// Colours each record the tile's pixels show (`out`), object by object in batches.
class VisibleShader {
 public:
  VisibleShader(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                VisibleBatch& batch, const VisibleSamples& out)
      : target_(target), records_(records), rect_(rect), b_(batch), out_(out) {}
  void add(int index, std::uint32_t slot);
  void flush();

 private:
  void shadeMapped(const Object& object, int index, std::uint32_t slot, const DrawRecord& r);
  const DrawTarget& target_;
  std::span<const DrawRecord* const> records_;
  const PixelRect& rect_;
  VisibleBatch& b_;
  const VisibleSamples& out_;
  std::uint32_t object_ = 0;
  VisibleLayout layout_;
};

}  // namespace illum
