// What the two drivers of the pipeline share (pipeline.cpp, binned and parallel; reference/, in
// submission order on one thread): drawing one record's fragments (rasterize → fragment →
// framebuffer), the drawing order and the finished frame. Records come from draw_record.h.
#pragma once

#include <illum/render.h>

#include "raster/setup/draw_record.h"
#include "raster/shade/fragment.h"
#include "raster/frame_context.h"
#include "raster/tile/framebuffer.h"
#include "raster/coverage/rasterize.h"
#include "raster/setup/setup.h"
#include "raster/setup/vertex.h"
#include "shading/shade_points.h"

#include <cstdint>
#include <span>
#include <vector>

namespace illum {

// How an object's triangles are drawn, chosen once per frame for each object by chooseRoute, the
// one place the rasterizer decides it. Every route's colours are the one-pixel formulas' bits.
enum class Route : std::uint8_t {
  Colored,   // flat and Gouraud, untextured: coloured as the depth pass finds each pixel (tile_raster.h)
  Surface,   // Phong without texture or maps, one sample: the visible surface kept, lit once per pixel
  Deferred,  // the record each pixel (each sample) shows kept, coloured afterwards (shade_visible.h)
  Blended,   // translucent under blending: fragment by fragment, in order (drawRecord)
};
Route chooseRoute(const FrameContext& frame, const Object& object, bool translucent);
// Phong without a texture, glTF's maps or ambient occlusion, in float channels: each pixel's colour
// is the lighting of its surface alone (the Surface route at one sample; multisampled, its tiny
// triangles lit at setup).
bool litFromSurface(const FrameContext& frame, const Object& object);

// What every triangle of a frame draws into.
struct DrawTarget {
  const FrameContext& frame;
  const Scene& scene;
  Framebuffer& fb;
  PixelProbe* probe;  // null unless a pixel is watched
  std::vector<AttributeLayout> layouts;  // per object: what its records carry
  std::vector<Route> route;  // per object
  // Per object, for the Surface route: its lighting and whether it has vertex colours.
  std::vector<ShadeSetup> setups;
  std::vector<std::uint8_t> colored;
  // Per object: the object whose setup and colouring light it alike (itself or an earlier one),
  // the owner its pixels name in the visible surface, so that a vector of pixels of several such
  // objects is lit in one pass (shadeOwnedPoints lights lanes of one owner at a time).
  std::vector<std::uint32_t> shadeOwner;
  // Per object: its tiny triangles worked out at setup, without records (tile_raster.h): coloured
  // (Colored, at every sample when multisampled), or as visible surface (Surface, without vertex
  // colours), or multisampled Phong's lit at every sample (litFromSurface, without vertex colours).
  std::vector<std::uint8_t> tiny;
  // Per object, of those: lit at setup (multisampled Phong, litFromSurface), with its `setups`.
  std::vector<std::uint8_t> tinyLit;

  DrawTarget(const FrameContext& frame, const Scene& scene, Framebuffer& fb, PixelProbe* probe);
  const AttributeLayout& layout(const DrawRecord& r) const { return layouts[r.object]; }
  bool blends(const DrawRecord& r) const { return route[r.object] == Route::Blended; }
};

// Draws the record's pixels inside `rect`; adds the fragments that passed the depth test. With
// `sample` (multisampling in one pass), only that sample's coverage and depth, into that sample of
// the framebuffer's (the pixels still shaded at their centres).
void drawRecord(const DrawTarget& target, const DrawRecord& record, const PixelRect& rect, std::size_t& fragments,
                int sample = -1);

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
