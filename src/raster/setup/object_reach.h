// How far an object's triangles can reach on the screen, known before any of them is set up: the
// window rectangle of its mesh's bounding box, projected. A tile beyond the reach of every object
// still to be drawn is finished, and can be resolved and given its memory back before the frame
// ends (pipeline.cpp).
#pragma once

#include "raster/coverage/rasterize.h"
#include "raster/frame_context.h"
#include "raster/tile/framebuffer.h"

#include <illum/scene.h>

#include <cstdint>
#include <span>
#include <vector>

namespace illum {

// Pixels every triangle of `object` that covers a sample lies in: its box's eight corners in
// clip space (where w is positive throughout the box, perspective projection maps the box into
// the hull of their images, and clipping keeps what it keeps of a triangle inside that), widened
// by a margin far beyond the vertex stage's rounding; the whole frame when a corner is behind the
// eye or not finite, or the mesh has no positions. Clamped to the frame; minX >
// maxX when the box lies outside it.
PixelRect objectReach(const FrameContext& frame, const Object& object);

// Per 64×64 tile of a frame (numbered row by row from the bottom), the last object of a drawing
// order that can reach it.
class TileReach {
 public:
  // Works it out for the objects of `order` that have triangles, when there are two or more of
  // them (with one, every tile is finished when the frame is); false when it was not.
  bool find(const FrameContext& frame, std::span<const Object* const> order);
  // Whether nothing after the first `objects` of the order (those set up in full) reaches `tile`.
  bool reachedOnlyBefore(int tile, std::uint32_t objects) const { return last_[std::size_t(tile)] <= objects; }

 private:
  std::vector<std::uint32_t> last_;  // 1 + the order's position of the last object reaching it; 0: none
};

}  // namespace illum
